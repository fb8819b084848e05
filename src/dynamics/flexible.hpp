#pragma once
/// Reduced-order flexible body (docs/methods.md s.10; Acikgoz & DeJong 2012, Earthquake Engng
/// Struct. Dyn. 41; Vassiliou, Mackie & Stojadinovic 2014): the planar block of simulate.hpp
/// split into a rigid base and one elastic mode, a modal mass m_s at height h_s above the base
/// that moves relative to the base along the body's own horizontal axis (modal coordinate q)
/// with the fixed-base frequency f and modal damping zeta. The base rests, slides, rocks about
/// either edge, slide-rocks or flies, with the contact, friction, restitution and mode
/// transitions of the rigid model (s.2, s.3).
///
/// The split keeps the whole body's mass M, CG height h and inertia I_c: the rigid remainder
/// has mass M - m_s, first moment M h - m_s h_s and second moment about the base point below
/// the CG I_c + M h^2 - m_s h_s^2. With q held at 0 the body is the rigid block, so an
/// infinitely stiff mode gives the rigid model; with the base held, q is the linear oscillator
/// q'' + 2 zeta omega q' + omega^2 q = -xg''.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "dynamics/simulate.hpp"

namespace freestand::dynamics {

/// Uniform cantilever, first mode (e.g. Chopra, Dynamics of Structures, distributed-mass
/// systems: effective modal mass 0.613 M at 0.726 of the height): the defaults when a case
/// gives no modal mass or height.
inline constexpr double cantilever_modal_mass_fraction = 0.613;
inline constexpr double cantilever_modal_height_ratio = 0.726;
/// Modal damping when none is given (steel equipment, ASCE 4 / RG 1.61 welded steel: 2%).
inline constexpr double default_modal_damping = 0.02;
/// Duration of an impact's contact pulse, s: about 0.1 ms for a steel or concrete contact (the
/// impact time Options::flat_landing_window_s also assumes). A mode much slower than it keeps
/// its momentum through an impact, one much faster follows the base (docs/methods.md s.10).
inline constexpr double default_impact_duration_s = 1e-4;

/// The elastic mode. Unset mass and height take the cantilever defaults above, the body's
/// height being the rigid model's top_height_m (2 h, a uniform body, unless given).
struct FlexibleMode {
    double frequency_hz = 0.0;                ///< fixed-base frequency f, Hz (> 0)
    double damping = default_modal_damping;   ///< modal damping ratio zeta, [0, 1)
    std::optional<double> mass_fraction;      ///< m_s / M, (0, 1)
    std::optional<double> height_m;           ///< h_s above the base, m (> 0)
};

/// A validated flexible body: the rigid model it is split from and the mode, defaults resolved.
struct FlexibleModel {
    BlockModel rigid;
    double frequency_hz = 0.0;
    double damping = 0.0;
    double mass_fraction = 0.0;
    double height_m = 0.0;
    bool mass_fraction_default = false;  ///< mass_fraction came from the cantilever default
    bool height_default = false;         ///< height_m came from the cantilever default
    /// Duration of an impact's contact pulse (a half-sine), s: the mode keeps the share of its
    /// momentum an oscillator keeps through such a pulse (1 for a mode much slower than it, 0
    /// for one much faster: the rigid block's impact).
    double impact_duration_s = default_impact_duration_s;
};

/// Validates the mode against the block. Throws InputError naming the field ("flexible.f",
/// "flexible.zeta", "flexible.mass", "flexible.height") when f is not finite and > 0, zeta is
/// outside [0, 1), the fraction outside (0, 1), the height not > 0, or the mass and height
/// leave the rigid remainder a negative moment of inertia about its own CG (the mode carries
/// more second moment than the whole body has).
FlexibleModel make_flexible_model(const BlockModel& rigid, const FlexibleMode& mode);

/// Peaks of the flexible run beyond the rigid Summary's.
struct FlexibleSummary {
    Summary base;                     ///< slip, uplift, overturning, modes of the rigid base
    double modal_max_m = 0.0;         ///< peak |q|, m
    double modal_drift_max = 0.0;     ///< peak |q| / h_s
    double modal_accel_max_g = 0.0;   ///< peak |absolute horizontal acceleration| of m_s, g
    bool uplifted = false;            ///< the base left flat contact (rock, slide-rock, flight)
    /// The mode is at or above rigid_limit_hz, where it moves with the base: the rigid block
    /// ran (simulate()), the modal peaks are 0.
    bool rigid_handover = false;
    std::size_t rejected_steps = 0;   ///< Dormand-Prince steps the error control rejected (event)
};

/// One output sample (at the excitation's sample times, continued through the tail).
struct FlexibleSample {
    double time_s = 0.0;
    double slide_m = 0.0;       ///< slip of the contact point (flight: of the base point)
    double rotation_rad = 0.0;  ///< s theta (> 0 rocking on the right edge)
    double modal_m = 0.0;       ///< q
    Mode mode = Mode::rest;
};

struct FlexibleResult {
    FlexibleSummary summary;
    std::vector<FlexibleSample> series;  ///< empty unless Options::record_series
    std::vector<ImpactEvent> impact_log;
};

/// Simulates the body from rest (q = q' = 0) at t = 0 until the excitation's end +
/// Options::tail_s (earlier once the base is at rest after the excitation with a mode too small
/// ever to unsettle it, or at overturning, theta = pi/2). Options::integrator event: rest is
/// stepped exactly (the linear oscillator under piecewise-linear input, Nigam & Jennings 1969),
/// the other modes by Dormand-Prince 5(4) with error control (dopri5.hpp) with steps ending at
/// every input sample and events located on its continuous extension; central_difference: the
/// planar baseline's fixed-step scheme at Options::cd_dt_s (docs/methods.md s.10). An impact
/// conserves the angular momentum about the struck edge (or multiplies theta' by a measured
/// restitution) and the mode keeps the share FlexibleModel::impact_duration_s gives of its
/// momentum (flexible_detail.hpp). Uses of Options: integrator, cd_dt_s, rel_tol, abs_tol,
/// max_contact_step_s, settle_rebound_rad, settle_interval_s, flat_landing_window_s, tail_s,
/// record_series, g_mps2 (initial_rotation_rad and initial_slide_velocity_mps must be 0).
/// A mode at or above rigid_limit_hz runs the rigid block instead (FlexibleSummary::
/// rigid_handover). Throws InputError for those, NumericalError when the step collapses, when
/// the Dormand-Prince steps exceed core::limits::max_adaptive_steps, or when central
/// difference's step (cd_dt_s, rounded down to divide the input's step) exceeds
/// cd_stable_step_s.
FlexibleResult simulate_flexible(const FlexibleModel& model, const Excitation& excitation,
                                 const Options& options = {});

/// Share of an impact's velocity change a mode may keep, and excess of its dynamic
/// amplification of the input, for the mode to count as moving with the base (1%: a response
/// within 1% of the base's, docs/methods.md s.10).
inline constexpr double rigid_mode_share = 0.01;
/// The frequency from which the mode moves with the base, Hz, so the model is the rigid block:
/// where an impact's contact pulse (FlexibleModel::impact_duration_s, T) leaves the mode at most
/// rigid_mode_share of its velocity change (the envelope of impact_modal_share,
/// 1 / ((2 f T)^2 - 1)) and the input, up to its Nyquist frequency 1 / (2 dt), is amplified by
/// at most 1 + rigid_mode_share (1 / (1 - (f_in / f)^2)): sqrt(1 + 1 / share) / (2 min(T, dt)),
/// 50 kHz at T = 0.1 ms and any coarser sampling. simulate_flexible runs the rigid block from
/// there.
double rigid_limit_hz(const FlexibleModel& model, const Excitation& excitation);

/// Longest step, s, with which central difference (Options::cd_dt_s) integrates the model's
/// elastic mode stably: 2 (sqrt(1 + 4 zeta^2) - 2 zeta) / omega, the scheme's own limit (rates
/// at half steps, x'_n extrapolated as x'_{n-1/2} + dt/2 x''_{n-1}: the root -1 of its
/// characteristic polynomial), with omega and zeta the mode's frequency and damping in the
/// contact state and pose where they are highest (read off the equations of motion: the mode
/// against the free base in flight, ~5.5 x the fixed-base frequency for a uniform block carrying
/// the cantilever's 0.613 M). The rigid block has no stiffness of its own (rigid contacts), so
/// the elastic mode is the only limit. g_mps2: the gravity the run uses.
double cd_stable_step_s(const FlexibleModel& model, double g_mps2 = units::g_mps2);

}  // namespace freestand::dynamics
