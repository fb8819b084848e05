// Nigam-Jennings response spectra against closed forms and a second integrator.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "core/errors.hpp"
#include "core/measures.hpp"
#include "core/readers.hpp"
#include "core/units.hpp"
#include "spectra/response.hpp"
#include "support/paths.hpp"
#include "support/sampled_record.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_spectra_test_response {

namespace fs = std::filesystem;
using namespace freestand;
using freestand::units::pi;

namespace {

using freestand::test::sampled_record;

constexpr double step_a = 2.0;  // m/s^2
double step_load(double) { return step_a; }

/// Relative displacement of u'' + 2 z w u' + w^2 u = -a under a step a from rest
/// (Chopra, Dynamics of Structures, eq. 4.3.4 with p0/k = a/w^2).
double step_response_m(double a, double w, double z, double t) {
    const double wd = w * std::sqrt(1.0 - z * z);
    return -(a / (w * w)) *
           (1.0 - std::exp(-z * w * t) *
                      (std::cos(wd * t) + z / std::sqrt(1.0 - z * z) * std::sin(wd * t)));
}

}  // namespace

TEST_CASE("undamped SDOF under a step peaks at 2 a / w^2 at t = T/2", "[spectra][response]") {
    // f = 1 Hz, dt = 0.01 s: the first peak t = pi / w = 0.5 s falls on sample 50.
    const auto rec = sampled_record(0.01, 301, step_load);
    const double w = 2.0 * pi;
    const auto peaks = spectra::peak_responses(rec, 0.0, {1.0});
    CHECK(peaks[0].sd_m == Approx(-2.0 * step_a / (w * w)).epsilon(1e-10));
    CHECK(peaks[0].time_s == Approx(0.5).margin(1e-12));
    const auto rs = spectra::response_spectra(rec, {0.0}, {1.0});
    CHECK(rs.psa_g[0][0] == Approx(2.0 * step_a / units::g_mps2).epsilon(1e-10));
    // f = 10 Hz: T = 10 dt, so 2 sub-steps per sample; the peak t = 0.05 s lies on sub-point 10.
    const double w10 = 20.0 * pi;
    const auto sub = spectra::peak_responses(rec, 0.0, {10.0, 1.0});
    CHECK(sub[0].sd_m == Approx(-2.0 * step_a / (w10 * w10)).epsilon(1e-10));
    CHECK(sub[0].time_s == Approx(0.05).margin(1e-12));
    CHECK(sub[1].time_s == Approx(0.5).margin(1e-12));
    CHECK(rs.psv_mps[0][0] == Approx(2.0 * step_a / w).epsilon(1e-10));
}

TEST_CASE("damped SDOF under a step follows the closed form before its first peak",
          "[spectra][response]") {
    // zeta = 0.05 and f chosen so the damped half period pi / wd is exactly 0.5 s (sample 50).
    const double z = 0.05;
    const double f = 1.0 / std::sqrt(1.0 - z * z);
    const double w = 2.0 * pi * f;
    // |u| rises monotonically up to the first peak, so the peak of a record cut at sample k is
    // |u(t_k)|: this checks the recurrence at every sample up to the peak.
    for (std::size_t k = 2; k <= 51; k += 7) {
        const auto rec = sampled_record(0.01, k, step_load);
        const double t = rec.duration_s();
        const auto rs = spectra::response_spectra(rec, {z}, {f});
        CHECK(rs.sd_m[0][0] == Approx(std::abs(step_response_m(step_a, w, z, t))).epsilon(1e-10));
    }
    const auto rec = sampled_record(0.01, 400, step_load);
    const auto peaks = spectra::peak_responses(rec, z, {f});
    const double overshoot = 1.0 + std::exp(-z * pi / std::sqrt(1.0 - z * z));
    CHECK(peaks[0].sd_m == Approx(-step_a / (w * w) * overshoot).epsilon(1e-10));
    CHECK(peaks[0].time_s == Approx(0.5).margin(1e-12));
}

namespace {

constexpr double sine_amp = 3.0;               // m/s^2
constexpr double sine_omega = 2.0 * pi * 0.8;  // rad/s
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

TEST_CASE("SDOF under a sine matches the exact steady plus transient solution",
          "[spectra][response]") {
    // Input sampled at dt = 2e-4 s: the piecewise-linear error in the load is ~(W dt)^2 / 8 =
    // 1.6e-7 relative; sub-steps of T/2000 resolve the peak to 1 - cos(pi/2000) = 1.2e-6.
    const double dt = 2e-4;
    const auto rec = sampled_record(dt, 50001, sine_load);  // 10 s
    for (double z : {0.0, 0.02, 0.05}) {
        for (double f : {0.5, 1.0, 3.0}) {
            const double w = 2.0 * pi * f;
            double exact = 0.0;
            for (int i = 0; i <= 1000000; ++i)
                exact = std::max(exact, std::abs(sine_response_m(w, z, 1e-5 * i)));
            const auto rs =
                spectra::response_spectra(rec, {z}, {f}, spectra::ResponseOptions{2000});
            INFO("zeta " << z << ", f " << f << " Hz");
            CHECK(rs.sd_m[0][0] == Approx(exact).epsilon(1e-5));
        }
    }
}

namespace {

const char* const shipped_records[] = {"RSN175_IMPVALL.H_H-E12140.AT2",
                                       "RSN175_IMPVALL.H_H-E12230.AT2",
                                       "RSN1546_CHICHI_TCU122-N.AT2"};

core::Record shipped(const char* name) {
    return core::read_at2(fs::path(freestand::test::data_dir()) / name);
}

/// Second method: classical RK4 on the same piecewise-linear input, with steps <= T/400, peak
/// |u| taken at the same points the Nigam-Jennings code uses (n equal sub-points per sample,
/// n = ceil(20 f dt)), so both compute the same quantity and only the integrator differs.
double rk4_peak_m(const core::Record& rec, double f_hz, double zeta) {
    const double w = 2.0 * pi * f_hz;
    const double dt = rec.dt_s;
    const int n = std::max(1, static_cast<int>(std::ceil(20.0 * f_hz * dt - 1e-12)));
    const int m = std::max(1, static_cast<int>(std::ceil(400.0 * f_hz * dt / n)));
    const double h = dt / (n * m);
    const auto& a = rec.accel_mps2;
    double u = 0.0, v = 0.0, peak = 0.0;
    for (std::size_t i = 1; i < a.size(); ++i) {
        const double slope = (a[i] - a[i - 1]) / dt;
        const auto acc = [&](double tau, double uu, double vv) {
            return -(a[i - 1] + slope * tau) - 2.0 * zeta * w * vv - w * w * uu;
        };
        for (int k = 0; k < n * m; ++k) {
            const double t = h * k;
            const double k1u = v, k1v = acc(t, u, v);
            const double k2u = v + 0.5 * h * k1v,
                         k2v = acc(t + 0.5 * h, u + 0.5 * h * k1u, v + 0.5 * h * k1v);
            const double k3u = v + 0.5 * h * k2v,
                         k3v = acc(t + 0.5 * h, u + 0.5 * h * k2u, v + 0.5 * h * k2v);
            const double k4u = v + h * k3v, k4v = acc(t + h, u + h * k3u, v + h * k3v);
            u += h / 6.0 * (k1u + 2.0 * k2u + 2.0 * k3u + k4u);
            v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
            if ((k + 1) % m == 0) peak = std::max(peak, std::abs(u));
        }
    }
    return peak;
}

}  // namespace

TEST_CASE("Nigam-Jennings agrees with fine-step RK4 on the three shipped records to 1e-4",
          "[spectra][response]") {
    const std::vector<double> f{0.1, 0.37, 1.3, 4.1, 11.0, 27.0, 80.0};
    const std::vector<double> z{0.02, 0.05};
    for (const char* name : shipped_records) {
        const auto rec = shipped(name);
        const auto rs = spectra::response_spectra(rec, z, f);
        for (std::size_t d = 0; d < z.size(); ++d) {
            for (std::size_t i = 0; i < f.size(); ++i) {
                INFO(name << " f " << f[i] << " Hz zeta " << z[d]);
                CHECK(rs.sd_m[d][i] == Approx(rk4_peak_m(rec, f[i], z[d])).epsilon(1e-4));
            }
        }
    }
}

TEST_CASE("rigid limit: PSA at 100 Hz equals PGA within 1%", "[spectra][response]") {
    for (const char* name : shipped_records) {
        const auto rec = shipped(name);
        const double pga = core::measure(rec).pga_g;
        const auto psa = spectra::psa_g(rec, 0.05, {100.0});
        INFO(name);
        CHECK(psa[0] == Approx(pga).epsilon(0.01));
    }
}

TEST_CASE("sub-stepping to T/20 catches peaks between samples", "[spectra][response]") {
    // Around T = 10 dt (20 Hz at dt = 0.005 s), +-0.1 decade. Reference: sub-steps T/2000.
    // Measured on El Centro 140: 2.2% worst error with one step per sample, 0.34% with T/20;
    // the bound for a sampled harmonic peak is 1 - cos(pi h / T): 4.9% at h = T/10, 1.23% at T/20.
    const auto rec = shipped(shipped_records[0]);
    std::vector<double> f;
    for (int k = -10; k <= 10; ++k) f.push_back(20.0 * std::pow(10.0, k / 100.0));
    const auto ref = spectra::response_spectra(rec, {0.05}, f, spectra::ResponseOptions{2000});
    const auto t20 = spectra::response_spectra(rec, {0.05}, f);
    const auto none = spectra::response_spectra(rec, {0.05}, f, spectra::ResponseOptions{0});
    double err20 = 0.0, err_none = 0.0;
    for (std::size_t i = 0; i < f.size(); ++i) {
        err20 = std::max(err20, std::abs(t20.psa_g[0][i] / ref.psa_g[0][i] - 1.0));
        err_none = std::max(err_none, std::abs(none.psa_g[0][i] / ref.psa_g[0][i] - 1.0));
        // A sampled peak never exceeds the true one, which is within 1 - cos(pi/2000) = 1.2e-6
        // of the reference.
        CHECK(t20.psa_g[0][i] <= ref.psa_g[0][i] * (1.0 + 2e-6));
    }
    CHECK(err20 < 0.005);
    CHECK(err_none > 0.015);
    CHECK(err_none < 1.0 - std::cos(pi / 10.0));
}

TEST_CASE("psa_g, response_spectra and peak_responses agree, SD, PSV, PSA are consistent",
          "[spectra][response]") {
    const auto rec = shipped(shipped_records[1]);
    const std::vector<double> f{0.2, 1.0, 5.0, 25.0, 60.0, 3.0};  // any order is accepted
    const auto rs = spectra::response_spectra(rec, {0.05, 0.1}, f);
    const auto fast = spectra::psa_g(rec, 0.1, f);
    const auto peaks = spectra::peak_responses(rec, 0.1, f);
    for (std::size_t i = 0; i < f.size(); ++i) {
        const double w = 2.0 * pi * f[i];
        CHECK(fast[i] == Approx(rs.psa_g[1][i]).epsilon(1e-14));
        CHECK(std::abs(peaks[i].sd_m) == Approx(rs.sd_m[1][i]).epsilon(1e-14));
        CHECK(peaks[i].time_s > 0.0);
        CHECK(peaks[i].time_s <= rec.duration_s());
        CHECK(rs.psv_mps[0][i] == Approx(w * rs.sd_m[0][i]).epsilon(1e-14));
        CHECK(rs.psa_g[0][i] == Approx(w * w * rs.sd_m[0][i] / units::g_mps2).epsilon(1e-14));
    }
    CHECK_THROWS_WITH(rs.spectrum(0),
                      Catch::Contains("frequency_hz: frequencies are not strictly increasing"));
    CHECK_THROWS_WITH(rs.spectrum(2),
                      Catch::Contains("damping_index: damping index 2 out of range"));
}

TEST_CASE("response spectra reject bad dampings, frequencies and records", "[spectra][response]") {
    const auto rec = sampled_record(0.01, 10, step_load);
    const auto one = sampled_record(0.01, 1, step_load);
    CHECK_THROWS_WITH(spectra::psa_g(one, 0.05, {1.0}),
                      Catch::Contains("test: samples: record \"synthetic\" has 1 sample; expected "
                                      "at least 2"));
    CHECK_THROWS_WITH(spectra::response_spectra(one, {0.05}, {1.0}), Catch::Contains("1 sample"));
    CHECK_THROWS_AS(spectra::psa_g(rec, 1.0, {1.0}), InputError);
    CHECK_THROWS_WITH(spectra::psa_g(rec, 1.0, {1.0}),
                      Catch::Contains("damping: value 1 is out of range; expected [0, 1)"));
    CHECK_THROWS_WITH(spectra::psa_g(rec, -0.1, {1.0}),
                      Catch::Contains("damping: value -0.1 is out of range; expected [0, 1)"));
    CHECK_THROWS_WITH(spectra::psa_g(rec, 0.05, {0.0}),
                      Catch::Contains("frequency_hz: value 0 must be a finite number > 0"));
    CHECK_THROWS_WITH(spectra::psa_g(rec, 0.05, {}),
                      Catch::Contains("frequency_hz: no frequency given"));
    CHECK_THROWS_WITH(spectra::response_spectra(rec, {}, {1.0}),
                      Catch::Contains("damping: no damping given"));
    core::Record empty = rec;
    empty.accel_mps2.clear();
    CHECK_THROWS_WITH(spectra::psa_g(empty, 0.05, {1.0}), Catch::Contains("record has no samples"));
    core::Record nan = rec;
    nan.accel_mps2[3] = std::nan("");
    CHECK_THROWS_WITH(spectra::psa_g(nan, 0.05, {1.0}),
                      Catch::Contains("sample 3 is not a finite number"));
}

namespace {

/// Frequencies 0.1-100 Hz at 30 per decade: at dt = 0.005 s, 1 to 10 sub-steps per sample and
/// groups of every size the vector loops form.
std::vector<double> wide_band() {
    std::vector<double> f;
    for (int k = 0; k <= 90; ++k) f.push_back(0.1 * std::pow(10.0, k / 30.0));
    return f;
}

/// The record's first `samples` samples.
core::Record first_part(const core::Record& rec, std::size_t samples) {
    core::Record out = rec;
    out.accel_mps2.resize(samples);
    return out;
}

}  // namespace

TEST_CASE("an OscillatorSet gives the free functions' bits at every vector width",
          "[spectra][response]") {
    const auto f = wide_band();
    for (const char* name : shipped_records) {
        // Lengths with a partial last block of peak logging and with a single step.
        for (std::size_t samples : {std::size_t{0}, std::size_t{1001}, std::size_t{2}}) {
            const auto full = shipped(name);
            const auto rec = samples == 0 ? full : first_part(full, samples);
            const auto psa = spectra::psa_g(rec, 0.05, f);
            const auto peaks = spectra::peak_responses(rec, 0.05, f);
            for (int lanes : {8, 4, 2}) {
                spectra::ResponseOptions o;
                o.max_lanes = lanes;
                const spectra::OscillatorSet set(0.05, f, rec.dt_s, o);
                const auto set_psa = set.psa_g(rec);
                const auto set_sd = set.sd_m(rec);
                const auto set_peaks = set.peak_responses(rec);
                const auto rs = spectra::response_spectra(rec, {0.05}, f, o);
                INFO(name << ", " << rec.size() << " samples, up to " << lanes << " lanes");
                for (std::size_t i = 0; i < f.size(); ++i) {
                    INFO("f " << f[i] << " Hz");
                    CHECK(set_psa[i] == psa[i]);
                    CHECK(rs.psa_g[0][i] == psa[i]);
                    CHECK(set_sd[i] == std::abs(peaks[i].sd_m));
                    CHECK(set_peaks[i].sd_m == peaks[i].sd_m);
                    CHECK(set_peaks[i].time_s == peaks[i].time_s);
                }
            }
        }
    }
}

TEST_CASE("peak_responses reports the first sub-point reaching the peak", "[spectra][response]") {
    // The recurrence up to sample k does not depend on later samples, so the record cut after
    // the peak's sample has the same SD, bit for bit, and the record cut before it a smaller one.
    const auto rec = shipped(shipped_records[0]);
    const std::vector<double> f{0.13, 0.9, 2.7, 8.0, 16.0, 45.0};  // 1, 1, 1, 1, 2 and 5 sub-steps
    const auto peaks = spectra::peak_responses(rec, 0.05, f);
    const spectra::OscillatorSet set(0.05, f, rec.dt_s);
    const auto sd = set.sd_m(rec);
    for (std::size_t i = 0; i < f.size(); ++i) {
        // The peak lies in the step ending at sample k (a sub-point of step k).
        const auto k = static_cast<std::size_t>(std::ceil(peaks[i].time_s / rec.dt_s - 1e-9));
        INFO("f " << f[i] << " Hz, peak at " << peaks[i].time_s << " s, sample " << k);
        REQUIRE(k >= 1);
        CHECK(std::abs(peaks[i].sd_m) == sd[i]);
        CHECK(spectra::OscillatorSet(0.05, {f[i]}, rec.dt_s).sd_m(first_part(rec, k + 1))[0] ==
              sd[i]);
        CHECK(spectra::OscillatorSet(0.05, {f[i]}, rec.dt_s).sd_m(first_part(rec, k))[0] < sd[i]);
    }
}

TEST_CASE("one OscillatorSet serves several threads at once with the same results",
          "[spectra][response]") {
    const auto base = shipped(shipped_records[1]);
    const spectra::OscillatorSet set(0.05, wide_band(), base.dt_s);
    std::vector<core::Record> records;
    for (int k = 1; k <= 4; ++k) {
        core::Record r = base;
        for (double& a : r.accel_mps2) a *= 0.5 * k;
        records.push_back(r);
    }
    std::vector<std::vector<double>> serial_psa;
    std::vector<std::vector<spectra::OscillatorPeak>> serial_peaks;
    for (const auto& r : records) {
        serial_psa.push_back(set.psa_g(r));
        serial_peaks.push_back(set.peak_responses(r));
    }
    std::vector<std::vector<double>> psa(records.size());
    std::vector<std::vector<spectra::OscillatorPeak>> peaks(records.size());
    std::vector<std::thread> threads;
    for (std::size_t k = 0; k < records.size(); ++k)
        threads.emplace_back([&, k] {
            psa[k] = set.psa_g(records[k]);
            peaks[k] = set.peak_responses(records[k]);
        });
    for (auto& t : threads) t.join();
    for (std::size_t k = 0; k < records.size(); ++k) {
        CHECK(psa[k] == serial_psa[k]);
        for (std::size_t i = 0; i < peaks[k].size(); ++i) {
            CHECK(peaks[k][i].sd_m == serial_peaks[k][i].sd_m);
            CHECK(peaks[k][i].time_s == serial_peaks[k][i].time_s);
        }
    }
}

TEST_CASE("an OscillatorSet rejects bad set-up values and a record of another time step",
          "[spectra][response]") {
    CHECK_THROWS_WITH(spectra::OscillatorSet(1.0, {1.0}, 0.01),
                      Catch::Contains("damping: value 1 is out of range; expected [0, 1)"));
    CHECK_THROWS_WITH(spectra::OscillatorSet(0.05, {}, 0.01),
                      Catch::Contains("frequency_hz: no frequency given"));
    CHECK_THROWS_WITH(spectra::OscillatorSet(0.05, {1.0}, 0.0),
                      Catch::Contains("dt_s: value 0 must be a finite number > 0"));
    const spectra::OscillatorSet set(0.05, {1.0}, 0.01);
    CHECK(set.dt_s() == 0.01);
    CHECK(set.damping() == 0.05);
    CHECK(set.frequency_hz() == std::vector<double>{1.0});
    const auto rec = sampled_record(0.02, 10, step_load);
    CHECK_THROWS_AS(set.psa_g(rec), InputError);
    CHECK_THROWS_WITH(set.peak_responses(rec),
                      Catch::Contains("test: dt: record \"synthetic\" is sampled at dt 0.02 s; "
                                      "these oscillators were set up for dt 0.01 s"));
    CHECK_THROWS_WITH(set.sd_m(sampled_record(0.01, 1, step_load)), Catch::Contains("1 sample"));
}

}  // namespace freestand_test_spectra_test_response
