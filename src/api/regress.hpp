#pragma once
/// regress: every case of a folder re-assessed, and the validation against the thesis re-run,
/// each compared with its golden result.json (STYLE.md: goldens compared numerically with an
/// epsilon, refreshed by one command).
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "api/json.hpp"
#include "assess/run_settings.hpp"
#include "report/render.hpp"
#include "report/validation.hpp"

namespace freestand::api {

/// One difference: JSON path ("/levels/3/slide_asce_m"), golden and fresh values as JSON text.
struct Difference {
    std::string path;
    std::string golden;
    std::string fresh;
};

/// Compares two result documents, ignoring the top-level "stamp". Numbers match when
/// |a - b| <= rtol max(|a|, |b|) (so 0 matches only 0); strings, booleans and nulls exactly;
/// objects by key set and arrays by length, then element-wise. rtol >= 0.
std::vector<Difference> compare_results(const json& golden, const json& fresh, double rtol);

/// One golden folder checked or refreshed: reports/<case stem>/ or reports/validation/.
struct RegressEntry {
    enum class Status {
        ok,       ///< the fresh result.json matches the golden
        changed,  ///< it differs (differences)
        missing,  ///< there is no golden result.json
        updated,  ///< refreshed: report or validation holds the documents to publish into dir
        skipped,  ///< the validation, when the cases folder lacks the shipped glove-box cases
    };
    Status status = Status::ok;
    std::string name;           ///< the golden folder's name
    std::filesystem::path dir;  ///< reports_dir / name
    /// The headline's JSON pointer: "/verdict" of a case, "/summary/text" of the validation.
    std::string headline;
    std::string fresh_headline;   ///< the fresh document's headline (a case's verdict line when updated)
    std::string golden_headline;  ///< the golden's, when changed
    std::vector<Difference> differences;  ///< when changed
    std::optional<report::Rendered> report;              ///< a case's, when updated
    std::optional<report::ValidationReport> validation;  ///< the validation's, when updated
};

struct RegressRequest {
    std::filesystem::path reports_dir{"reports"};  ///< the golden report folders
    std::filesystem::path cases_dir{"cases"};      ///< every *.toml in it, sorted by name
    bool update = false;  ///< refresh the goldens instead of comparing with them
    double rtol = 1e-6;   ///< relative tolerance for numbers, >= 0
    std::string commit;   ///< the build's commit, for the stamps
    assess::RunSettings run;
    /// Called with each entry as it is done (a run takes minutes): cases in name order, then
    /// the validation.
    std::function<void(const RegressEntry&)> on_entry;
};

struct RegressResult {
    std::vector<RegressEntry> entries;  ///< as passed to on_entry
    /// True unless an entry is changed or missing.
    bool all_ok() const;
};

/// Runs the request: InputError with field `rtol` for a negative or not finite tolerance,
/// IoError when cases_dir is no folder, InputError naming a golden that is not valid JSON;
/// the assessments' errors propagate.
RegressResult regress(const RegressRequest& request);

}  // namespace freestand::api
