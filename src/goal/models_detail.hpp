#pragma once
/// Which simulation models the goal's samples run (not installed).
#include <string>
#include <vector>

#include "assess/case.hpp"
#include "fragility/fragility.hpp"

namespace freestand::goal::detail {

struct GoalModels {
    fragility::Models models;
    std::string text;                ///< the models, in words
    std::vector<std::string> notes;  ///< where the samples depart from the case's levels
};

/// The models of a simulated level of case c at each PGA: the flexible body in a direction
/// where its flag is raised and the model can run (assess::flexible_model_decides), else the
/// rigid block; biaxial sliding for a sample that rocks in neither direction.
GoalModels goal_models(const assess::Case& c, const std::vector<double>& pga_g);

}  // namespace freestand::goal::detail
