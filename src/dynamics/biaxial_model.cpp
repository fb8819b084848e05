// Biaxial sliding: the model, its excitations, the rocking screen and the entry point
// (docs/methods.md s.10).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/steps.hpp"
#include "core/limits.hpp"
#include "dynamics/biaxial_detail.hpp"
#include "dynamics/resample.hpp"

namespace freestand::dynamics {

BiaxialModel make_biaxial_model(double mu_s, std::optional<double> mu_k) {
    // The case's range (core::limits::friction), whichever entry point built the model.
    core::limits::require_in(mu_s, core::limits::friction, {"", 0, "mu_s"});
    BiaxialModel m{mu_s, mu_k.value_or(mu_s)};
    if (!std::isfinite(m.mu_k) || m.mu_k < 0.0 || m.mu_k > mu_s)
        throw InputError({"", 0, "mu_k"},
                         fmt::format("kinetic friction must be in [0, mu_s = {}]; got {}", mu_s,
                                     m.mu_k));
    return m;
}

double BiaxialExcitation::duration_s() const {
    return x_mps2.empty() ? 0.0 : dt_s * static_cast<double>(x_mps2.size() - 1);
}

double BiaxialExcitation::pga_mps2() const {
    double peak = 0.0;
    for (std::size_t i = 0; i < x_mps2.size(); ++i)
        peak = std::max(peak, std::hypot(x_mps2[i], i < y_mps2.size() ? y_mps2[i] : 0.0));
    return peak;
}

BiaxialExcitation biaxial_excitation(const Excitation& planar, std::vector<double> y_mps2) {
    if (y_mps2.size() > planar.horizontal_mps2.size())
        throw InputError({"", 0, "y_mps2"},
                         fmt::format("{} samples; expected at most the {} of the x component",
                                     y_mps2.size(), planar.horizontal_mps2.size()));
    BiaxialExcitation e;
    e.label = planar.label;
    e.dt_s = planar.dt_s;
    e.x_mps2 = planar.horizontal_mps2;
    e.vertical_mps2 = planar.vertical_mps2;
    e.y_mps2 = std::move(y_mps2);
    e.y_mps2.resize(e.x_mps2.size(), 0.0);
    return e;
}

BiaxialExcitation biaxial_excitation_from_records(const core::Record& x, const core::Record& y,
                                                  double scale, const core::Record* vertical) {
    core::validate(y);
    Excitation planar = excitation_from_record(x, scale, vertical, scale);
    // Extend x with zeros (and the vertical with its record) to cover a longer y.
    const auto n_y = static_cast<std::size_t>(core::steps_covering(y.duration_s() / x.dt_s)) + 1;
    if (n_y > planar.horizontal_mps2.size()) {
        const std::size_t n_x = planar.horizontal_mps2.size();
        planar.horizontal_mps2.resize(n_y, 0.0);
        if (vertical) {
            planar.vertical_mps2.resize(n_y);
            for (std::size_t i = n_x; i < n_y; ++i)
                planar.vertical_mps2[i] = scale * detail::sample_at(*vertical, x.time_s(i));
        }
    }
    std::vector<double> ys(planar.horizontal_mps2.size());
    for (std::size_t i = 0; i < ys.size(); ++i) ys[i] = scale * detail::sample_at(y, x.time_s(i));
    BiaxialExcitation e = biaxial_excitation(planar, std::move(ys));
    e.label = fmt::format("{} (x) + {} (y)", planar.label, y.name);
    return e;
}

BiaxialExcitation biaxial_sine_excitation(const SineSpec& spec, double phase_deg) {
    SineSpec sx = spec, sy = spec;
    sx.phase_deg = 0.0;
    sy.phase_deg = phase_deg;
    if (!std::isfinite(phase_deg))
        throw InputError({"", 0, "phase_deg"}, fmt::format("must be finite; got {}", phase_deg));
    BiaxialExcitation e = biaxial_excitation(sine_excitation(sx), sine_excitation(sy).horizontal_mps2);
    e.label = fmt::format("{} (x), phase {} deg (y)", e.label, phase_deg);
    return e;
}

std::optional<std::string> biaxial_rocking_reason(const block::Block& block,
                                                  const BiaxialModel& model,
                                                  const BiaxialExcitation& e, double g_mps2) {
    // The edge tipped over first (the smaller b): the square plan puts it in both directions.
    const double tan_alpha = block.tan_alpha(block.critical_edge());
    if (model.mu_k > tan_alpha)
        return fmt::format("mu_k = {} > tan(alpha) = {:.4g}: a sliding block lifts its leading "
                           "edge (docs/methods.md s.3)", model.mu_k, tan_alpha);
    if (model.mu_s <= tan_alpha) return std::nullopt;  // it slides before it can tip (s.2)
    for (std::size_t i = 0; i < e.x_mps2.size(); ++i) {
        const double G = g_mps2 + (i < e.vertical_mps2.size() ? e.vertical_mps2[i] : 0.0);
        for (int c = 0; c < 2; ++c) {
            const double a = c == 0 ? e.x_mps2[i] : e.y_mps2[i];
            if (std::abs(a) > tan_alpha * G)
                return fmt::format("the {} component reaches {:.4g} g at t = {:.4g} s, above "
                                   "g tan(alpha) = {:.4g} g with mu_s = {} > tan(alpha) "
                                   "(docs/methods.md s.2)",
                                   c == 0 ? "x" : "y", std::abs(a) / g_mps2, e.dt_s * double(i),
                                   tan_alpha * G / g_mps2, model.mu_s);
        }
    }
    return std::nullopt;
}

void detail::require_biaxial_excitation(const BiaxialExcitation& e) {
    require_positive(e.dt_s, {"", 0, "excitation dt_s"});
    if (e.x_mps2.empty())
        throw InputError({"", 0, "excitation x_mps2"}, "expected at least one sample");
    if (e.y_mps2.size() != e.x_mps2.size())
        throw InputError({"", 0, "excitation y_mps2"},
                         fmt::format("{} samples; expected as many as x_mps2 ({})",
                                     e.y_mps2.size(), e.x_mps2.size()));
    if (!e.vertical_mps2.empty() && e.vertical_mps2.size() != e.x_mps2.size())
        throw InputError({"", 0, "excitation vertical_mps2"},
                         "must be empty or as long as the horizontal samples");
    for (const auto* series : {&e.x_mps2, &e.y_mps2, &e.vertical_mps2})
        core::limits::require_accelerations(*series, {"", 0, "excitation"});
    core::limits::require_within(static_cast<double>(e.x_mps2.size()), core::limits::max_samples,
                                 {"", 0, "excitation"}, "the excitation's samples");
}

namespace {

void require_options(const BiaxialExcitation& e, const Options& o) {
    require_positive(o.rel_tol, {"", 0, "rel_tol"});
    require_positive(o.abs_tol, {"", 0, "abs_tol"});
    require_positive(o.cd_dt_s, {"", 0, "cd_dt_s"});
    require_in_range(o.max_contact_step_s, 0.0, 1.0, {"", 0, "max_contact_step_s (s)"}, false, true);
    if (!std::isfinite(o.tail_s) || o.tail_s < 0.0)
        throw InputError({"", 0, "tail_s"}, fmt::format("must be >= 0 s; got {}", o.tail_s));
    if (o.initial_rotation_rad != 0.0)
        throw InputError({"", 0, "initial_rotation_rad"},
                         "must be 0: the biaxial model has no rocking");
    if (o.initial_slide_velocity_mps != 0.0)
        throw InputError({"", 0, "initial_slide_velocity_mps"},
                         "must be 0: the biaxial model starts at rest");
    if (o.integrator == Integrator::central_difference) {
        const double duration_s = e.dt_s * static_cast<double>(e.x_mps2.size()) + o.tail_s;
        core::limits::require_within(duration_s / o.cd_dt_s, core::limits::max_fixed_steps,
                                     {"", 0, "cd_dt_s"}, "central difference (duration / dt)");
    }
}

}  // namespace

Options biaxial_options() {
    Options o;
    o.rel_tol = 1e-6;
    o.abs_tol = 1e-8;
    return o;
}

BiaxialResult simulate_biaxial(const BiaxialModel& model, const BiaxialExcitation& excitation,
                               const Options& options) {
    detail::require_biaxial_excitation(excitation);
    require_options(excitation, options);
    const auto start = std::chrono::steady_clock::now();
    const detail::BiaxialBase base(excitation, options.g_mps2);
    BiaxialResult r = options.integrator == Integrator::event
                          ? detail::run_biaxial_event(model, base, options)
                          : detail::run_biaxial_cd(model, base, options);
    r.summary.pga_g = excitation.pga_mps2() / options.g_mps2;
    r.summary.wall_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

}  // namespace freestand::dynamics
