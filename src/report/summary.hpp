#pragma once
/// A batch's summary (README "Batch"): one row per component in list order, rendered as
/// summary.md, self-contained summary.html (templates/summary.{md,html}.mustache, compiled in),
/// summary.csv (RFC 4180) and summary.json. The summary only reads what each row carries.
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "assess/result.hpp"

namespace freestand::report {

/// What an assessed component's headline says (the same one level as its report's headline).
struct SummaryOutcome {
    std::string component;     ///< [component] name
    std::string verdict_kind;  ///< acceptable, acceptable_with_clearance, change_material, anchor
    std::string verdict;       ///< the verdict line's text, e.g. "acceptable with clearance >= 47 mm"
    std::string governing_level;  ///< "PGA 0.400 g, direction x[ with <material>]"
    double governing_pga_g = 0.0;
    std::string governing_direction;  ///< "x" or "y"
    std::string governing_material;   ///< the recommended material's trial, "" for the own base
    std::optional<double> margin;     ///< capacity / demand; absent for "no motion"
    std::string margin_text;          ///< "1.15" or "no motion"
    std::string decided_by;           ///< the deciding model
    std::string recommended_material;  ///< "" when none is recommended
    std::vector<std::string> open_conditions;
};

/// The headline of an assessment as a summary row shows it.
SummaryOutcome summary_outcome(const assess::AssessmentResult& r);

/// One row: a component of the list, assessed (outcome) or failed (error, exit_code).
struct SummaryRow {
    std::string name;         ///< the list's name for it: its report folder
    std::string case_file;    ///< path as the batch read it
    std::string case_sha256;  ///< of the case file's bytes; "" when it could not be read
    std::string overrides;    ///< the list's values replacing the case file's (assess::describe)
    std::optional<SummaryOutcome> outcome;  ///< present when the component was assessed
    std::string error;  ///< why it could not be assessed (the error message); "" when assessed
    int exit_code = 0;  ///< 0 assessed; else the failure's class (3 input, 4 numerical, 5 I/O, 70)
};

/// The stamp of a batch: the tool, the build, the list (the cases are hashed per row).
struct SummaryStamp {
    std::string tool_version;  ///< core::version()
    std::string commit;        ///< the build's commit, as the reports' stamp
    std::string list;          ///< the list file or folder, as given
    std::string list_sha256;   ///< of the list file's bytes; "" for a folder
};

struct Summary {
    std::vector<SummaryRow> rows;
    SummaryStamp stamp;
};

struct RenderedSummary {
    std::string markdown;
    std::string html;  ///< self-contained: inline CSS, no external resources
    std::string csv;   ///< RFC 4180: header row, CRLF line ends, quoted where needed
    std::string json;  ///< 2-space indented, trailing newline
};

/// File names of the summary in a batch's output folder.
inline const std::vector<std::string>& summary_file_names() {
    static const std::vector<std::string> names{"summary.md", "summary.html", "summary.csv",
                                                "summary.json"};
    return names;
}

/// Rows (numbers rounded to 10 significant digits, absent values null), counts and the stamp.
nlohmann::ordered_json summary_json(const Summary& s);

/// Renders the four documents; case text is escaped as in the reports (render.hpp).
RenderedSummary render_summary(const Summary& s);

}  // namespace freestand::report
