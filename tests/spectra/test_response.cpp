// Nigam-Jennings response spectra against closed forms and a second integrator.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/measures.hpp"
#include "core/readers.hpp"
#include "core/units.hpp"
#include "spectra/response.hpp"

namespace fs = std::filesystem;
using namespace freestand;
using freestand::units::pi;

namespace {

core::Record make_record(double dt_s, std::size_t count, double (*a)(double)) {
    core::Record r;
    r.name = "synthetic";
    r.source = "test";
    r.dt_s = dt_s;
    r.accel_mps2.resize(count);
    for (std::size_t i = 0; i < count; ++i) r.accel_mps2[i] = a(dt_s * static_cast<double>(i));
    return r;
}

constexpr double step_a = 2.0;  // m/s^2
double step_load(double) { return step_a; }

/// Relative displacement of u'' + 2 z w u' + w^2 u = -a under a step a from rest
/// (Chopra, Dynamics of Structures, eq. 4.3.4 with p0/k = a/w^2).
double step_response_m(double a, double w, double z, double t) {
    const double wd = w * std::sqrt(1.0 - z * z);
    return -(a / (w * w)) *
           (1.0 - std::exp(-z * w * t) * (std::cos(wd * t) + z / std::sqrt(1.0 - z * z) * std::sin(wd * t)));
}

}  // namespace

TEST_CASE("undamped SDOF under a step peaks at 2 a / w^2 at t = T/2", "[spectra][response]") {
    // f = 1 Hz, dt = 0.01 s: the first peak t = pi / w = 0.5 s falls on sample 50.
    const auto rec = make_record(0.01, 301, step_load);
    const double w = 2.0 * pi;
    const auto peaks = spectra::peak_responses(rec, 0.0, {1.0});
    CHECK(peaks[0].sd_m == Approx(-2.0 * step_a / (w * w)).epsilon(1e-10));
    CHECK(peaks[0].time_s == Approx(0.5).margin(1e-12));
    const auto rs = spectra::response_spectra(rec, {0.0}, {1.0});
    CHECK(rs.psa_g[0][0] == Approx(2.0 * step_a / units::g_mps2).epsilon(1e-10));
    CHECK(rs.psv_mps[0][0] == Approx(2.0 * step_a / w).epsilon(1e-10));
}

TEST_CASE("damped SDOF under a step follows the closed form before its first peak", "[spectra][response]") {
    // zeta = 0.05 and f chosen so the damped half period pi / wd is exactly 0.5 s (sample 50).
    const double z = 0.05;
    const double f = 1.0 / std::sqrt(1.0 - z * z);
    const double w = 2.0 * pi * f;
    // |u| rises monotonically up to the first peak, so the peak of a record cut at sample k is
    // |u(t_k)|: this checks the recurrence at every sample up to the peak.
    for (std::size_t k = 2; k <= 51; k += 7) {
        const auto rec = make_record(0.01, k, step_load);
        const double t = rec.duration_s();
        const auto rs = spectra::response_spectra(rec, {z}, {f});
        CHECK(rs.sd_m[0][0] == Approx(std::abs(step_response_m(step_a, w, z, t))).epsilon(1e-10));
    }
    const auto rec = make_record(0.01, 400, step_load);
    const auto peaks = spectra::peak_responses(rec, z, {f});
    const double overshoot = 1.0 + std::exp(-z * pi / std::sqrt(1.0 - z * z));
    CHECK(peaks[0].sd_m == Approx(-step_a / (w * w) * overshoot).epsilon(1e-10));
    CHECK(peaks[0].time_s == Approx(0.5).margin(1e-12));
}

namespace {

constexpr double sine_amp = 3.0;                // m/s^2
constexpr double sine_omega = 2.0 * pi * 0.8;   // rad/s
double sine_load(double t) { return sine_amp * std::sin(sine_omega * t); }

/// u'' + 2 z w u' + w^2 u = -A sin(W t) from rest: steady state C sin Wt + D cos Wt with
/// (w^2 - W^2) C - 2 z w W D = -A, (w^2 - W^2) D + 2 z w W C = 0, plus the transient
/// e^{-z w t}(E cos wd t + F sin wd t) with E = -D, F = (z w E - C W) / wd (u(0) = u'(0) = 0).
double sine_response_m(double w, double z, double t) {
    const double W = sine_omega;
    const double denom = (w * w - W * W) * (w * w - W * W) + (2.0 * z * w * W) * (2.0 * z * w * W);
    const double C = -sine_amp * (w * w - W * W) / denom;
    const double D = sine_amp * 2.0 * z * w * W / denom;
    const double wd = w * std::sqrt(1.0 - z * z);
    const double E = -D;
    const double F = (z * w * E - C * W) / wd;
    return C * std::sin(W * t) + D * std::cos(W * t) +
           std::exp(-z * w * t) * (E * std::cos(wd * t) + F * std::sin(wd * t));
}

}  // namespace

TEST_CASE("SDOF under a sine matches the exact steady plus transient solution", "[spectra][response]") {
    // Input sampled at dt = 2e-4 s: the piecewise-linear error in the load is ~(W dt)^2 / 8 =
    // 1.6e-7 relative; sub-steps of T/2000 resolve the peak to 1 - cos(pi/2000) = 1.2e-6.
    const double dt = 2e-4;
    const auto rec = make_record(dt, 50001, sine_load);  // 10 s
    for (double z : {0.0, 0.02, 0.05}) {
        for (double f : {0.5, 1.0, 3.0}) {
            const double w = 2.0 * pi * f;
            double exact = 0.0;
            for (int i = 0; i <= 1000000; ++i)
                exact = std::max(exact, std::abs(sine_response_m(w, z, 1e-5 * i)));
            const auto rs = spectra::response_spectra(rec, {z}, {f}, spectra::ResponseOptions{2000});
            INFO("zeta " << z << ", f " << f << " Hz");
            CHECK(rs.sd_m[0][0] == Approx(exact).epsilon(1e-5));
        }
    }
}
