// Random-phase stationary process shaped by an envelope and iterated on the spectral ratio in
// the frequency domain (Gasparini & Vanmarcke 1976, SIMQKE): phases fixed, Fourier amplitudes of
// the stationary process multiplied by target / computed PSA, envelope re-applied each pass.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <random>

#include "core/errors.hpp"
#include "core/units.hpp"
#include "motion/criteria.hpp"
#include "motion/fft.hpp"
#include "motion/internal.hpp"
#include "spectra/response.hpp"

namespace freestand::motion {

double uniform01(std::uint64_t draw) { return static_cast<double>(draw >> 11) * 0x1.0p-53; }

std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t component, std::uint64_t attempt) {
    std::uint64_t z =
        seed ^ (component * 0x9E3779B97F4A7C15ull) ^ (attempt * 0xD1B54A32D192ED03ull);
    z += 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

double envelope_at(const Envelope& e, double t_s, double duration_s) {
    if (t_s <= 0.0) return 0.0;
    if (t_s < e.rise_s) return (t_s / e.rise_s) * (t_s / e.rise_s);
    const double decay_start = e.rise_s + e.strong_s;
    if (t_s <= decay_start) return 1.0;
    const double decay_len = duration_s - decay_start;
    if (decay_len <= 0.0) return 1.0;
    return std::exp(std::log(e.end_level) * (t_s - decay_start) / decay_len);
}

namespace {

constexpr int kPasses = 8;        // SIMQKE passes; wavelet matching finishes the job
constexpr int kPerDecade = 20;    // ratio sampled at these frequencies
constexpr double kMaxStep = 3.0;  // a single pass changes an amplitude by at most this factor

void validate_envelope(const Envelope& e, double duration_s) {
    require_positive(e.rise_s, SourceLocation{"", 0, "envelope rise_s"});
    require_positive(e.strong_s, SourceLocation{"", 0, "envelope strong_s"});
    require_in_range(e.end_level, 0.0, 1.0, SourceLocation{"", 0, "envelope end_level"}, false,
                     true);
    if (e.rise_s + e.strong_s > duration_s)
        throw InputError(SourceLocation{"", 0, "envelope"},
                         fmt::format("rise {} s + strong part {} s exceed the duration {} s",
                                     e.rise_s, e.strong_s, duration_s));
}

// Log-frequency linear interpolation of ratio samples, constant beyond the ends.
double interp_log(const std::vector<double>& f, const std::vector<double>& r, double x) {
    if (x <= f.front()) return r.front();
    if (x >= f.back()) return r.back();
    const auto hi = static_cast<std::size_t>(std::upper_bound(f.begin(), f.end(), x) - f.begin());
    const double t = std::log(x / f[hi - 1]) / std::log(f[hi] / f[hi - 1]);
    return r[hi - 1] + t * (r[hi] - r[hi - 1]);
}

}  // namespace

core::Record synthesize(const Target& target, double duration_s, double dt_s, std::uint64_t seed,
                        const Envelope& envelope) {
    validate_target(target.psa_5pct, 0.05);
    validate_envelope(envelope, duration_s);
    const auto n = static_cast<std::size_t>(std::llround(duration_s / dt_s)) + 1;
    const std::size_t nfft = fft_size(n);
    RealFft fft(nfft);
    const double df = 1.0 / (static_cast<double>(nfft) * dt_s);

    // Starting amplitudes from random vibration: G(omega) ~ PSA^2 / omega, so |X| ~ PSA / sqrt(f).
    std::mt19937_64 rng(seed);
    std::vector<std::complex<double>> unit(fft.bins());
    std::vector<double> amp(fft.bins(), 0.0);
    for (std::size_t k = 1; k < fft.bins(); ++k) {
        const double phase = units::two_pi * uniform01(rng());
        unit[k] = std::polar(1.0, phase);
        const double fk = static_cast<double>(k) * df;
        amp[k] = fk < 0.05 ? 0.0 : target.psa_5pct.psa_at(fk) / std::sqrt(fk);
    }
    std::vector<double> env(n);
    for (std::size_t i = 0; i < n; ++i)
        env[i] = envelope_at(envelope, static_cast<double>(i) * dt_s, duration_s);

    core::Record rec;
    rec.dt_s = dt_s;
    rec.accel_mps2.resize(n);
    auto build = [&] {
        std::vector<std::complex<double>> spec(fft.bins());
        for (std::size_t k = 0; k < spec.size(); ++k) spec[k] = amp[k] * unit[k];
        const std::vector<double> x = fft.inverse(spec);
        for (std::size_t i = 0; i < n; ++i) rec.accel_mps2[i] = env[i] * x[i];
    };
    const std::vector<double> f =
        spectra::log_frequencies(criteria::band_low_hz, criteria::band_high_for(dt_s), kPerDecade);
    std::vector<double> target_psa;
    for (double fi : f) target_psa.push_back(target.psa_5pct.psa_at(fi));
    for (int pass = 0; pass < kPasses; ++pass) {
        build();
        const std::vector<double> psa = spectra::psa_g(rec, 0.05, f);
        if (pass == 0) {
            // The starting level is arbitrary: fix it first with one geometric-mean factor.
            double log_sum = 0.0;
            for (std::size_t i = 0; i < f.size(); ++i) log_sum += std::log(target_psa[i] / psa[i]);
            const double scale = std::exp(log_sum / static_cast<double>(f.size()));
            for (double& a : amp) a *= scale;
            continue;
        }
        std::vector<double> r(f.size());
        for (std::size_t i = 0; i < f.size(); ++i)
            r[i] = std::clamp(target_psa[i] / std::max(psa[i], 1e-300), 1.0 / kMaxStep, kMaxStep);
        for (std::size_t k = 1; k < amp.size(); ++k)
            amp[k] *= interp_log(f, r, static_cast<double>(k) * df);
    }
    build();
    return rec;
}

}  // namespace freestand::motion
