#include "report/case_assessment.hpp"

#include <nlohmann/json.hpp>

#include "assess/overrides.hpp"
#include "assess/pipeline.hpp"
#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "report/fragility_json.hpp"
#include "report/goal_json.hpp"

namespace freestand::report {

CaseAssessment assess_case(const assess::Case& c, const std::string& case_bytes,
                           const std::filesystem::path& case_file, const std::string& commit,
                           const assess::RunSettings& settings) {
    CaseAssessment run;
    if (!c.units.empty() && c.options.fragility.enabled)
        throw InputError(SourceLocation{case_file.string(), 0, "options.fragility"},
                         "not available for two [[unit]] tables (the fragility analysis takes "
                         "one component)");
    run.result = assess::assess(c, settings);
    if (c.options.fragility.enabled) {
        fragility::Config config;
        config.pga_g = c.options.fragility.pga_g;
        config.samples = c.options.fragility.samples;
        config.seed = c.options.seed;
        run.fragility = fragility::run_all(c, config, settings);
    }
    if (c.site.dbe_pga_g) {
        run.goal = goal::evaluate_headline_goal(run.result, settings);
        goal::apply_goal(run.result, *run.goal);
    }
    run.stamp = make_stamp(case_bytes, case_file.string(), c.options.seed, commit);
    run.stamp.inputs = stamped_inputs(c);
    return run;
}

CaseAssessment assess_case_file(const std::filesystem::path& case_file,
                                const std::optional<std::vector<double>>& pga_g,
                                const std::string& commit, const assess::RunSettings& run) {
    const std::string bytes = core::read_input_file(case_file);
    assess::Case c = assess::parse_case(bytes, case_file.string());
    if (pga_g) c = assess::with_pga_levels(std::move(c), *pga_g);
    return assess_case(c, bytes, case_file, commit, run);
}

std::string result_json_text(const assess::AssessmentResult& r, const Stamp& stamp,
                             const fragility::Result* fragility,
                             const goal::PerformanceGoal* goal) {
    nlohmann::ordered_json json = to_json(r, stamp);
    if (fragility) json["fragility"] = fragility_body_json(*fragility);
    if (goal) json["performance_goal"] = goal_json(*goal);
    return json.dump(2) + "\n";
}

}  // namespace freestand::report
