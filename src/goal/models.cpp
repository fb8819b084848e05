#include <fmt/format.h>
#include <fmt/ranges.h>

#include "assess/flexible_level.hpp"
#include "assess/level.hpp"
#include "goal/models_detail.hpp"

namespace freestand::goal::detail {
namespace {

// "x at 0.1, 0.15 g; y at 0.1 g" for the (level, direction) pairs marked.
std::string where(const std::vector<double>& pga_g, const std::vector<std::array<bool, 2>>& on) {
    std::vector<std::string> parts;
    for (const assess::Direction d : {assess::Direction::x, assess::Direction::y}) {
        std::vector<std::string> levels;
        for (std::size_t j = 0; j < on.size(); ++j)
            if (on[j][d == assess::Direction::x ? 0 : 1])
                levels.push_back(fmt::format("{:.4g}", pga_g[j]));
        if (!levels.empty())
            parts.push_back(
                fmt::format("{} at {} g", assess::to_string(d), fmt::join(levels, ", ")));
    }
    return fmt::format("{}", fmt::join(parts, "; "));
}

}  // namespace

GoalModels goal_models(const assess::Case& c, const std::vector<double>& pga_g) {
    GoalModels out;
    std::vector<std::array<bool, 2>> raised(pga_g.size()), runs(pga_g.size());
    bool any_raised = false, any_runs = false;
    for (std::size_t j = 0; j < pga_g.size(); ++j) {
        // A vertical PGA of 1 g or more lifts the block off at rest: the static threshold is
        // gone, so the flag, which marks uplift below it, cannot be raised (rocking/flexible.hpp).
        if (assess::weightless_level({pga_g[j]}, c.site.vertical_ratio)) continue;
        const assess::LevelDemand demand = assess::level_demand(c.site, pga_g[j]);
        for (const assess::Direction d : {assess::Direction::x, assess::Direction::y}) {
            const std::size_t i = d == assess::Direction::x ? 0 : 1;
            const assess::FlexibleFlag flag =
                assess::screen_flexible(c.component, c.component.block(d), d, demand);
            raised[j][i] = flag.raised;
            runs[j][i] = assess::flexible_model_decides(c, flag);
            any_raised = any_raised || flag.raised;
            any_runs = any_runs || runs[j][i];
        }
    }
    out.text = "the rigid planar block in x and in y (docs/methods.md s.3)";
    if (any_runs) {
        out.models.flexible = runs;
        out.text += fmt::format(
            ", the flexible body instead (rigid base carrying one elastic mode, s.10) where its "
            "flag is raised, as at the case's levels: {}",
            where(pga_g, runs));
    } else if (any_raised) {
        out.notes.push_back(fmt::format(
            "The flexible-body flag is raised ({}) but {}: the samples run the rigid block "
            "there, as the case's levels do.",
            where(pga_g, raised), *assess::flexible_model_blocker(c)));
    }
    out.models.biaxial_slide = true;
    out.text +=
        "; the slide of a sample whose block rocks in neither direction comes from "
        "biaxial sliding (both horizontal components at once, s.10), as at a simulated "
        "level";
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
