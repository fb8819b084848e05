#pragma once
/// assess: one case file to its verdict (docs/methods.md s.9), the fragility analysis and the
/// performance goal it asks for, and its report folder's documents.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "api/json.hpp"
#include "assess/overrides.hpp"
#include "assess/result.hpp"
#include "assess/run_settings.hpp"
#include "core/publish.hpp"
#include "fragility/fragility.hpp"
#include "goal/goal.hpp"
#include "report/json.hpp"
#include "report/render.hpp"

namespace freestand::api {

struct AssessRequest {
    /// The case file: read unless case_bytes holds its text; it names the case in messages and
    /// resolves the case's relative paths.
    std::filesystem::path case_file;
    std::optional<std::string> case_bytes;    ///< the case text already read (hashed into the stamp)
    std::optional<std::vector<double>> pga_g;  ///< replaces the case's PGA levels, g
    assess::CaseOverrides overrides;  ///< values written into the case text before it is read
    /// Refuses a case of two [[unit]] tables (InputError, field `unit`): a batch's summary has
    /// one row per component.
    bool single_component = false;
    bool pdf = false;  ///< also make report.pdf from report.html
    std::string commit;               ///< the build's commit, for the stamp
    assess::RunSettings run;          ///< threads, caches, progress: no result depends on them
};

struct AssessResult {
    AssessRequest request;
    assess::AssessmentResult result;
    std::optional<fragility::Result> fragility;  ///< with [options] fragility = true
    std::optional<goal::PerformanceGoal> goal;   ///< with [site] dbe_pga_g
    report::Stamp stamp;
};

/// Reads the case (IoError), replaces its levels or values as the request says, assesses it,
/// runs the fragility analysis when the case asks for one and, when it names its DBE, the
/// performance goal of the headline's configuration, which then decides the headline with the
/// levels (goal::apply_goal). InputError names the case file and key, or the request's field
/// (`pga_g`); NumericalError propagates.
AssessResult assess(const AssessRequest& request);

/// result.json: the assessment with its stamp, "fragility" and "performance_goal" when present.
json to_json(const AssessResult& result);

/// An assessment with its report folder.
struct AssessReport {
    AssessResult assessed;
    report::Rendered rendered;
    /// report_files(rendered), with report.pdf last when the request asks for it.
    std::vector<core::OutputFile> files;
    /// Wall-clock seconds of the assessment with its rendering and of the PDF conversion: for
    /// a terminal, never for a document (outputs are byte-identical per input).
    double assess_s = 0;
    double pdf_s = 0;
    std::optional<std::filesystem::path> pdf_converter;  ///< the program that made report.pdf
};

/// assess and render; with request.pdf the converter is found first (IoError before any work
/// when there is none) and report.pdf made from report.html.
AssessReport assess_report(const AssessRequest& request);

}  // namespace freestand::api
