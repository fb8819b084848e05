#pragma once
/// The report's figures, drawn from AssessmentResult::plots (no physics here).
#include <string>
#include <vector>

#include "assess/result.hpp"

namespace freestand::report {

/// A figure: file name (for Markdown, written next to report.md), caption and SVG text.
struct Figure {
    std::string file;
    std::string caption;
    std::string svg;
};

/// Every figure the result has data for, in report order: initiation diagrams (x, y); per
/// direction the sliding demand (demand-slide-<d>.svg) and rocking demand (demand-rock-<d>.svg)
/// against PGA, drawn from the levels, each omitted when no level of the direction has data for
/// it; spectra; and, when a level was simulated, ground motion, slip and rotation of the
/// governing history.
std::vector<Figure> figures(const assess::AssessmentResult& r);

}  // namespace freestand::report
