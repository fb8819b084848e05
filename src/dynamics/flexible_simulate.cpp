// simulate_flexible (flexible.hpp): checks the options and runs the chosen integrator.
#include <chrono>

#include "core/errors.hpp"
#include "dynamics/flexible_detail.hpp"

namespace freestand::dynamics {

FlexibleResult simulate_flexible(const FlexibleModel& model, const Excitation& excitation,
                                 const Options& options) {
    if (options.initial_rotation_rad != 0.0 || options.initial_slide_velocity_mps != 0.0)
        throw InputError({"", 0, "initial condition"},
                         "the flexible-body model starts at rest (no initial rotation or slip)");
    if (excitation.horizontal_mps2.size() < 2 || !(excitation.dt_s > 0.0))
        throw InputError({"", 0, "excitation"}, "needs at least two samples and a step > 0 s");
    const auto wall0 = std::chrono::steady_clock::now();
    const detail::FlexGeometry g = detail::make_flex_geometry(model);
    const detail::BaseMotion bm(excitation, options.g_mps2);
    FlexibleResult out = options.integrator == Integrator::central_difference
                             ? detail::run_flexible_cd(g, bm, options)
                             : detail::run_flexible_event(g, bm, options);
    out.summary.base.wall_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    return out;
}

}  // namespace freestand::dynamics
