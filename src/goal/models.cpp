#include "goal/models_detail.hpp"

namespace freestand::goal::detail {

GoalModels goal_models(const assess::Case& c, const std::vector<double>& pga_g) {
    fragility::CaseModels m = fragility::case_models(c, pga_g);
    GoalModels out{std::move(m.models), std::move(m.text), std::move(m.notes)};
    out.notes.push_back(
        "Every sample is simulated, with friction and restitution drawn between their bounds: "
        "the screen that passes a level of the assessment on closed forms (docs/methods.md s.6 "
        "step 4) and the bounding properties of its simulations play no part.");
    if (c.options.simulate == assess::SimulatePolicy::never)
        out.notes.push_back(
            "options.simulate = \"never\" does not apply to the goal: the "
            "fragility engine simulates every sample.");
    return out;
}

}  // namespace freestand::goal::detail
