// The models a fragility sample runs to be decided as the case's levels are (docs/methods.md
// s.9, s.10, s.11).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "assess/flexible_level.hpp"
#include "assess/level.hpp"
#include "fragility/fragility.hpp"

namespace freestand::fragility {
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

CaseModels case_models(const assess::Case& c, const std::vector<double>& pga_g) {
    CaseModels out;
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
    if (any_runs) {
        out.models.flexible = runs;
    } else if (any_raised) {
        out.notes.push_back(fmt::format(
            "The flexible-body flag is raised ({}) but {}: the samples run the rigid block "
            "there, as the case's levels do.",
            where(pga_g, raised), *assess::flexible_model_blocker(c)));
    }
    out.models.biaxial_slide = true;
    out.models.body3d = true;
    out.text = describe_models(out.models, pga_g);
    return out;
}

std::string describe_models(const Models& m, const std::vector<double>& pga_g) {
    std::string text = planar_models_text;
    if (!m.flexible.empty())
        text += fmt::format(
            ", the flexible body instead (rigid base carrying one elastic mode, s.10) where its "
            "flag is raised, as at the case's levels: {}",
            where(pga_g, m.flexible));
    if (m.body3d)
        text += std::string("; a sample whose block rocks in x or y under its motion runs the "
                            "3D rigid body instead of the rigid planar blocks (every component "
                            "at once, s.11)") +
                (m.flexible.empty() ? ""
                                    : ", carrying the flexible body's mode along x and y where "
                                      "the flag is raised, in place of the planar flexible runs "
                                      "(a sample whose rigid block rocks in neither direction "
                                      "keeps them)");
    if (m.biaxial_slide)
        text += std::string(m.body3d ? ", and" : ";") +
                " the slide of a sample whose block rocks in neither direction comes from "
                "biaxial sliding (both horizontal components at once, s.10)";
    if (m.body3d || m.biaxial_slide) text += ", as at a simulated level";
    return text;
}

}  // namespace freestand::fragility
