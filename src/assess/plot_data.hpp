#pragma once
/// The numbers behind the report's plots, computed here so the report only draws them.
#include <vector>

#include "assess/histories.hpp"
#include "assess/level.hpp"
#include "assess/result.hpp"

namespace freestand::assess {

/// Initiation diagrams of both directions; the spectra of the governing level (target and the
/// matched histories, 5%); the ground motion, slip and rotation of the governing simulated
/// history (re-simulated once with its series). History plots stay empty when no level was
/// simulated.
PlotData plot_data(const AssessmentResult& r, const std::vector<LevelDemand>& demands,
                   HistoryBank& bank);

/// Keeps at most max_points of a series, as the min and max of equal buckets, so peaks survive.
Series decimate(const Series& s, std::size_t max_points);

}  // namespace freestand::assess
