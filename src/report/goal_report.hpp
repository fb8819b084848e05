#pragma once
/// The performance goal's section of an assessment report (docs/methods.md s.6 step 5).
#include <mstch/mstch.hpp>

#include "goal/goal.hpp"

namespace freestand::report {

/// The section's template values (goal_*), merged into an assessment report's context.
mstch::map goal_section_context(const goal::PerformanceGoal& g);

}  // namespace freestand::report
