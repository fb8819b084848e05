#pragma once
/// result.json of one assessed case: what `assess` writes into its report folder and what the
/// Python module returns.
#include <nlohmann/json.hpp>
#include <string>

#include "assess/result.hpp"
#include "fragility/fragility.hpp"
#include "goal/goal.hpp"
#include "report/json.hpp"

namespace freestand::report {

/// The assessment with its stamp and, with a fragility result, its "fragility" object, with a
/// goal its "performance_goal" object.
nlohmann::ordered_json result_json(const assess::AssessmentResult& r, const Stamp& stamp,
                                   const fragility::Result* fragility,
                                   const goal::PerformanceGoal* goal = nullptr);

/// result_json 2-space indented with a trailing newline.
std::string result_json_text(const assess::AssessmentResult& r, const Stamp& stamp,
                             const fragility::Result* fragility,
                             const goal::PerformanceGoal* goal = nullptr);

}  // namespace freestand::report
