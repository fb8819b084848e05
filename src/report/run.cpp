#include "report/run.hpp"

#include <fmt/format.h>

#include "assess/overrides.hpp"
#include "assess/pipeline.hpp"
#include "assess/verdict.hpp"
#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "report/joined.hpp"

namespace freestand::report {

namespace {

// fragility_threads: 0 for every core; the fragility result does not depend on it.
CaseRun assess_and_render(const assess::Case& c, const std::string& case_bytes,
                          const std::filesystem::path& case_file, const std::string& commit,
                          int fragility_threads) {
    CaseRun run;
    if (!c.units.empty() && c.options.fragility.enabled)
        throw InputError(SourceLocation{case_file.string(), 0, "options.fragility"},
                         "not available for two [[unit]] tables (the fragility analysis takes "
                         "one component)");
    run.result = assess::assess(c);
    if (c.options.fragility.enabled) {
        fragility::Config config;
        config.pga_g = c.options.fragility.pga_g;
        config.samples = c.options.fragility.samples;
        config.seed = c.options.seed;
        run.fragility = fragility::run_all(c, config, fragility_threads);
    }
    Stamp stamp = make_stamp(case_bytes, case_file.string(), c.options.seed, commit);
    stamp.inputs = stamped_inputs(c);
    run.rendered = render(run.result, stamp, run.fragility ? &*run.fragility : nullptr);
    return run;
}

}  // namespace

CaseRun run_case(const std::filesystem::path& case_file,
                 const std::optional<std::vector<double>>& pga_g, const std::string& commit) {
    const std::string bytes = core::read_input_file(case_file);
    assess::Case c = assess::parse_case(bytes, case_file.string());
    if (pga_g) c = assess::with_pga_levels(std::move(c), *pga_g);
    return assess_and_render(c, bytes, case_file, commit, 0);
}

CaseRun run_case(const std::string& case_bytes, const std::filesystem::path& case_file,
                 const assess::CaseOverrides& overrides, const std::string& commit,
                 int fragility_threads) {
    const assess::Case c = assess::parse_case(case_bytes, case_file.string(), overrides);
    if (!c.units.empty())
        throw InputError(SourceLocation{case_file.string(), 0, "unit"},
                         "a batch runs one-component cases; assess two [[unit]] tables with "
                         "`freestand assess`");
    return assess_and_render(c, case_bytes, case_file, commit, fragility_threads);
}

std::string verdict_line(const assess::AssessmentResult& r) {
    if (r.joined) return joined_verdict_line(r);
    const assess::Verdict& v = r.overall.verdict;
    std::string out =
        fmt::format("{}: {} (governing {}, margin {}, decided by {})", r.input.component.name,
                    assess::verdict_text(v), headline_level(r), assess::margin_text(v),
                    assess::to_string(v.decided_by));
    for (const std::string& c : v.conditions) out += "; open condition: " + c;
    return out;
}

}  // namespace freestand::report
