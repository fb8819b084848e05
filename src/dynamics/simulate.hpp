#pragma once
/// Time-history simulation of a planar rigid block on a moving base (docs/methods.md s.1, s.2, s.3):
/// rest, slide, rock about either edge, slide-rock and free flight, with impacts and overturning.
/// Two integrators: event-driven with exact event location (the reference) and the classic
/// fixed-step central-difference scheme (the baseline).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "block/block.hpp"
#include "block/mode.hpp"
#include "core/record.hpp"
#include "core/steps.hpp"
#include "core/units.hpp"

namespace freestand::dynamics {

/// Contact state of the block. Rock and slide-rock carry an active edge (Sample::edge).
using Mode = block::Mode;
using block::mode_count;
/// "rest", "slide", "rock", "slide-rock", "flight".
using block::to_string;

/// The block and its contact with the base.
struct BlockModel {
    block::Block block;
    double mu_s = 0.0;  ///< static friction coefficient (>= 0)
    double mu_k = 0.0;  ///< kinetic friction coefficient (0 <= mu_k <= mu_s)
    /// Coefficient of restitution on angular velocity at an impact. nullopt: conservation of
    /// angular momentum about the striking edge (Housner 1963), which for a symmetric block is
    /// block::Block::housner_restitution.
    std::optional<double> restitution;
    double top_height_m = 0.0;  ///< height of the top corners above the base (for top_accel)
};

/// Validated model. mu_k defaults to mu_s, top height to 2 h (a uniform block). Throws
/// InputError naming the parameter (mu_s, mu_k, restitution, top_height_m) when
/// mu_s is outside core::limits::friction ([0, 2], as a case), mu_k outside [0, mu_s], r
/// outside core::limits::restitution ([0, 1]) or the top below the CG.
BlockModel make_block_model(const block::Block& block, double mu_s,
                            std::optional<double> mu_k = std::nullopt,
                            std::optional<double> restitution = std::nullopt,
                            std::optional<double> top_height_m = std::nullopt);

/// Base acceleration as piecewise-linear samples at a uniform step (sample i at i dt_s);
/// after the last sample the base is at rest. The integrators evaluate it between samples by
/// linear interpolation and stop every step at sample times (the input has kinks there).
struct Excitation {
    std::string label;                   ///< record name or "sine A g, f Hz, T s"
    double dt_s = 0.0;                   ///< sample step, s
    std::vector<double> horizontal_mps2; ///< xg'', positive to the right
    std::vector<double> vertical_mps2;   ///< yg'', positive up; empty = no vertical motion

    double duration_s() const;  ///< time of the last sample, s
    double pga_mps2() const;    ///< peak |xg''|, m/s^2
};

/// Excitation from a record, its accelerations multiplied by scale. A vertical record with a
/// different step is interpolated linearly onto the horizontal samples (zero beyond its end).
/// Throws InputError if a record is invalid.
Excitation excitation_from_record(const core::Record& horizontal, double scale = 1.0,
                                  const core::Record* vertical = nullptr,
                                  double vertical_scale = 1.0);

/// Harmonic input of docs/methods.md s.3: xg'' = A g sin(2 pi f t) on 0 <= t <= T, zero after,
/// optionally tapered by (1 - cos(pi t / t_ramp)) / 2 for t < t_ramp.
struct SineSpec {
    double amplitude_g = 0.0;
    double frequency_hz = 0.0;
    double duration_s = 0.0;
    double ramp_s = 0.0;  ///< 0: no ramp
    double dt_s = 0.0;    ///< sampling; 0: min(0.005 s, 1 / (400 f)), adjusted so T / dt is whole
    /// Phase, degrees: A g sin(2 pi f t + phase). The second horizontal component of a biaxial
    /// sine (docs/methods.md s.10); 0 for the planar convention.
    double phase_deg = 0.0;
};
/// Samples the sine (piecewise-linear between samples; max relative error (pi/N)^2/2 with N
/// samples per cycle, 3e-5 at the default N >= 400). Throws InputError on a non-positive
/// frequency or duration, a negative amplitude or ramp, a non-finite phase.
Excitation sine_excitation(const SineSpec& spec);

enum class Integrator { event, central_difference };
/// "event" or "cd".
const char* integrator_name(Integrator integrator);

/// Integration settings. Tolerances are those of the event-driven integrator unless stated.
struct Options {
    Integrator integrator = Integrator::event;
    double cd_dt_s = 1e-4;       ///< central-difference step (rounded down to divide dt_s)
    /// Relative tolerance per step of the Taylor polynomials of rock and slide-rock (taylor.hpp):
    /// their last two terms over a step, for theta, u and their rates. Steps end at every input
    /// sample (the input's slope jumps there); the degree adapts (typically 6-8 at 1e-9 on 5 ms
    /// samples) and a step is shortened only where the highest degree does not suffice. The
    /// default puts peaks within ~1e-11 relative of rel_tol 1e-13 on the benchmark records,
    /// far below central difference at 1e-4 s (1e-3).
    double rel_tol = 1e-9;
    double abs_tol = 1e-11;      ///< absolute tolerance (rad, m, rad/s, m/s)
    /// Longest rock / slide-rock step, s. Steps also end at every input sample, so this binds
    /// only on records sampled coarser and after the excitation. Impacts and slip stops are
    /// searched inside a step, the force events (friction exceeded, lift-off) by their sign at
    /// its ends: a step must not span two crossings of one (a rocking half-cycle of the
    /// smallest blocks is ~0.1 s). At most 1 s.
    double max_contact_step_s = 0.02;
    /// Settling (Zeno) rule: after an impact whose rebound would lift the block by less than
    /// this angle (free-rocking energy estimate), the block is set flat with theta = theta' = 0.
    double settle_rebound_rad = 1e-7;
    /// Settling rule for chatter: 64 consecutive events each within this time of the previous
    /// one set the block at rest and hold it there for 1 us (a loop at one instant, such as a
    /// rock onset that only grazes g tan(alpha), then moves on); 100000 throw NumericalError.
    double settle_interval_s = 1e-9;
    /// A landing from flight is flat (both edges at once, Coulomb impact) when the far edge's
    /// gap would close at the landing's vertical speed within this time. A rigid-body model
    /// otherwise resolves a landing tilted by 1e-5 rad as two corner impacts microseconds apart,
    /// whose angular-momentum transfer spins the block up (4.8 rad/s from 17 m/s) and throws it
    /// back into the air; real contacts act together over an impact time of about 0.1 ms.
    double flat_landing_window_s = 1e-4;
    double tail_s = 10.0;        ///< simulated time after the excitation ends (stops at rest)
    bool record_series = true;   ///< fill SimulationResult::series
    /// Initial condition (the base is at rest at t = 0): rotation s theta0 (> 0 on the right
    /// edge) released with theta' = 0, and slip velocity u'(0).
    double initial_rotation_rad = 0.0;
    double initial_slide_velocity_mps = 0.0;
    double g_mps2 = units::g_mps2;  ///< gravity (docs/methods.md, Conventions)
};

/// Central difference's step on an input sampled at sample_dt_s: cd_dt_s rounded down to
/// divide it (steps end at every sample), s.
inline double central_difference_step_s(double sample_dt_s, double cd_dt_s) {
    const double n_sub = std::max(1.0, core::steps_covering(sample_dt_s / cd_dt_s));
    return sample_dt_s / n_sub;
}

/// How overturning was decided.
enum class OverturnCriterion {
    none,
    /// theta reached pi/2.
    angle_half_pi,
    /// The excitation had ended while the block rocked (no slip) with theta > alpha and
    /// theta' > 0: with the base at rest gravity's moment about the pivot points outward for
    /// alpha < theta < pi/2 and friction does no work, so theta' stays positive and the block
    /// falls. The time reported is when the criterion first held.
    past_alpha_after_excitation,
};
/// "none", "angle_half_pi", "past_alpha_after_excitation".
const char* overturn_criterion_name(OverturnCriterion criterion);

/// One output sample (at the excitation's sample times, continued through the tail).
struct Sample {
    double time_s = 0.0;
    /// Slip u of the contact point relative to the base (the block's slip when flat); in flight
    /// the CG's horizontal displacement relative to the base.
    double slide_m = 0.0;
    double slide_velocity_mps = 0.0; ///< u'
    double rotation_rad = 0.0;       ///< s theta: > 0 rocking on the right edge
    double angular_velocity_radps = 0.0;  ///< s theta'
    Mode mode = Mode::rest;
    double normal_force_N = 0.0;     ///< base reaction, vertical
    double friction_force_N = 0.0;   ///< base reaction, horizontal (on the block)
    double top_accel_mps2 = 0.0;     ///< absolute horizontal acceleration, larger top corner
};

struct Summary {
    std::string integrator;          ///< "event" or "cd"
    double slide_max_m = 0.0;        ///< max |u|
    double slide_residual_m = 0.0;   ///< |u| at the end
    double rock_max_rad = 0.0;       ///< max theta
    double rock_max_over_alpha = 0.0;///< max theta / alpha of the active edge
    bool overturned = false;
    std::optional<double> overturn_time_s;
    std::optional<int> overturn_mode;  ///< 1: after >= 1 impact, 2: without impact
    OverturnCriterion overturn_criterion = OverturnCriterion::none;
    std::size_t impacts = 0;         ///< edge-to-edge impacts and landings from flight
    std::size_t mode_changes = 0;
    std::array<double, mode_count> time_in_mode_s{};  ///< indexed by Mode
    double top_accel_max_g = 0.0;    ///< peak |absolute top acceleration| over the samples, g
    double pga_g = 0.0;
    double amplification = 0.0;      ///< top_accel_max_g / pga_g (0 if pga is 0)
    std::size_t settlements = 0;     ///< Zeno / chatter settlements
    std::size_t steps = 0;           ///< integrator steps taken
    double end_time_s = 0.0;         ///< time the simulation stopped
    double wall_s = 0.0;             ///< wall-clock time of the integration
};

/// One impact: theta returned to 0 and rotation passed to the other edge (or a landing).
struct ImpactEvent {
    double time_s = 0.0;
    double omega_before_radps = 0.0;  ///< |theta'| just before
    double omega_after_radps = 0.0;   ///< theta' about the new edge just after (0 if settled)
    bool settled = false;             ///< the rebound was below the settling angle
};

struct SimulationResult {
    Summary summary;
    std::vector<Sample> series;
    std::vector<ImpactEvent> impact_log;
};

/// Simulates the block from rest at t = 0 under the excitation, until excitation end + tail
/// (earlier once at rest after the excitation, or at overturning). Throws NumericalError if
/// the event-driven integrator's step falls below 1e-14 s without settling.
SimulationResult simulate(const BlockModel& model, const Excitation& excitation,
                          const Options& options = {});

}  // namespace freestand::dynamics
