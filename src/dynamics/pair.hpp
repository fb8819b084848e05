#pragma once
/// Two free-standing units side by side under one base motion, joined by a transfer tunnel
/// (docs/methods.md s.10): each unit is its own planar rigid block, simulated by simulate();
/// the demand is their relative displacement at the tunnel's height.
#include <array>
#include <cstddef>

#include "dynamics/simulate.hpp"

namespace freestand::dynamics {

struct PairOptions {
    double tunnel_height_m = 0.0;  ///< height of the tunnel above the base, m (>= 0)
    /// Series samples per input step (>= 1). The excitation is resampled at dt_s / refine by
    /// linear interpolation: the same piecewise-linear base motion the simulator integrates, so
    /// the runs are unchanged and only observed more densely. The peak of the relative
    /// displacement is taken over the samples; 1 samples at the input steps.
    std::size_t refine = 1;
};

struct PairResult {
    /// Peak |r| over the samples, r = d_1 - d_2 and d a unit's displacement relative to the base
    /// at tunnel height (displacement_at_height_m), m.
    double relative_max_m = 0.0;
    double relative_max_time_s = 0.0;  ///< time of that peak, s
    double relative_residual_m = 0.0;  ///< |r| when both units have stopped, m
    /// A unit overturned: the relative displacement is then unbounded (the peak above is only
    /// up to the overturn).
    bool overturned = false;
    std::array<Summary, 2> units;  ///< each unit's own run
    std::size_t samples = 0;       ///< samples the peak was taken over
};

/// Horizontal displacement relative to the base of a unit's point at height_m, small-angle
/// sense (docs/methods.md s.10): u + height_m theta in contact (u the slip, theta > 0 on the
/// right edge, so the top moves right); in flight, where Sample::slide_m is the CG's
/// displacement, X + (height_m - cg_height_m) theta.
double displacement_at_height_m(const Sample& s, double cg_height_m, double height_m);

/// The excitation sampled refine times more densely by linear interpolation (the same base
/// motion). Throws InputError for refine 0.
Excitation refined(const Excitation& excitation, std::size_t refine);

/// Simulates both units from rest under the same excitation and returns the peak relative
/// displacement at the tunnel's height. A unit that stops first holds its last state (at rest
/// after the excitation). Throws InputError naming tunnel_height_m or refine when out of range,
/// and what simulate() throws.
PairResult simulate_pair(const std::array<BlockModel, 2>& units, const Excitation& excitation,
                         const PairOptions& pair, const Options& options = {});

}  // namespace freestand::dynamics
