#pragma once
/// Reports of a two-unit case (assess/joined.hpp): the pair's verdict and tunnel check, then
/// each unit's own report; result.json with "pair" and "units".
#include "assess/result.hpp"
#include "report/render.hpp"

namespace freestand::report {

/// Renders a result whose joined part is set (r.joined): report.md (the pair's section, then
/// each unit's report), a self-contained report.html, result.json and the units' figures, named
/// unit1-*.svg and unit2-*.svg.
Rendered render_joined(const assess::AssessmentResult& r, const Stamp& stamp);

/// The pair's one-line verdict: "<unit 1> + <unit 2>: <verdict>".
std::string joined_verdict_line(const assess::AssessmentResult& r);

}  // namespace freestand::report
