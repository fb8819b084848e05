#pragma once
/// Biaxial sliding of the simulated levels of one PGA (docs/methods.md s.10): the histories'
/// two horizontal components at once where the block slides without rocking.
#include <vector>

#include "assess/case.hpp"
#include "assess/histories.hpp"
#include "assess/level.hpp"
#include "assess/result.hpp"

namespace freestand::assess {

/// The model name LevelResult::model carries for a level whose sliding demand is biaxial.
inline constexpr const char* biaxial_model_name =
    "biaxial sliding, both horizontal components at once with isotropic Coulomb friction "
    "(docs/methods.md s.10), beside the rigid planar block for rocking and overturning "
    "(docs/methods.md s.3)";

/// For the levels of one PGA (directions x and y, as evaluate_level made them): every simulated
/// level gets LevelResult::biaxial. Where the block slides at the sliding bound (mode slide)
/// and rocks under no history (dynamics::biaxial_rocking_reason, with each direction's block),
/// every history runs biaxially once (h1 along x, h2 along y, the vertical; scaled to the PGA
/// as excitation() scales them) and shared by the levels it applies to; their model, verdict
/// and trail are then remade with the biaxial peak |u| as the sliding demand. Elsewhere the
/// planar model stays and model_reason says why the biaxial one does not apply.
void apply_biaxial(const Case& c, const LevelDemand& demand, std::vector<LevelResult*> levels,
                   HistoryBank& bank);

}  // namespace freestand::assess
