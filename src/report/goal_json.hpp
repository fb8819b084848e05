#pragma once
/// The "performance_goal" object of result.json (docs/methods.md s.6 step 5).
#include <nlohmann/json_fwd.hpp>

#include "goal/goal.hpp"

namespace freestand::report {

/// {"dbe_pga_g", "configuration", "limit_state", "p_dbe", "p_dbe_ci95", "p_150", "p_150_ci95",
/// "passes", "margin", "margin_basis", "theta_m_g", "beta", "targets", "levels_g",
/// "samples_per_level", "pool", "seed", "models", "motions", "mu_s", "restitution",
/// "limit_states": {"overturn": {...}, "slide", "rock", "any"}, "levels", "notes", "method"}:
/// the top-level p's, margin and fit are the governing limit state's; numbers to 10
/// significant digits.
nlohmann::ordered_json goal_json(const goal::PerformanceGoal& g);

}  // namespace freestand::report
