#pragma once
/// Pieces of a fragility sample the runner shares with no one (not installed).
#include <optional>

#include "assess/case.hpp"
#include "assess/histories.hpp"

namespace freestand::fragility {

/// The peak |u| of the rigid block sliding under both horizontal components of the set at once
/// (and its vertical), scaled to pga_g, with isotropic friction mu_s, mu_k (docs/methods.md
/// s.10); nullopt when the block of direction x or y would rock under it
/// (dynamics::biaxial_rocking_reason), which the biaxial model cannot show. The rule and the
/// scaling are those of a simulated level (assess/biaxial_level.hpp).
std::optional<double> biaxial_slide_m(const assess::Case& c, const assess::HistorySet& set,
                                      double pga_g, double mu_s, double mu_k);

}  // namespace freestand::fragility
