// simulate_flexible (flexible.hpp): checks the options, hands a mode that moves with the base
// over to the rigid block, and runs the chosen integrator.
#include <chrono>
#include <fmt/format.h>

#include "core/errors.hpp"
#include "dynamics/flexible_detail.hpp"

namespace freestand::dynamics {

namespace {

// The rigid block's run as the flexible body's: the mode moves with the base (q = 0).
FlexibleResult rigid_run(const FlexibleModel& model, const Excitation& excitation,
                         const Options& options) {
    SimulationResult rigid = simulate(model.rigid, excitation, options);
    FlexibleResult out;
    out.summary.base = rigid.summary;
    out.summary.rigid_handover = true;
    const auto& t = rigid.summary.time_in_mode_s;
    out.summary.uplifted = t[static_cast<std::size_t>(Mode::rock)] > 0.0 ||
                           t[static_cast<std::size_t>(Mode::slide_rock)] > 0.0 ||
                           t[static_cast<std::size_t>(Mode::flight)] > 0.0;
    out.series.reserve(rigid.series.size());
    for (const Sample& s : rigid.series)
        out.series.push_back({s.time_s, s.slide_m, s.rotation_rad, 0.0, s.mode});
    out.impact_log = std::move(rigid.impact_log);
    return out;
}

// Central difference diverges once its step exceeds the elastic mode's stability limit: a
// 500 Hz mode at 1e-4 s "overturned" at 0.43 s where the body rocks to 0.49 alpha.
void require_stable_cd(const FlexibleModel& model, const Excitation& excitation,
                       const Options& options) {
    const double h_s = central_difference_step_s(excitation.dt_s, options.cd_dt_s);
    const double limit_s = cd_stable_step_s(model, options.g_mps2);
    if (h_s <= limit_s) return;
    throw NumericalError(fmt::format(
        "central difference: step {:.3g} s exceeds the stability limit {:.3g} s of the elastic "
        "mode at f = {} Hz (2 (sqrt(1 + 4 zeta^2) - 2 zeta) / omega, omega and zeta of the mode "
        "against the base, highest with the base free); use the event integrator or a step "
        "<= {:.3g} s",
        h_s, limit_s, model.frequency_hz, limit_s));
}

}  // namespace

FlexibleResult simulate_flexible(const FlexibleModel& model, const Excitation& excitation,
                                 const Options& options) {
    if (options.initial_rotation_rad != 0.0 || options.initial_slide_velocity_mps != 0.0)
        throw InputError({"", 0, "initial condition"},
                         "the flexible-body model starts at rest (no initial rotation or slip)");
    if (excitation.horizontal_mps2.size() < 2 || !(excitation.dt_s > 0.0))
        throw InputError({"", 0, "excitation"}, "needs at least two samples and a step > 0 s");
    const double rigid_hz = rigid_limit_hz(model, excitation);
    if (model.frequency_hz >= rigid_hz) return rigid_run(model, excitation, options);
    if (options.integrator == Integrator::central_difference)
        require_stable_cd(model, excitation, options);
    const auto wall0 = std::chrono::steady_clock::now();
    const detail::FlexGeometry g = detail::make_flex_geometry(model);
    const detail::BaseMotion bm(excitation, options.g_mps2);
    FlexibleResult out = options.integrator == Integrator::central_difference
                             ? detail::run_flexible_cd(g, bm, options)
                             : detail::run_flexible_event(g, bm, options, rigid_hz);
    out.summary.base.wall_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    return out;
}

}  // namespace freestand::dynamics
