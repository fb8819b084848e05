#pragma once
/// A level whose flexible-body flag is raised: the reduced-order flexible model (docs/methods.md
/// s.10, dynamics/flexible.hpp) runs over the level's histories at the planar simulation's
/// bounds and decides the level; the rigid planar simulation is reported beside it.
#include <optional>
#include <string>

#include "assess/histories.hpp"
#include "assess/result.hpp"
#include "dynamics/flexible.hpp"

namespace freestand::assess {

/// The model name LevelResult::model carries for the flexible-body simulation.
inline constexpr const char* flexible_model_name =
    "flexible body: rigid base (resting, sliding, rocking or slide-rocking) carrying one elastic "
    "mode (docs/methods.md s.10)";

/// Why the flexible model cannot run at a level with a raised flag (no fixed-base frequency,
/// or options.simulate = "never"), or nullopt when it runs. Not called for a lowered flag.
std::optional<std::string> flexible_model_blocker(const Case& c);

/// Whether the flexible model decides a level with this flag: raised, and nothing blocks it.
bool flexible_model_decides(const Case& c, const FlexibleFlag& flag);

/// The flexible model of the component in direction d with one bound's contact: the case's
/// fixed-base frequency and modal keys, the cantilever defaults for those absent.
dynamics::FlexibleModel flexible_model(const Component& comp, const ContactBound& contact,
                                       Direction d);

/// Runs the flexible model over the level's histories (generating them if needed) and fills
/// level.flexible_simulation, level.model and level.model_reason; the planar simulation must
/// already be in level.simulation.
void simulate_flexible_level(const Case& c, LevelResult& level, double pga_g, HistoryBank& bank,
                             bool rocking_mode);

}  // namespace freestand::assess
