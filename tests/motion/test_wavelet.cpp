// Closed forms behind the matcher: Faddeeva function, wavelet response, end weights, RNG.
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include "core/measures.hpp"
#include "core/random.hpp"
#include "core/units.hpp"
#include "motion/criteria.hpp"
#include "motion/faddeeva.hpp"
#include "motion/internal.hpp"
#include "motion/wavelet.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_motion_test_wavelet {

using namespace freestand;
using namespace freestand::motion;

TEST_CASE("Faddeeva function against real closed forms", "[motion][faddeeva]") {
    // w(iy) = exp(y^2) erfc(y) (real) and Re w(x) = exp(-x^2) on the real axis
    // (Abramowitz & Stegun 7.1.3, 7.1.29); tolerance 1e-8 relative (stated accuracy).
    for (double y : {0.0, 0.1, 0.5, 1.0, 2.0, 5.0, 7.9, 8.1, 20.0}) {
        const std::complex<double> w = faddeeva_upper({0.0, y});
        const double ref = std::exp(y * y) * std::erfc(y);  // erfc(20) ~ 5e-176, no underflow
        CHECK(w.real() == Approx(ref).epsilon(1e-8));
        CHECK(std::abs(w.imag()) < 1e-12);
    }
    for (double x : {0.0, 0.3, 1.0, 2.5, 4.0})
        CHECK(faddeeva_upper({x, 0.0}).real() == Approx(std::exp(-x * x)).margin(1e-9));
    // Dawson's function: Im w(x) = 2/sqrt(pi) F(x); F(1) = 0.5380795069127684 (A&S Table 7.5).
    CHECK(faddeeva_upper({1.0, 0.0}).imag() ==
          Approx(2.0 / std::sqrt(M_PI) * 0.5380795069127684).epsilon(1e-9));
}

namespace {
// Direct midpoint quadrature of y(t) = w^2/wd int_0^t exp(-z w (t-s)) sin(wd (t-s)) a(s) ds
// (the record, and so the wavelet in it, starts at t = 0).
double brute_response(const Wavelet& w, double f_hz, double zeta, double t) {
    const double om = 2 * M_PI * f_hz, wd = om * std::sqrt(1 - zeta * zeta), h = 2e-5;
    double s = 0.0;
    for (double x = std::max(0.0, w.start_s() - w.gamma_s); x < t; x += h) {
        const double m = x + h / 2;
        s += std::exp(-zeta * om * (t - m)) * std::sin(wd * (t - m)) * w.value(m) * h;
    }
    return om * om / wd * s;
}
}  // namespace

TEST_CASE("closed-form wavelet response equals direct convolution", "[motion][wavelet]") {
    // Tolerance 1e-6 of the peak response: the quadrature error at h = 2e-5 s.
    for (double fw : {0.3, 2.0, 12.0})
        for (double fo : {0.3, 2.0, 12.0, 40.0}) {
            // Centred at 5 s: the 0.3 Hz wavelet (gamma 3.6 s) is cut off at t = 0, the others not.
            const Wavelet w = Wavelet::for_oscillator(fw, std::max(fw, fo), 0.05, 5.0);
            const double scale = std::abs(wavelet_response(w, fw, 0.05, 5.0));
            for (double t : {3.0, 4.9, 5.0, 5.2, 7.0}) {
                INFO("fw " << fw << " fo " << fo << " t " << t);
                CHECK(wavelet_response(w, fo, 0.05, t) ==
                      Approx(brute_response(w, fo, 0.05, t)).margin(1e-6 * scale));
            }
        }
}

namespace {

// The closed form as first written: one cexp per half integral for exp(i Omega T - T^2/gamma^2)
// (wavelet.cpp now takes the -Omega one as the conjugate of the +Omega one) and the start state
// computed inside. Same operations otherwise, so the bits must agree.
std::complex<double> half_integral_ref(double omega_signed, double omega, double zeta,
                                       double omega_d, double gamma, double T) {
    const std::complex<double> i(0.0, 1.0);
    const std::complex<double> p(zeta * omega, -omega_d);
    const std::complex<double> q = p + i * omega_signed;
    const std::complex<double> z = q * (gamma / 2.0) - T / gamma;
    const double scale = gamma * std::sqrt(std::numbers::pi) / 2.0;
    const std::complex<double> tail = std::exp(i * omega_signed * T - T * T / (gamma * gamma));
    if (z.real() >= 0.0) return scale * tail * faddeeva_upper(i * z);
    const std::complex<double> full = std::exp(-p * T + q * q * (gamma * gamma / 4.0));
    return scale * (2.0 * full - tail * faddeeva_upper(-i * z));
}

std::pair<double, double> full_state_ref(const Wavelet& w, double omega, double damping,
                                         double t_s) {
    const double omega_d = omega * std::sqrt(1.0 - damping * damping);
    const double T = t_s - w.centre_s;
    if (T < -4.0 * w.gamma_s) return {0.0, 0.0};
    if (T > 4.0 * w.gamma_s && damping * omega * (T - 4.0 * w.gamma_s) > 20.0) return {0.0, 0.0};
    const std::complex<double> sum =
        half_integral_ref(w.omega_d_radps, omega, damping, omega_d, w.gamma_s, T) +
        half_integral_ref(-w.omega_d_radps, omega, damping, omega_d, w.gamma_s, T);
    const double k = omega * omega / (2.0 * omega_d);
    return {k * sum.imag(), k * (omega_d * sum.real() - damping * omega * sum.imag())};
}

double wavelet_response_ref(const Wavelet& w, double f_hz, double damping, double t_s) {
    const double omega = 2.0 * std::numbers::pi * f_hz;
    const double full = full_state_ref(w, omega, damping, t_s).first;
    if (w.start_s() >= 0.0 || t_s < 0.0) return full;
    const auto [y0, ydot0] = full_state_ref(w, omega, damping, 0.0);
    const double omega_d = omega * std::sqrt(1.0 - damping * damping);
    const double decay = std::exp(-damping * omega * t_s);
    const double free =
        decay * (y0 * std::cos(omega_d * t_s) +
                 (ydot0 + damping * omega * y0) / omega_d * std::sin(omega_d * t_s));
    return full - free;
}

}  // namespace

TEST_CASE(
    "wavelet responses keep their bits: conjugate tails, start state and oscillator given once",
    "[motion][wavelet]") {
    REQUIRE(units::hz_to_radps(1.7) == 2.0 * std::numbers::pi * 1.7);
    std::vector<Wavelet> waves;
    for (double fw : {0.1, 0.3, 2.0, 12.0, 40.0})
        for (double t_peak : {0.0, 0.37, 5.0, 19.9}) {
            waves.push_back(Wavelet::for_oscillator(fw, std::max(fw, 3.0), 0.05, t_peak));
            waves.push_back(Wavelet::at(fw, 0.05, t_peak));
        }
    waves.push_back(Wavelet::pulse(6.0, 1.5));  // omega' = 0: its own conjugate
    waves.push_back(Wavelet::pulse(0.5, 1.5));
    std::size_t compared = 0;
    for (const Wavelet& w : waves)
        for (double fo : {0.1, 0.73, 3.0, 25.0, 50.0}) {
            const WaveletStart start = wavelet_start(w, fo, 0.05);
            // t = centre gives T = 0 exactly; t = 0 the start itself.
            for (double t : {0.0, 0.005, w.centre_s, w.centre_s + 0.01, 2.5, 7.35, 19.995}) {
                const double ref = wavelet_response_ref(w, fo, 0.05, t);
                INFO("wavelet at " << w.centre_s << " s, " << w.frequency_hz << " Hz; f " << fo
                                   << " Hz, t " << t << " s");
                CHECK(wavelet_response(w, fo, 0.05, t) == ref);
                CHECK(wavelet_response(w, fo, 0.05, t, start) == ref);
                CHECK(wavelet_response(w, oscillator_at(fo, 0.05, t), start) == ref);
                compared += ref != 0.0 ? 1 : 0;
            }
        }
    CHECK(compared > 500);
}

TEST_CASE("Faddeeva's batch form gives each argument's bits", "[motion][faddeeva]") {
    // Arguments of the series (|z| < 8) and of the asymptotic form, interleaved, in batches of
    // every remainder of the series' groups of four.
    std::vector<std::complex<double>> z;
    for (double x : {0.0, 0.4, -1.3, 3.0, -6.5, 9.0})
        for (double y : {0.0, 0.2, 1.7, 5.0, 8.5}) z.emplace_back(x, y);
    for (std::size_t n = 0; n <= z.size(); n += (n < 9 ? 1 : 7)) {
        std::vector<std::complex<double>> w(n);
        faddeeva_upper(z.data(), w.data(), n);
        for (std::size_t j = 0; j < n; ++j) {
            INFO(n << " arguments, z = " << z[j]);
            CHECK(w[j].real() == faddeeva_upper(z[j]).real());
            CHECK(w[j].imag() == faddeeva_upper(z[j]).imag());
        }
    }
}

TEST_CASE("wavelet responses and start states in a batch keep each one's bits",
          "[motion][wavelet]") {
    // Wavelets cut off at t = 0 and not, pulses, and times before a wavelet (zero), inside and
    // long after it: more requests than one batch of the closed forms' Faddeeva evaluations.
    std::vector<Wavelet> waves;
    for (double fw : {0.1, 2.0, 40.0})
        for (double t_peak : {0.37, 12.0}) waves.push_back(Wavelet::at(fw, 0.05, t_peak));
    waves.push_back(Wavelet::pulse(6.0, 1.5));
    std::vector<OscillatorAt> at;
    for (double fo : {0.1, 3.0, 50.0})
        for (double t : {0.0, 0.005, 5.0, 19.995}) at.push_back(oscillator_at(fo, 0.05, t));
    std::vector<StartRequest> starts;
    std::vector<WaveletStart> start(waves.size() * at.size());
    for (std::size_t k = 0; k < start.size(); ++k)
        starts.push_back({&waves[k / at.size()], at[k % at.size()].f_hz, 0.05, &start[k]});
    wavelet_starts(starts.data(), starts.size());
    std::vector<ResponseRequest> requests;
    std::vector<double> y(start.size());
    for (std::size_t k = 0; k < start.size(); ++k)
        requests.push_back({&waves[k / at.size()], &at[k % at.size()], &start[k], &y[k]});
    wavelet_responses(requests.data(), requests.size());
    REQUIRE(requests.size() > 64);
    std::size_t nonzero = 0;
    for (std::size_t k = 0; k < requests.size(); ++k) {
        const Wavelet& w = waves[k / at.size()];
        const OscillatorAt& o = at[k % at.size()];
        INFO("wavelet at " << w.centre_s << " s, " << w.frequency_hz << " Hz; f " << o.f_hz
                           << " Hz, t " << o.t_s << " s");
        const WaveletStart ref = wavelet_start(w, o.f_hz, 0.05);
        CHECK(start[k].y == ref.y);
        CHECK(start[k].ydot == ref.ydot);
        CHECK(y[k] == wavelet_response(w, o, ref));
        nonzero += y[k] != 0.0 ? 1 : 0;
    }
    CHECK(nonzero > 40);
}

TEST_CASE("sampling a wavelet with its weighted sums gives the samples and the dot products",
          "[motion][wavelet]") {
    const std::size_t samples = 4001;
    const EndWeights ends = end_weights(samples, 0.005);
    for (const Wavelet& w :
         {Wavelet::at(0.1, 0.05, 3.0), Wavelet::at(2.0, 0.05, 10.0), Wavelet::at(30.0, 0.05, 19.99),
          Wavelet::at(5.0, 0.05, 40.0), Wavelet::pulse(6.7, 1.6)}) {
        const SampledWavelet plain = sample_wavelet(w, 0.005, samples);
        SampledWavelet reused = sample_wavelet(Wavelet::at(0.2, 0.05, 1.0), 0.005, samples);
        const auto [v, d] =
            sample_wavelet(w, 0.005, samples, reused, ends.velocity, ends.displacement);
        double v_ref = 0.0, d_ref = 0.0;
        for (std::size_t k = 0; k < plain.values.size(); ++k) {
            v_ref += ends.velocity[plain.first + k] * plain.values[k];
            d_ref += ends.displacement[plain.first + k] * plain.values[k];
        }
        INFO("wavelet at " << w.centre_s << " s");
        CHECK(reused.first == plain.first);
        CHECK(reused.values == plain.values);
        CHECK(v == v_ref);
        CHECK(d == d_ref);
    }
}

TEST_CASE("wavelets sampled together keep each one's samples and sums", "[motion][wavelet]") {
    // Lengths from the whole record to a few samples, one wavelet outside the record, and
    // counts leaving every remainder of the groups sampled side by side.
    const std::size_t samples = 4001;
    const EndWeights ends = end_weights(samples, 0.005);
    std::vector<Wavelet> waves;
    for (double f : {0.1, 30.0, 2.0, 0.1, 8.0, 45.0, 0.7})
        waves.push_back(Wavelet::at(f, 0.05, 9.5 + f / 10.0));
    waves.push_back(Wavelet::at(5.0, 0.05, 40.0));
    waves.push_back(Wavelet::pulse(6.7, 1.6));
    for (std::size_t n = 0; n <= waves.size(); ++n) {
        std::vector<SampledWavelet> out(n);
        std::vector<double> v(n, -1.0), d(n, -1.0);
        std::vector<SampleRequest> r;
        for (std::size_t j = 0; j < n; ++j) r.push_back({&waves[j], &out[j], &v[j], &d[j]});
        sample_wavelets(r.data(), n, 0.005, samples, ends.velocity, ends.displacement);
        for (std::size_t j = 0; j < n; ++j) {
            SampledWavelet one;
            const auto [v1, d1] =
                sample_wavelet(waves[j], 0.005, samples, one, ends.velocity, ends.displacement);
            INFO(n << " wavelets, the one at " << waves[j].centre_s << " s");
            CHECK(out[j].first == one.first);
            CHECK(out[j].values == one.values);
            CHECK(v[j] == v1);
            CHECK(d[j] == d1);
        }
    }
}

TEST_CASE("own wavelet peaks at its peak time, its drift is the closed-form residual",
          "[motion][wavelet]") {
    for (double f : {0.5, 2.0, 10.0}) {
        const Wavelet w = Wavelet::at(f, 0.05, 10.0);
        const double at_peak = wavelet_response(w, f, 0.05, 10.0);
        // AA2010: the shift puts the oscillator's peak at t_peak, within a few % of a period.
        double best = 0.0, best_t = 0.0;
        for (double t = 10.0 - 0.3 / f; t <= 10.0 + 0.3 / f; t += 0.002 / f) {
            const double y = std::abs(wavelet_response(w, f, 0.05, t));
            if (y > best) {
                best = y;
                best_t = t;
            }
        }
        CHECK(std::abs(best_t - 10.0) * f < 0.06);
        CHECK(at_peak > 0.98 * best);
        // Velocity and displacement at the end of a 20 s record holding the whole wavelet.
        core::Record r;
        r.dt_s = 0.005;
        r.accel_mps2.assign(4001 + static_cast<std::size_t>(8.0 * w.gamma_s / 0.005), 0.0);
        add_wavelet(w, 1.0, r.dt_s, r.accel_mps2);
        const core::GroundMotion gm = core::measure(r);
        // int cos(W x) exp(-x^2/g^2) dx = g sqrt(pi) exp(-(W g / 2)^2); the displacement at the end
        // is (T - centre) times that. 2% covers sampling and the +-4 gamma truncation.
        const double v_ref =
            w.gamma_s * std::sqrt(M_PI) * std::exp(-std::pow(w.omega_d_radps * w.gamma_s / 2, 2));
        INFO("f " << f << " pgv " << gm.pgv_mps);
        // At 2 and 10 Hz the residual (< 3e-7) is of the size of the trapezoidal sampling error.
        if (f < 1.0) {
            CHECK(gm.final_velocity_mps == Approx(v_ref).epsilon(0.02));
            CHECK(gm.final_displacement_m ==
                  Approx(v_ref * (r.duration_s() - w.centre_s)).epsilon(0.02));
        }
        CHECK(std::abs(gm.final_velocity_mps) < 1e-4 * gm.pgv_mps);
    }
}

TEST_CASE("end weights reproduce the trapezoidal final velocity and displacement",
          "[motion][baseline]") {
    core::Record r;
    r.dt_s = 0.01;
    std::mt19937_64 rng(7);
    for (int i = 0; i < 1001; ++i) r.accel_mps2.push_back(core::uniform01(rng()) - 0.5);
    const EndWeights w = end_weights(r.size(), r.dt_s);
    double v = 0.0, d = 0.0;
    for (std::size_t i = 0; i < r.size(); ++i) {
        v += w.velocity[i] * r.accel_mps2[i];
        d += w.displacement[i] * r.accel_mps2[i];
    }
    const core::GroundMotion gm = core::measure(r);
    CHECK(v == Approx(gm.final_velocity_mps).epsilon(1e-12));
    CHECK(d == Approx(gm.final_displacement_m).epsilon(1e-10));
}

TEST_CASE("portable uniform transform and seed derivation", "[motion][rng]") {
    CHECK(core::uniform01(0) == 0.0);
    CHECK(core::uniform01(~0ull) == Approx(1.0 - 0x1.0p-53).epsilon(0));
    CHECK(core::uniform01(~0ull) < 1.0);
    // mt19937_64's 10000th output from the default seed is fixed by the standard (C++
    // [rand.predef]).
    std::mt19937_64 g;
    g.discard(9999);
    CHECK(g() == 9981545732273789042ull);
    CHECK(core::component_seed(1, 0, 0) != core::component_seed(1, 1, 0));
    CHECK(core::component_seed(1, 0, 0) != core::component_seed(1, 0, 1));
    CHECK(core::component_seed(1, 2, 3) == core::component_seed(1, 2, 3));
}

TEST_CASE("envelope: quadratic rise, flat strong part, exponential decay to end level",
          "[motion][envelope]") {
    const Envelope e{};  // 2 s rise, 10 s strong, 0.05 at the end
    CHECK(envelope_at(e, 0.0, 20.0) == 0.0);
    CHECK(envelope_at(e, 1.0, 20.0) == Approx(0.25));
    CHECK(envelope_at(e, 7.0, 20.0) == 1.0);
    CHECK(envelope_at(e, 20.0, 20.0) == Approx(0.05));
    CHECK(envelope_at(e, 16.0, 20.0) == Approx(std::sqrt(0.05)));
}

TEST_CASE("check band follows Nyquist and SRP point density", "[motion][criteria]") {
    CHECK(criteria::band_high_for(0.005) == 50.0);
    CHECK(criteria::band_high_for(0.02) == 25.0);
    const auto f = criteria::check_frequencies(0.005);
    CHECK(f.front() == 0.1);
    CHECK(f.back() == 50.0);
    CHECK(static_cast<double>(f.size() - 1) >= 100.0 * std::log10(500.0) - 1e-9);
}

TEST_CASE("record PSD: white noise gives sigma^2 dt / pi per rad/s", "[motion][psd]") {
    // One-sided per rad/s: integral over omega in (0, pi/dt) of s^2 dt / pi = s^2 (Parseval).
    // Box-Muller normals from the portable uniform; tolerance 10% (band average of ~1e3 bins).
    core::Record r;
    r.dt_s = 0.01;
    std::mt19937_64 g(11);
    const double sigma = 2.0;
    for (int i = 0; i < 65536; ++i) {
        const double u1 = 1.0 - core::uniform01(g()), u2 = core::uniform01(g());
        r.accel_mps2.push_back(sigma * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2));
    }
    const std::vector<double> f{0.5, 2.0, 10.0, 30.0};
    const auto s = averaged_psd_per_radps(r, r.duration_s(), f);
    for (std::size_t i = 0; i < f.size(); ++i) {
        INFO("f " << f[i]);
        CHECK(s[i] == Approx(sigma * sigma * r.dt_s / M_PI).epsilon(0.10));
    }
}

}  // namespace freestand_test_motion_test_wavelet
