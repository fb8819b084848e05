#include "report/result_document.hpp"

#include "report/fragility_json.hpp"
#include "report/goal_json.hpp"

namespace freestand::report {

nlohmann::ordered_json result_json(const assess::AssessmentResult& r, const Stamp& stamp,
                                   const fragility::Result* fragility,
                                   const goal::PerformanceGoal* goal) {
    nlohmann::ordered_json json = to_json(r, stamp);
    if (fragility) json["fragility"] = fragility_body_json(*fragility);
    if (goal) json["performance_goal"] = goal_json(*goal);
    return json;
}

std::string result_json_text(const assess::AssessmentResult& r, const Stamp& stamp,
                             const fragility::Result* fragility,
                             const goal::PerformanceGoal* goal) {
    return result_json(r, stamp, fragility, goal).dump(2) + "\n";
}

}  // namespace freestand::report
