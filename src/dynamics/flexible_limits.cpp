// Where the flexible body's model holds and what it costs (flexible.hpp): the frequency from
// which its mode moves with the base (the rigid block runs), the step budget of the
// Dormand-Prince integrator, central difference's stability limit.
#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "core/errors.hpp"
#include "core/limits.hpp"
#include "dynamics/flexible_detail.hpp"

namespace freestand::dynamics {

double rigid_limit_hz(const FlexibleModel& model, const Excitation& excitation) {
    // impact_modal_share(x) has the envelope 1 / ((x / pi)^2 - 1), x / pi = 2 f T; the input's
    // amplification 1 / (1 - (f_in / f)^2) with f_in = 1 / (2 dt). Both are 1 + share or less
    // from f = sqrt(1 + 1 / share) / (2 tau), tau the shorter of T and dt.
    const double tau_s = std::min(model.impact_duration_s, excitation.dt_s);
    return std::sqrt(1.0 + 1.0 / rigid_mode_share) / (2.0 * tau_s);
}

double cd_stable_step_s(const FlexibleModel& model, double g_mps2) {
    return detail::cd_stable_step_s(detail::make_flex_geometry(model), g_mps2);
}

namespace detail {

void require_step_budget(std::size_t steps, double t_s, double f_hz, double rigid_limit_hz) {
    if (static_cast<double>(steps) <= core::limits::max_adaptive_steps) return;
    throw NumericalError(fmt::format(
        "flexible-body integrator: {} Dormand-Prince steps by t = {} s, above the limit {:.0f} "
        "(README, Limits): the mode at {} Hz is too stiff for the record (the rigid block runs "
        "from {:.0f} Hz)",
        steps, t_s, core::limits::max_adaptive_steps, f_hz, rigid_limit_hz));
}

namespace {

// The mode's frequency and damping in mode m at state x: q'' = -omega^2 q - 2 zeta omega q' +
// ..., read off the equations of motion by central differences in q and q' (the spring and the
// damper are linear, the rest of q'' varies slowly with them).
struct ModalRate {
    double omega = 0.0, zeta = 0.0;
};
ModalRate modal_rate(const FlexGeometry& g, const FlexMode& m, FlexState x, Base base) {
    const std::size_t iq = is_flight(m.mode) ? 6 : 4;
    auto qdd = [&](std::size_t i, double d) {
        FlexState y = x;
        y[i] += d;
        FlexState dx;
        FlexAccel a;
        flex_rhs(g, m, y, base, dx, a);
        return a.qdd;
    };
    constexpr double dq_m = 1e-7, dqd_mps = 1e-7;
    const double k = -(qdd(iq, dq_m) - qdd(iq, -dq_m)) / (2.0 * dq_m);
    const double c = -(qdd(iq + 1, dqd_mps) - qdd(iq + 1, -dqd_mps)) / (2.0 * dqd_mps);
    if (!(k > 0.0)) return {};
    const double omega = std::sqrt(k);
    return {omega, std::max(0.0, c / (2.0 * omega))};
}

}  // namespace

double cd_stable_step_s(const FlexGeometry& g, double g_mps2) {
    const Base base{0.0, g_mps2};
    double limit_s = 2.0 / g.omega * (std::sqrt(1.0 + 4.0 * g.zeta * g.zeta) - 2.0 * g.zeta);
    auto bound = [&](const FlexMode& m, const FlexState& x) {
        ModalRate r;
        try {
            r = modal_rate(g, m, x, base);
        } catch (const NumericalError&) {
            return;  // no slide-rock solution at this pose (Painleve): never integrated there
        }
        if (r.omega <= 0.0) return;
        const double z = r.zeta;
        limit_s = std::min(limit_s, 2.0 / r.omega * (std::sqrt(1.0 + 4.0 * z * z) - 2.0 * z));
    };
    // Every contact state the integrator steps, over the standing range of uplift (the mode's
    // coupling to the base changes with the pose: slide-rock's friction raises it by a few
    // percent at large uplift) and flight.
    constexpr int poses = 32;
    for (int j = 0; j <= poses; ++j) {
        const double th = std::numbers::pi / 2.0 * j / poses;
        for (int s : {-1, 1}) {
            bound({Mode::rock, s, 1}, {0, 0, th, 0, 0, 0, 0, 0});
            for (int sigma : {-1, 1}) bound({Mode::slide_rock, s, sigma}, {0, 0, th, 0, 0, 0, 0, 0});
        }
        bound({Mode::flight, 1, 1}, {0, 0, g.hs, 0, th, 0, 0, 0});
    }
    for (int sigma : {-1, 1}) bound({Mode::slide, 1, sigma}, {});
    return limit_s;
}

}  // namespace detail
}  // namespace freestand::dynamics
