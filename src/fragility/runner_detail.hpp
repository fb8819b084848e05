#pragma once
/// Pieces of a fragility sample the runner shares with no one (not installed).
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "assess/case.hpp"
#include "assess/histories.hpp"
#include "fragility/fragility.hpp"

namespace freestand::fragility {

/// The draws of one sample from its own stream: they depend on (seed, level, sample) alone
/// (docs/methods.md s.9), so a merge can redraw them to check a shard's.
struct Draw {
    std::size_t pick = 0;  ///< index into the pool (the sets, or the records of the suite)
    double mu_s = 0.0;
    std::array<double, 2> restitution{};  ///< x, y
};

/// The draws of sample `sample` of level `level` from laws, picking among pool motions.
Draw draw(const Laws& laws, std::uint64_t seed, int level, int sample, std::size_t pool);

/// The peak |u| of the rigid block sliding under both horizontal components of the set at once
/// (and its vertical), scaled to pga_g, with isotropic friction mu_s, mu_k (docs/methods.md
/// s.10); nullopt when the block of direction x or y would rock under it
/// (dynamics::biaxial_rocking_reason), which the biaxial model cannot show. The rule and the
/// scaling are those of a simulated level (assess/biaxial_level.hpp).
std::optional<double> biaxial_slide_m(const assess::Case& c, const assess::HistorySet& set,
                                      double pga_g, double mu_s, double mu_k);

}  // namespace freestand::fragility
