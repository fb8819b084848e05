#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "support/paths.hpp"
#include "core/errors.hpp"
#include "core/measures.hpp"
#include "core/readers.hpp"
#include "core/units.hpp"
#include "support/sampled_record.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_core_test_measures {

namespace fs = std::filesystem;
using namespace freestand;

namespace {

constexpr double tight_rel = 1e-12;  // closed forms the trapezoid reproduces exactly (rounding only)

using freestand::test::sampled_record;

}  // namespace

TEST_CASE("Constant acceleration integrates exactly: v = a t, d = a t^2 / 2", "[core][measures]") {
    // The trapezoid is exact for linear v; for d it sums a dt^2 (2i - 1) / 2 = a (i dt)^2 / 2.
    const double a = 2.0;
    const auto rec = sampled_record(0.01, 101, [](double) { return 2.0; });
    const auto v = core::velocity_mps(rec);
    const auto d = core::displacement_m(rec);
    for (std::size_t i = 0; i < rec.size(); ++i) {
        const double t = rec.time_s(i);
        CHECK(v[i] == Approx(a * t).epsilon(tight_rel).margin(1e-15));
        CHECK(d[i] == Approx(0.5 * a * t * t).epsilon(tight_rel).margin(1e-15));
    }
    const auto gm = core::measure(rec);
    CHECK(gm.pga_g == Approx(a / units::g_mps2).epsilon(tight_rel));
    CHECK(gm.pgv_mps == Approx(a * 1.0).epsilon(tight_rel));
    CHECK(gm.pgd_m == Approx(0.5 * a).epsilon(tight_rel));
    CHECK(gm.final_velocity_mps == Approx(2.0).epsilon(tight_rel));
    CHECK(gm.final_displacement_m == Approx(1.0).epsilon(tight_rel));
    // I_a = pi / (2 g) a^2 T; Husid is linear in t, so D5-75 = 0.70 T and D5-95 = 0.90 T.
    CHECK(gm.arias_mps == Approx(units::pi / (2.0 * units::g_mps2) * a * a * 1.0).epsilon(tight_rel));
    CHECK(gm.d5_75_s == Approx(0.70).epsilon(1e-10));
    CHECK(gm.d5_95_s == Approx(0.90).epsilon(1e-10));
}

TEST_CASE("Sine acceleration: PGV, PGD and Arias intensity against closed forms", "[core][measures]") {
    // a = a0 sin(w t), 1 Hz, 10 whole cycles. From rest: v = a0/w (1 - cos w t), peak 2 a0/w at
    // t = T/2; d = a0/w (t - sin(w t)/w), peak at the end. Trapezoid error is O(dt^2): with
    // dt = 1 ms it is (w dt)^2 / 12 ~ 3e-6 relative, so 1e-5 is the stated tolerance.
    const double a0 = 3.0;
    const double w = units::two_pi;
    const auto rec =
        sampled_record(0.001, 10001, [](double t) { return 3.0 * std::sin(units::two_pi * t); });
    const auto gm = core::measure(rec);
    CHECK(gm.pga_g == Approx(a0 / units::g_mps2).epsilon(1e-6));
    CHECK(gm.pgv_mps == Approx(2.0 * a0 / w).epsilon(1e-5));
    CHECK(gm.pgd_m == Approx(a0 / w * 10.0).epsilon(1e-5));
    CHECK(gm.final_velocity_mps == Approx(0.0).margin(1e-5 * a0 / w));
    // The trapezoid sums sin^2 over whole periods exactly (discrete orthogonality), so
    // I_a = pi / (2 g) a0^2 T / 2 holds to rounding.
    CHECK(gm.arias_mps == Approx(units::pi / (2.0 * units::g_mps2) * a0 * a0 * 10.0 / 2.0).epsilon(1e-12));
}

TEST_CASE("Significant duration of a box-shaped record is 0.9 of its length", "[core][measures]") {
    // 100 zeros, 200 samples of 1.5 m/s^2, 100 zeros: the trapezoid spreads the energy over
    // exactly 200 dt (half a step at each edge), and both crossings fall where the Husid curve
    // is linear, so D5-95 = 0.9 * 200 dt and D5-75 = 0.7 * 200 dt exactly.
    core::Record rec;
    rec.dt_s = 0.01;
    rec.accel_mps2.assign(400, 0.0);
    for (std::size_t i = 100; i < 300; ++i) rec.accel_mps2[i] = 1.5;
    const auto gm = core::measure(rec);
    CHECK(gm.d5_95_s == Approx(1.8).epsilon(1e-12));
    CHECK(gm.d5_75_s == Approx(1.4).epsilon(1e-12));
    CHECK(core::significant_duration_s(rec, 0.25, 0.75) == Approx(1.0).epsilon(1e-12));
    const auto h = core::husid(rec);
    CHECK(h.front() == 0.0);
    CHECK(h.back() == 1.0);
}

TEST_CASE("Crossing time interpolates linearly between samples", "[core][measures]") {
    const std::vector<double> curve{0.0, 0.2, 0.6, 1.0};
    CHECK(core::crossing_time_s(curve, 0.5, 0.4) == Approx(0.75).epsilon(1e-14));  // half-way 1 -> 2
    CHECK(core::crossing_time_s(curve, 0.5, 0.0) == 0.0);
    CHECK(core::crossing_time_s(curve, 0.5, 1.0) == Approx(1.5).epsilon(1e-14));
    CHECK(core::crossing_time_s(curve, 0.5, 2.0) == Approx(1.5).epsilon(1e-14));  // never reached
}

TEST_CASE("A record without energy has zero Arias intensity and durations", "[core][measures]") {
    core::Record rec;
    rec.dt_s = 0.02;
    rec.accel_mps2.assign(50, 0.0);
    const auto gm = core::measure(rec);
    CHECK(gm.arias_mps == 0.0);
    CHECK(gm.d5_75_s == 0.0);
    CHECK(gm.d5_95_s == 0.0);
    CHECK(gm.pgd_m == 0.0);
}

TEST_CASE("Measures reject an invalid record and bad duration fractions", "[core][measures]") {
    core::Record empty;
    empty.source = "empty-record";
    empty.dt_s = 0.01;
    CHECK_THROWS_AS(core::measure(empty), InputError);
    CHECK_THROWS_WITH(core::measure(empty), Catch::Contains("empty-record: record has no samples"));
    core::Record bad;
    bad.source = "nan-record";
    bad.dt_s = 0.01;
    bad.accel_mps2 = {0.0, std::nan(""), 1.0};
    CHECK_THROWS_WITH(core::velocity_mps(bad), Catch::Contains("nan-record: sample 1 is not a finite number"));
    core::Record ok;
    ok.dt_s = 0.01;
    ok.accel_mps2 = {0.0, 1.0, 0.0};
    CHECK_THROWS_AS(core::significant_duration_s(ok, 0.95, 0.05), InputError);
    CHECK_THROWS_WITH(core::significant_duration_s(ok, 0.95, 0.05),
                      Catch::Contains("significant duration: fractions 0.95 and 0.05 must satisfy 0 <= from < to <= 1"));
}

TEST_CASE("Measures of the shipped records agree with independent sums", "[core][measures]") {
    for (const char* file : {"RSN175_IMPVALL.H_H-E12140.AT2", "RSN1546_CHICHI_TCU122-N.AT2"}) {
        const auto rec = core::read_at2(fs::path(freestand::test::data_dir()) / file);
        const auto gm = core::measure(rec);
        // Independent: closed-form trapezoid sums in long double, no running integrals shared
        // with the library. v_N = dt (sum a - (a_0 + a_N)/2), I_a likewise on a^2, and
        // d_N = dt^2 sum_i (N - i) a_i with the end corrections of the double trapezoid.
        const auto& a = rec.accel_mps2;
        const std::size_t n = a.size();
        const long double dt = rec.dt_s;
        long double sum_a = 0, sum_a2 = 0, peak = 0;
        for (double x : a) {
            sum_a += x;
            sum_a2 += static_cast<long double>(x) * x;
            peak = std::max(peak, std::fabs(static_cast<long double>(x)));
        }
        const long double v_end = dt * (sum_a - 0.5L * (a.front() + a.back()));
        const long double ia = units::pi / (2.0 * units::g_mps2) * dt *
                               (sum_a2 - 0.5L * (static_cast<long double>(a.front()) * a.front() +
                                                 static_cast<long double>(a.back()) * a.back()));
        // d_N = dt sum_{k=1}^{N-1} v_k + dt v_N / 2 (v_0 = 0), with v_k from its own closed form.
        long double prefix = 0, d_end = 0, v_k = 0;
        for (std::size_t k = 1; k < n; ++k) {
            prefix += a[k - 1];
            v_k = dt * (prefix - 0.5L * a.front() + 0.5L * a[k]);
            d_end += (k + 1 < n ? dt : 0.5L * dt) * v_k;
        }
        INFO(file);
        CHECK(gm.pga_g == Approx(static_cast<double>(peak) / units::g_mps2).epsilon(1e-14));
        CHECK(gm.final_velocity_mps == Approx(static_cast<double>(v_end)).margin(1e-9));
        CHECK(gm.final_displacement_m == Approx(static_cast<double>(d_end)).margin(1e-8));
        CHECK(gm.arias_mps == Approx(static_cast<double>(ia)).epsilon(1e-10));
        // Husid crossings from a long-double running sum, interpolated on the crossing segment.
        std::vector<long double> cum(n, 0.0L);
        for (std::size_t k = 1; k < n; ++k)
            cum[k] = cum[k - 1] + 0.5L * dt * (static_cast<long double>(a[k - 1]) * a[k - 1] +
                                               static_cast<long double>(a[k]) * a[k]);
        const auto crossing = [&](long double fraction) {
            const long double level = fraction * cum.back();
            std::size_t k = 1;
            while (cum[k] < level) ++k;
            return static_cast<double>(dt * (static_cast<long double>(k - 1) + (level - cum[k - 1]) / (cum[k] - cum[k - 1])));
        };
        CHECK(gm.d5_75_s == Approx(crossing(0.75L) - crossing(0.05L)).epsilon(1e-9));
        CHECK(gm.d5_95_s == Approx(crossing(0.95L) - crossing(0.05L)).epsilon(1e-9));
        CHECK(core::significant_duration_s(rec, 0.05, 0.95) == gm.d5_95_s);
        CHECK(gm.d5_95_s < rec.duration_s());
    }
}

}  // namespace freestand_test_core_test_measures
