#pragma once
/// Markdown and HTML reports rendered with mstch from templates/report.{md,html}.mustache
/// (compiled in), plus result.json and the figures. Reports only read the result.
#include <filesystem>
#include <string>
#include <vector>

#include "assess/result.hpp"
#include "core/publish.hpp"
#include "fragility/fragility.hpp"
#include "goal/goal.hpp"
#include "report/escape.hpp"
#include "report/json.hpp"
#include "report/plots.hpp"

namespace freestand::report {

/// Every output file's contents.
struct Rendered {
    std::string markdown;
    std::string html;             ///< self-contained: inline CSS and SVG, no external resources
    std::string json;             ///< result.json, 2-space indented, trailing newline
    std::vector<Figure> figures;  ///< also written as SVG files for the Markdown report
    /// Files beside the figures that the HTML report inlines elsewhere (the fragility curves).
    std::vector<core::OutputFile> extra_files;
};

/// Renders all outputs. Case text is escaped: HTML-escaped in the HTML report; in Markdown,
/// '<' and '&' as entities (no raw HTML can start) and Markdown punctuation backslash-escaped,
/// newlines folded to spaces. With a fragility result ([options] fragility = true) the reports
/// gain its section before the assumptions, result.json its "fragility" object and the folder
/// its figure. With a performance goal ([site] dbe_pga_g) the reports gain its section after
/// the verdict and result.json its "performance_goal" object.
Rendered render(const assess::AssessmentResult& r, const Stamp& stamp,
                const fragility::Result* fragility = nullptr,
                const goal::PerformanceGoal* goal = nullptr);

/// The files of a report folder: the figures, the extra files, report.md, report.html,
/// result.json (what write_report publishes).
std::vector<core::OutputFile> report_files(const Rendered& rendered);

/// Publishes report.md, report.html, result.json and the figures as the whole content of dir
/// (core::publish_folder: all old or all new for any reader; only a folder freestand owns is
/// replaced). Throws IoError naming the path, before anything is written where it can.
void write_report(const std::filesystem::path& dir, const Rendered& rendered);

/// The headline's governing level, "PGA 0.400 g, direction x", with " with <material>" when it
/// is a level of the recommended material's trial (AssessmentResult::overall_from_trial).
std::string headline_level(const assess::AssessmentResult& r);

}  // namespace freestand::report
