#include "report/run.hpp"

#include <fmt/format.h>

#include "assess/pipeline.hpp"
#include "assess/verdict.hpp"
#include "core/file_io.hpp"

namespace freestand::report {

CaseRun run_case(const std::filesystem::path& case_file,
                 const std::optional<std::vector<double>>& pga_g, const std::string& commit) {
    const std::string bytes = core::read_input_file(case_file);
    assess::Case c = assess::parse_case(bytes, case_file.string());
    if (pga_g) c = assess::with_pga_levels(std::move(c), *pga_g);
    CaseRun run;
    run.result = assess::assess(c);
    run.rendered =
        render(run.result, make_stamp(bytes, case_file.string(), c.options.seed, commit));
    return run;
}

std::string verdict_line(const assess::AssessmentResult& r) {
    std::string where;
    if (!r.levels.empty()) {
        const auto& g = r.levels[r.governing_level];
        where = fmt::format("governing PGA {:.3f} g, direction {}, ", g.pga_g,
                            assess::to_string(g.direction));
    }
    const std::string with = r.overall.material.empty() ? "" : " with " + r.overall.material;
    return fmt::format("{}: {} ({}margin{} {}, decided by {})", r.input.component.name,
                       assess::verdict_text(r.overall), where, with,
                       r.overall.margin ? fmt::format("{:.2f}", *r.overall.margin) : "unbounded",
                       assess::to_string(r.overall.decided_by));
}

}  // namespace freestand::report
