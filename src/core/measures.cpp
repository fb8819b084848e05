#include "core/measures.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/units.hpp"

namespace freestand::core {

namespace {

/// Cumulative trapezoidal integral of samples y at step dt, starting at 0.
std::vector<double> cumulative_trapezoid(const std::vector<double>& y, double dt_s) {
    std::vector<double> out(y.size(), 0.0);
    for (std::size_t i = 1; i < y.size(); ++i) out[i] = out[i - 1] + 0.5 * dt_s * (y[i - 1] + y[i]);
    return out;
}

double max_abs(const std::vector<double>& y) {
    double peak = 0.0;
    for (double v : y) peak = std::max(peak, std::abs(v));
    return peak;
}

}  // namespace

std::vector<double> velocity_mps(const Record& record) {
    validate(record);
    return cumulative_trapezoid(record.accel_mps2, record.dt_s);
}

std::vector<double> displacement_m(const Record& record) {
    return cumulative_trapezoid(velocity_mps(record), record.dt_s);
}

std::vector<double> velocity_mps(const std::vector<double>& accel_mps2, double dt_s) {
    return cumulative_trapezoid(accel_mps2, dt_s);
}

std::vector<double> displacement_m(const std::vector<double>& accel_mps2, double dt_s) {
    return cumulative_trapezoid(cumulative_trapezoid(accel_mps2, dt_s), dt_s);
}

std::vector<double> arias_intensity_mps(const Record& record, double g_mps2) {
    validate(record);
    std::vector<double> a2(record.size());
    std::transform(record.accel_mps2.begin(), record.accel_mps2.end(), a2.begin(),
                   [](double a) { return a * a; });
    std::vector<double> cumulative = cumulative_trapezoid(a2, record.dt_s);
    // Arias (1970): I_a = pi / (2 g) * integral a(t)^2 dt.
    for (double& v : cumulative) v *= units::pi / (2.0 * g_mps2);
    return cumulative;
}

namespace {

std::vector<double> normalised(std::vector<double> cumulative) {
    const double total = cumulative.back();
    if (total <= 0.0) return std::vector<double>(cumulative.size(), 0.0);
    for (double& v : cumulative) v /= total;
    return cumulative;
}

}  // namespace

std::vector<double> husid(const Record& record) { return normalised(arias_intensity_mps(record)); }

double crossing_time_s(const std::vector<double>& curve, double dt_s, double level) {
    const auto it = std::find_if(curve.begin(), curve.end(), [level](double v) { return v >= level; });
    if (it == curve.end()) return curve.empty() ? 0.0 : dt_s * static_cast<double>(curve.size() - 1);
    const auto i = static_cast<std::size_t>(it - curve.begin());
    if (i == 0) return 0.0;
    // curve[i-1] < level <= curve[i], so the denominator is > 0.
    const double fraction = (level - curve[i - 1]) / (curve[i] - curve[i - 1]);
    return dt_s * (static_cast<double>(i - 1) + fraction);
}

namespace {

double duration_from_husid(const std::vector<double>& h, double dt_s, double from, double to) {
    if (h.back() <= 0.0) return 0.0;
    return crossing_time_s(h, dt_s, to) - crossing_time_s(h, dt_s, from);
}

}  // namespace

double significant_duration_s(const Record& record, double from_fraction, double to_fraction) {
    if (!(from_fraction >= 0.0 && from_fraction < to_fraction && to_fraction <= 1.0))
        throw InputError({"", 0, "significant duration"},
                         fmt::format("fractions {} and {} must satisfy 0 <= from < to <= 1",
                                     from_fraction, to_fraction));
    return duration_from_husid(husid(record), record.dt_s, from_fraction, to_fraction);
}

GroundMotion measure(const Record& record, double g_mps2) {
    validate(record);
    const std::vector<double> v = velocity_mps(record);
    const std::vector<double> d = cumulative_trapezoid(v, record.dt_s);
    const std::vector<double> arias = arias_intensity_mps(record, g_mps2);
    const std::vector<double> h = normalised(arias);
    GroundMotion gm;
    gm.pga_g = units::mps2_to_g(max_abs(record.accel_mps2), g_mps2);
    gm.pgv_mps = max_abs(v);
    gm.pgd_m = max_abs(d);
    gm.arias_mps = arias.back();
    gm.d5_75_s = duration_from_husid(h, record.dt_s, 0.05, 0.75);
    gm.d5_95_s = duration_from_husid(h, record.dt_s, 0.05, 0.95);
    gm.final_velocity_mps = v.back();
    gm.final_displacement_m = d.back();
    return gm;
}

}  // namespace freestand::core
