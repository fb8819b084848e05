#include "report/run.hpp"

#include <fmt/format.h>

#include "assess/overrides.hpp"
#include "assess/pipeline.hpp"
#include "assess/verdict.hpp"
#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/printable.hpp"
#include "report/case_assessment.hpp"
#include "report/joined.hpp"

namespace freestand::report {

namespace {

CaseRun render_case(CaseAssessment a) {
    CaseRun run;
    run.rendered = render(a.result, a.stamp, a.fragility ? &*a.fragility : nullptr,
                          a.goal ? &*a.goal : nullptr);
    run.result = std::move(a.result);
    run.fragility = std::move(a.fragility);
    run.goal = std::move(a.goal);
    return run;
}

}  // namespace

CaseRun run_case(const std::filesystem::path& case_file,
                 const std::optional<std::vector<double>>& pga_g, const std::string& commit,
                 const assess::RunSettings& run) {
    return render_case(assess_case_file(case_file, pga_g, commit, run));
}

CaseRun run_case(const std::string& case_bytes, const std::filesystem::path& case_file,
                 const assess::CaseOverrides& overrides, const std::string& commit,
                 const assess::RunSettings& run) {
    const assess::Case c = assess::parse_case(case_bytes, case_file.string(), overrides);
    if (!c.units.empty())
        throw InputError(SourceLocation{case_file.string(), 0, "unit"},
                         "a batch runs one-component cases; assess two [[unit]] tables with "
                         "`freestand assess`");
    return render_case(assess_case(c, case_bytes, case_file, commit, run));
}

std::string verdict_line(const assess::AssessmentResult& r) {
    // One line on a terminal: a name's line breaks and bidirectional overrides are shown, not
    // obeyed (a CR would let the name overwrite the verdict).
    if (r.joined) return core::printable_name(joined_verdict_line(r));
    const assess::Verdict& v = r.overall.verdict;
    std::string out =
        fmt::format("{}: {} (governing {}, margin {}, decided by {})", r.input.component.name,
                    assess::verdict_text(v), headline_level(r), assess::margin_text(v),
                    assess::to_string(v.decided_by));
    for (const std::string& c : v.conditions) out += "; open condition: " + c;
    return core::printable_name(out);
}

}  // namespace freestand::report
