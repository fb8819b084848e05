#pragma once
/// Displacement-aware baseline correction of a generated or matched history
/// (docs/methods.md s.8 "Realism"). A history must end at rest (final velocity and displacement
/// zero, SRP 3.7.1); how it is brought to rest decides its displacement. Two velocity-step
/// pulses alone (the classic correction) add a displacement bump of (velocity offset) x (time
/// between them), which on matched 20 s records was the largest part of PGD (D/A 1-4 m/g). Here
/// the correction is chosen among smooth long-period shapes to make the peak displacement as
/// small as possible while the end conditions hold exactly.
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "motion/criteria.hpp"
#include "motion/wavelet.hpp"

namespace freestand::motion {

class BaselineCorrector {
  public:
    /// For records of `samples` samples at dt_s (>= 3 samples).
    BaselineCorrector(std::size_t samples, double dt_s);

    /// The same, built once and shared while in use (it is immutable): generation builds one
    /// for every synthesis and every match, all of one length. The last few lengths are kept.
    static std::shared_ptr<const BaselineCorrector> shared(std::size_t samples, double dt_s);

    /// Adds sum c_k s_k(t) to accel_mps2, s_k the correction shapes (two Gaussian acceleration
    /// pulses at T/3 and 2T/3 and the displacement shapes sin^2(pi t/T) sin(k pi t/T),
    /// k = 1..3, which carry no motion below ~(k + 2) / (2T) Hz into the record's ends), with c
    /// minimising the peak displacement (iteratively reweighted least squares on the
    /// displacement, reweighted toward its peak, an approximation of the minimax) subject to
    /// zero final velocity and displacement (exact, by Lagrange multipliers).
    void minimise_displacement(std::vector<double>& accel_mps2) const;

    /// Full correction: minimise_displacement, then the displacement is tapered to rest over
    /// the first and last taper_s (d <- w d with w the quintic smoothstep, so the record starts
    /// and ends at rest with zero acceleration, velocity and displacement), then the tiny
    /// remainder of the final velocity and displacement (integration error of the taper,
    /// ~1e-5 m) is removed exactly by the two pulses.
    void correct(std::vector<double>& accel_mps2) const;

    /// Length of the end tapers, s.
    static constexpr double taper_s = 1.0;

    /// The two Gaussian acceleration pulses (smooth velocity steps) at T/3 and 2T/3 of a record
    /// lasting duration_s, gamma = min(T / 12, 2 s): the matcher's baseline columns too.
    static std::array<Wavelet, 2> pulses(double duration_s);

  private:
    std::size_t samples_;
    double dt_s_;
    std::size_t stride_;                        // displacement fitted every stride samples
    EndWeights ends_;                           // final velocity / displacement functionals
    std::vector<std::vector<double>> shape_a_;  // correction shapes, acceleration
    std::vector<std::vector<double>> shape_d_;  // their displacement on the fit grid
    std::vector<double> shape_end_v_, shape_end_d_;

    /// Correction shapes: the two pulses and the three displacement shapes.
    static constexpr std::size_t kShapes = 5;
    /// The weighted least-squares sums of minimise_displacement: H_ij (j >= i, row by row) and
    /// g_i, for the fit-grid weights and displacement d.
    struct WeightedSums {
        std::array<double, kShapes*(kShapes + 1) / 2> h{};
        std::array<double, kShapes> g{};
    };
    WeightedSums weighted_sums(const std::vector<double>& weight,
                               const std::vector<double>& d) const;
    /// The displacement of core::displacement_m at every stride-th sample.
    std::vector<double> displacement_on_grid(const std::vector<double>& accel_mps2) const;
    void taper_ends(std::vector<double>& accel_mps2) const;
    void zero_ends_exactly(std::vector<double>& accel_mps2) const;
};

}  // namespace freestand::motion
