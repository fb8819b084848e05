#pragma once
/// Biaxial sliding (docs/methods.md s.10): a rigid block sliding on a plane under both
/// horizontal base components at once (and the vertical one, through N = M (g + yg'')), with
/// isotropic Coulomb friction. It has no rocking: it is the model for blocks that slide, and
/// biaxial_rocking_reason() says when a block would rock instead.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "block/block.hpp"
#include "core/record.hpp"
#include "core/units.hpp"
#include "dynamics/simulate.hpp"

namespace freestand::dynamics {

/// Friction of the sliding contact (isotropic: the same in every direction).
struct BiaxialModel {
    double mu_s = 0.0;  ///< static friction coefficient (>= 0)
    double mu_k = 0.0;  ///< kinetic friction coefficient (0 <= mu_k <= mu_s)
};
/// Validated model; mu_k defaults to mu_s. Throws InputError naming mu_s or mu_k.
BiaxialModel make_biaxial_model(double mu_s, std::optional<double> mu_k = std::nullopt);

/// Both horizontal base accelerations (and optionally the vertical one) as piecewise-linear
/// samples at one uniform step, as Excitation; the base is at rest after the last sample.
struct BiaxialExcitation {
    std::string label;
    double dt_s = 0.0;
    std::vector<double> x_mps2;         ///< xg''
    std::vector<double> y_mps2;         ///< the second horizontal component, as long as x_mps2
    std::vector<double> vertical_mps2;  ///< yg'' positive up; empty = no vertical motion

    double duration_s() const;  ///< time of the last sample, s
    double pga_mps2() const;    ///< peak |a_g| of the horizontal vector, m/s^2
};

/// x and vertical as excitation_from_record(x, scale, vertical, scale); y (times scale) is
/// interpolated onto x's samples, which are extended with zeros to cover y if it is longer.
/// Throws InputError if a record is invalid.
BiaxialExcitation biaxial_excitation_from_records(const core::Record& x, const core::Record& y,
                                                  double scale = 1.0,
                                                  const core::Record* vertical = nullptr);
/// x = A g sin(2 pi f t), y = A g sin(2 pi f t + phase) (spec's phase_deg is ignored for x),
/// both with the ramp of sine_excitation. Throws InputError as sine_excitation does.
BiaxialExcitation biaxial_sine_excitation(const SineSpec& spec, double phase_deg);
/// A planar excitation plus a second horizontal component on its samples (shorter: padded with
/// zeros). Throws InputError naming y_mps2 if it is longer than the planar samples.
BiaxialExcitation biaxial_excitation(const Excitation& planar, std::vector<double> y_mps2);

/// Why the planar block would rock under the excitation, which the biaxial model cannot
/// represent, or nullopt. Per horizontal component (the plan is taken square: the block's
/// half-widths hold in y as well), by docs/methods.md s.2: the base can tip the block only if
/// friction holds it, mu_s > tan(alpha), and the component exceeds tan(alpha) (g + yg'') at a
/// sample; and a sliding block lifts its leading edge when mu_k > tan(alpha) (s.3).
std::optional<std::string> biaxial_rocking_reason(const block::Block& block,
                                                  const BiaxialModel& model,
                                                  const BiaxialExcitation& excitation,
                                                  double g_mps2 = units::g_mps2);

/// One output sample (at the excitation's sample times, continued through the tail).
struct BiaxialSample {
    double time_s = 0.0;
    double slip_x_m = 0.0, slip_y_m = 0.0;        ///< slip u relative to the base
    double v_x_mps = 0.0, v_y_mps = 0.0;          ///< u'
    Mode mode = Mode::rest;                       ///< rest, slide or flight
    bool sliding() const { return mode == Mode::slide; }
};

struct BiaxialSummary {
    std::string integrator;          ///< "event" or "cd"
    double slide_max_m = 0.0;        ///< peak |u| (the vector)
    double slide_max_x_m = 0.0;      ///< peak |u_x|
    double slide_max_y_m = 0.0;      ///< peak |u_y|
    double slide_residual_m = 0.0;   ///< |u| at the end
    double slide_residual_x_m = 0.0; ///< u_x at the end (signed)
    double slide_residual_y_m = 0.0; ///< u_y at the end (signed)
    std::size_t mode_changes = 0;    ///< changes among rest, slide and flight
    std::array<double, mode_count> time_in_mode_s{};  ///< indexed by Mode (rest, slide, flight)
    double pga_g = 0.0;              ///< peak |a_g| of the horizontal vector, g
    std::size_t steps = 0;           ///< accepted integrator steps
    std::size_t rejected_steps = 0;  ///< steps the error control (or a turn) rejected
    double end_time_s = 0.0;
    double wall_s = 0.0;
};

struct BiaxialResult {
    BiaxialSummary summary;
    std::vector<BiaxialSample> series;  ///< empty unless Options::record_series
};

/// The biaxial slide's default options: Options{} with rel_tol 1e-6 and abs_tol 1e-8 (m, m/s).
/// Looser than the planar 1e-9: a Dormand-Prince step costs far more than a closed-form planar
/// segment, and at 1e-6 the peak |u| of bench_dynamics's biaxial El Centro case is within
/// 7e-8 relative of its converged value (rel_tol 1e-12), against 2e-3 for central difference
/// at 1e-4 s, in a quarter of the steps 1e-9 takes (docs/methods.md s.10).
Options biaxial_options();

/// Simulates the block from rest at t = 0 until the excitation's end + Options::tail_s (earlier
/// once at rest after it). Uses of Options: integrator, cd_dt_s, rel_tol, abs_tol (the
/// Dormand-Prince error control, m and m/s; rel_tol also sets the slip's relaxation time
/// below which a slow slip is taken slaved to the load, biaxial_detail.hpp), max_contact_step_s (the longest step), tail_s,
/// record_series, g_mps2. Throws InputError naming the parameter for a bad excitation or option
/// (initial_rotation_rad and initial_slide_velocity_mps must be 0: the model starts at rest).
BiaxialResult simulate_biaxial(const BiaxialModel& model, const BiaxialExcitation& excitation,
                               const Options& options = biaxial_options());

}  // namespace freestand::dynamics
