#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/steps.hpp"
#include "core/limits.hpp"
#include "core/tolerances.hpp"
#include "core/units.hpp"
#include "dynamics/resample.hpp"
#include "dynamics/simulate.hpp"

namespace freestand::dynamics {

const char* integrator_name(Integrator integrator) {
    return integrator == Integrator::event ? "event" : "cd";
}

const char* overturn_criterion_name(OverturnCriterion criterion) {
    switch (criterion) {
        case OverturnCriterion::none: return "none";
        case OverturnCriterion::angle_half_pi: return "angle_half_pi";
        case OverturnCriterion::past_alpha_after_excitation: return "past_alpha_after_excitation";
    }
    return "?";
}

BlockModel make_block_model(const block::Block& block, double mu_s, std::optional<double> mu_k,
                            std::optional<double> restitution, std::optional<double> top_height_m) {
    // The case's range (core::limits::friction), whichever entry point built the model.
    core::limits::require_in(mu_s, core::limits::friction, {"", 0, "mu_s"});
    BlockModel m;
    m.block = block;
    m.mu_s = mu_s;
    m.mu_k = mu_k.value_or(mu_s);
    if (!std::isfinite(m.mu_k) || m.mu_k < 0.0 || m.mu_k > mu_s)
        throw InputError({"", 0, "mu_k"},
                         fmt::format("kinetic friction must be in [0, mu_s = {}]; got {}", mu_s,
                                     m.mu_k));
    if (restitution) {
        core::limits::require_in(*restitution, core::limits::restitution, {"", 0, "restitution"});
    }
    m.restitution = restitution;
    m.top_height_m = top_height_m.value_or(2.0 * block.h_m);
    if (!std::isfinite(m.top_height_m) || m.top_height_m < block.h_m)
        throw InputError({"", 0, "top_height_m"},
                         fmt::format("top height must be >= the CG height {} m; got {}", block.h_m,
                                     m.top_height_m));
    return m;
}

double Excitation::duration_s() const {
    return horizontal_mps2.empty() ? 0.0
                                   : dt_s * static_cast<double>(horizontal_mps2.size() - 1);
}

double Excitation::pga_mps2() const {
    double peak = 0.0;
    for (double a : horizontal_mps2) peak = std::max(peak, std::abs(a));
    return peak;
}

namespace detail {

double sample_at(const core::Record& rec, double t) {
    if (t < 0.0 || rec.accel_mps2.empty()) return 0.0;
    const double x = t / rec.dt_s;
    const auto i = static_cast<std::size_t>(std::floor(x));
    if (i + 1 >= rec.accel_mps2.size())
        return i + 1 == rec.accel_mps2.size() && x - static_cast<double>(i) < core::tol::relative
                   ? rec.accel_mps2.back()
                   : 0.0;
    const double w = x - static_cast<double>(i);
    return (1.0 - w) * rec.accel_mps2[i] + w * rec.accel_mps2[i + 1];
}

}  // namespace detail
using detail::sample_at;

Excitation excitation_from_record(const core::Record& horizontal, double scale,
                                  const core::Record* vertical, double vertical_scale) {
    core::validate(horizontal);
    if (!std::isfinite(scale))
        throw InputError({"", 0, "scale"}, fmt::format("must be finite; got {}", scale));
    Excitation e;
    e.label = horizontal.name;
    e.dt_s = horizontal.dt_s;
    e.horizontal_mps2.reserve(horizontal.size());
    for (double a : horizontal.accel_mps2) e.horizontal_mps2.push_back(scale * a);
    if (vertical) {
        core::validate(*vertical);
        e.label += " + " + vertical->name;
        e.vertical_mps2.resize(horizontal.size());
        for (std::size_t i = 0; i < horizontal.size(); ++i)
            e.vertical_mps2[i] = vertical_scale * sample_at(*vertical, horizontal.time_s(i));
    }
    return e;
}

Excitation sine_excitation(const SineSpec& spec) {
    if (!std::isfinite(spec.amplitude_g) || spec.amplitude_g < 0.0)
        throw InputError({"", 0, "sine.amplitude_g"},
                         fmt::format("must be >= 0 g; got {}", spec.amplitude_g));
    require_positive(spec.frequency_hz, {"", 0, "sine.frequency_hz"});
    require_positive(spec.duration_s, {"", 0, "sine.duration_s"});
    if (!std::isfinite(spec.ramp_s) || spec.ramp_s < 0.0)
        throw InputError({"", 0, "sine.ramp_s"}, fmt::format("must be >= 0 s; got {}", spec.ramp_s));
    if (spec.dt_s != 0.0) require_positive(spec.dt_s, {"", 0, "sine.dt_s"});
    if (!std::isfinite(spec.phase_deg))
        throw InputError({"", 0, "sine.phase_deg"}, fmt::format("must be finite; got {}", spec.phase_deg));
    const double dt_target =
        spec.dt_s > 0.0 ? spec.dt_s : std::min(0.005, 1.0 / (400.0 * spec.frequency_hz));
    core::limits::require_within(spec.frequency_hz, core::limits::max_frequency_hz,
                                 {"", 0, "sine.frequency_hz"}, "the sine's frequency");
    const double steps = core::steps_covering(spec.duration_s / dt_target);
    core::limits::require_within(steps + 1.0, core::limits::max_samples,
                                 {"", 0, "sine.duration_s"},
                                 "the sine's sampling (duration / step)");
    Excitation e;
    e.label = fmt::format("sine {} g, {} Hz, {} s", spec.amplitude_g, spec.frequency_hz,
                          spec.duration_s);
    if (spec.ramp_s > 0.0) e.label += fmt::format(", ramp {} s", spec.ramp_s);
    if (spec.phase_deg != 0.0) e.label += fmt::format(", phase {} deg", spec.phase_deg);
    const double phase_rad = spec.phase_deg * units::pi / 180.0;
    e.dt_s = spec.duration_s / steps;
    const auto n = static_cast<std::size_t>(steps) + 1;
    e.horizontal_mps2.resize(n);
    const double a = units::g_to_mps2(spec.amplitude_g);
    for (std::size_t i = 0; i < n; ++i) {
        const double t = e.dt_s * static_cast<double>(i);
        double taper = 1.0;
        if (t < spec.ramp_s) taper = 0.5 * (1.0 - std::cos(units::pi * t / spec.ramp_s));
        e.horizontal_mps2[i] = taper * a * std::sin(units::two_pi * spec.frequency_hz * t + phase_rad);
    }
    return e;
}

}  // namespace freestand::dynamics
