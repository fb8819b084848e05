#include <chrono>
#include <cmath>

#include "core/errors.hpp"
#include "core/limits.hpp"
#include "dynamics/integrators.hpp"

namespace freestand::dynamics {

namespace {
// Out-of-range physics is an input error (README "Limits"): an acceleration past the limit,
// e.g. from --scale 1e308, would otherwise integrate to a displacement of 8e304 m.
void require_accelerations(const Excitation& e) {
    for (const auto* series : {&e.horizontal_mps2, &e.vertical_mps2})
        core::limits::require_accelerations(*series, {"", 0, "excitation"});
}
}  // namespace

SimulationResult simulate(const BlockModel& model, const Excitation& excitation,
                          const Options& options) {
    require_positive(excitation.dt_s, {"", 0, "excitation dt_s"});
    if (!excitation.vertical_mps2.empty() &&
        excitation.vertical_mps2.size() != excitation.horizontal_mps2.size())
        throw InputError({"", 0, "excitation vertical_mps2"},
                         "must be empty or as long as the horizontal samples");
    require_positive(options.cd_dt_s, {"", 0, "cd_dt_s"});
    require_positive(options.rel_tol, {"", 0, "rel_tol"});
    require_positive(options.abs_tol, {"", 0, "abs_tol"});
    // h_cap_ in the engine never exceeds 1 s.
    require_in_range(options.max_contact_step_s, 0.0, 1.0, {"", 0, "max_contact_step_s (s)"}, false, true);
    require_accelerations(excitation);
    core::limits::require_within(static_cast<double>(excitation.horizontal_mps2.size()),
                                 core::limits::max_samples, {"", 0, "excitation"},
                                 "the excitation's samples");
    if (options.integrator == Integrator::central_difference) {
        const double duration_s =
            excitation.dt_s * static_cast<double>(excitation.horizontal_mps2.size()) +
            options.tail_s;
        core::limits::require_within(duration_s / options.cd_dt_s, core::limits::max_fixed_steps,
                                     {"", 0, "cd_dt_s"}, "central difference (duration / dt)");
    }
    const auto start = std::chrono::steady_clock::now();
    const detail::Geometry g = detail::make_geometry(model);
    const detail::BaseMotion base(excitation, options.g_mps2);
    SimulationResult r = options.integrator == Integrator::event
                             ? detail::run_event_driven(g, base, options)
                             : detail::run_central_difference(g, base, options);
    r.summary.wall_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

}  // namespace freestand::dynamics
