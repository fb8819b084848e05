#include "spectra/response.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "core/contract.hpp"
#include "core/errors.hpp"
#include "core/limits.hpp"
#include "core/units.hpp"

namespace freestand::spectra {

namespace {

using Row = std::array<double, 4>;  // coefficients of (u_i, v_i, a_i, a_{i+1})

/// Exact one-sample map of an oscillator u'' + 2 zeta w u' + w^2 u = -a(t), a piecewise linear
/// (Nigam & Jennings 1969), resolved at n equal sub-points of each sample interval. Row k of
/// sub_u gives u at sub-point k+1; end_v gives v at the end of the interval.
struct Stepper {
    double omega_radps = 0.0;
    std::vector<Row> sub_u;
    Row end_v{};
};

/// 2x2 free-vibration propagator over h and the 2x2 load matrix (columns: a at start and end of
/// the step). Derived from the particular solution of the linear load, u_p = p0 + p1 t with
/// p1 = -(a1 - a0) / (h w^2), p0 = -(a0 + 2 zeta w p1) / w^2, plus free vibration from
/// (u - p0, v - p1); this is algebraically the Nigam-Jennings coefficient set.
struct StepMatrices {
    double a11, a12, a21, a22;
    double b11, b12, b21, b22;
};

StepMatrices step_matrices(double omega, double zeta, double h) {
    const double wd = omega * std::sqrt(1.0 - zeta * zeta);
    const double e = std::exp(-zeta * omega * h);
    const double c = std::cos(wd * h);
    const double s = std::sin(wd * h);
    StepMatrices m{};
    m.a11 = e * (c + zeta * omega / wd * s);
    m.a12 = e * s / wd;
    m.a21 = -e * omega * omega / wd * s;
    m.a22 = e * (c - zeta * omega / wd * s);
    const double w2 = omega * omega;
    // d(p0, p1)/d(a0) and d(p0, p1)/d(a1).
    const double dp1_da0 = 1.0 / (h * w2);
    const double dp0_da0 = -1.0 / w2 - 2.0 * zeta / (h * w2 * omega);
    const double dp1_da1 = -dp1_da0;
    const double dp0_da1 = 2.0 * zeta / (h * w2 * omega);
    m.b11 = (1.0 - m.a11) * dp0_da0 + (h - m.a12) * dp1_da0;
    m.b12 = (1.0 - m.a11) * dp0_da1 + (h - m.a12) * dp1_da1;
    m.b21 = -m.a21 * dp0_da0 + (1.0 - m.a22) * dp1_da0;
    m.b22 = -m.a21 * dp0_da1 + (1.0 - m.a22) * dp1_da1;
    return m;
}

int substeps(double f_hz, double dt_s, int min_steps_per_period) {
    if (min_steps_per_period <= 0) return 1;
    // Step h = dt / n <= T / m  <=>  n >= dt m f.
    const double need = dt_s * static_cast<double>(min_steps_per_period) * f_hz;
    return std::max(1, static_cast<int>(std::ceil(need - 1e-12)));
}

Stepper make_stepper(double f_hz, double zeta, double dt_s, int min_steps_per_period) {
    const int n = substeps(f_hz, dt_s, min_steps_per_period);
    const double omega = units::hz_to_radps(f_hz);
    const StepMatrices m = step_matrices(omega, zeta, dt_s / static_cast<double>(n));
    Stepper st;
    st.omega_radps = omega;
    st.sub_u.resize(static_cast<std::size_t>(n));
    // Compose the sub-steps symbolically: the state at sub-point k is a linear map of
    // (u_i, v_i, a_i, a_{i+1}); the load at sub-point k is a_i + (k/n)(a_{i+1} - a_i).
    Row u{1.0, 0.0, 0.0, 0.0};
    Row v{0.0, 1.0, 0.0, 0.0};
    for (int k = 1; k <= n; ++k) {
        const double r0 = static_cast<double>(k - 1) / static_cast<double>(n);
        const double r1 = static_cast<double>(k) / static_cast<double>(n);
        Row nu{}, nv{};
        for (std::size_t j = 0; j < 4; ++j) {
            nu[j] = m.a11 * u[j] + m.a12 * v[j];
            nv[j] = m.a21 * u[j] + m.a22 * v[j];
        }
        nu[2] += m.b11 * (1.0 - r0) + m.b12 * (1.0 - r1);
        nu[3] += m.b11 * r0 + m.b12 * r1;
        nv[2] += m.b21 * (1.0 - r0) + m.b22 * (1.0 - r1);
        nv[3] += m.b21 * r0 + m.b22 * r1;
        u = nu;
        v = nv;
        st.sub_u[static_cast<std::size_t>(k - 1)] = u;
    }
    st.end_v = v;
    return st;
}

/// Two oscillators side by side (GCC/Clang vector extension: one SSE2/NEON register, and the
/// compiler falls back to scalar code on targets without one).
using Pair = double __attribute__((vector_size(16)));

inline Pair pair_max(Pair x, Pair y) { return x > y ? x : y; }
inline Pair pair_abs(Pair x) { return x < 0.0 ? -x : x; }

/// Peak of one oscillator: max |u|, the signed u there, and the index of the first sub-point
/// reaching it, counted from the first sample (time = index * dt / n).
struct Peak {
    double abs_m = 0.0;
    double signed_m = 0.0;
    double index = 0.0;
};

/// Running peak of a pair of oscillators. With Track, also the signed value and the sub-point
/// index of the first maximum (strict >, as a scalar loop would keep it).
template <bool Track>
struct PairPeak {
    Pair abs_m{}, signed_m{}, index{};
    void update(Pair un, double at) {
        const Pair m = pair_abs(un);
        if constexpr (Track) {
            const auto larger = m > abs_m;
            signed_m = larger ? un : signed_m;
            index = larger ? Pair{at, at} : index;
        }
        abs_m = pair_max(abs_m, m);
    }
};

/// Peaks over the record, from rest, of 2P oscillators with the same number of sub-steps n,
/// advanced in lockstep. The recurrences are independent, so one oscillator's latency chain
/// (u -> u_next, three dependent flops per sample) overlaps the others'.
template <std::size_t P, bool Track>
void run_batch(const Stepper* const* st, const std::vector<double>& a, Peak* peak) {
    const std::size_t n = st[0]->sub_u.size();
    // Coefficients packed per pair: cu[(k * 4 + j) * P + p] holds coefficient j of sub-point k
    // for oscillators 2p and 2p+1; cv[j * P + p] likewise for v at the end of the sample.
    std::vector<Pair> cu(n * 4 * P);
    std::array<Pair, 4 * P> cv{};
    for (std::size_t p = 0; p < P; ++p) {
        const Stepper& s0 = *st[2 * p];
        const Stepper& s1 = *st[2 * p + 1];
        for (std::size_t k = 0; k < n; ++k)
            for (std::size_t j = 0; j < 4; ++j)
                cu[(k * 4 + j) * P + p] = Pair{s0.sub_u[k][j], s1.sub_u[k][j]};
        for (std::size_t j = 0; j < 4; ++j) cv[j * P + p] = Pair{s0.end_v[j], s1.end_v[j]};
    }
    std::array<Pair, P> u{}, v{};
    std::array<PairPeak<Track>, P> pk{};
    const std::size_t count = a.size();
    if (n == 1) {
        // T >= 20 dt: the common case, free of the sub-point loop so everything stays in registers.
        std::array<Pair, 4 * P> c1{};
        for (std::size_t j = 0; j < 4 * P; ++j) c1[j] = cu[j];
        for (std::size_t i = 1; i < count; ++i) {
            const Pair a0{a[i - 1], a[i - 1]};
            const Pair a1{a[i], a[i]};
            for (std::size_t p = 0; p < P; ++p) {
                const Pair un =
                    (c1[p] * u[p] + c1[P + p] * v[p]) + (c1[2 * P + p] * a0 + c1[3 * P + p] * a1);
                v[p] =
                    (cv[p] * u[p] + cv[P + p] * v[p]) + (cv[2 * P + p] * a0 + cv[3 * P + p] * a1);
                u[p] = un;
                pk[p].update(un, static_cast<double>(i));
            }
        }
    } else {
        const Pair* c = cu.data();
        for (std::size_t i = 1; i < count; ++i) {
            const Pair a0{a[i - 1], a[i - 1]};
            const Pair a1{a[i], a[i]};
            std::array<Pair, P> un{};
            for (std::size_t k = 0; k < n; ++k) {
                const Pair* r = c + k * 4 * P;
                const double at = static_cast<double>((i - 1) * n + k + 1);
                for (std::size_t p = 0; p < P; ++p) {
                    un[p] =
                        (r[p] * u[p] + r[P + p] * v[p]) + (r[2 * P + p] * a0 + r[3 * P + p] * a1);
                    pk[p].update(un[p], at);
                }
            }
            for (std::size_t p = 0; p < P; ++p) {
                v[p] =
                    (cv[p] * u[p] + cv[P + p] * v[p]) + (cv[2 * P + p] * a0 + cv[3 * P + p] * a1);
                u[p] = un[p];
            }
        }
    }
    for (std::size_t p = 0; p < P; ++p) {
        for (std::size_t lane = 0; lane < 2; ++lane)
            peak[2 * p + lane] = Peak{pk[p].abs_m[lane], pk[p].signed_m[lane], pk[p].index[lane]};
    }
}

/// Peaks of every stepper: sorts them by sub-step count and runs batches of up to 8 equal
/// counts together; a batch with an odd count repeats its last oscillator (result dropped).
template <bool Track>
std::vector<Peak> peaks_of(const std::vector<Stepper>& steppers, const std::vector<double>& a) {
    std::vector<std::size_t> order(steppers.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
        return steppers[x].sub_u.size() < steppers[y].sub_u.size();
    });
    std::vector<Peak> peaks(steppers.size());
    constexpr std::size_t batch = 8;
    std::size_t i = 0;
    while (i < order.size()) {
        std::size_t len = 1;
        while (len < batch && i + len < order.size() &&
               steppers[order[i + len]].sub_u.size() == steppers[order[i]].sub_u.size())
            ++len;
        std::array<const Stepper*, batch> group{};
        for (std::size_t o = 0; o < batch; ++o)
            group[o] = &steppers[order[i + std::min(o, len - 1)]];
        std::array<Peak, batch> out{};
        switch ((len + 1) / 2) {
            case 4:
                run_batch<4, Track>(group.data(), a, out.data());
                break;
            case 3:
                run_batch<3, Track>(group.data(), a, out.data());
                break;
            case 2:
                run_batch<2, Track>(group.data(), a, out.data());
                break;
            default:
                run_batch<1, Track>(group.data(), a, out.data());
                break;
        }
        for (std::size_t o = 0; o < len; ++o) peaks[order[i + o]] = out[o];
        i += len;
    }
    return peaks;
}

void check_inputs(const core::Record& record, const std::vector<double>& dampings,
                  const std::vector<double>& frequency_hz) {
    core::validate(record);
    if (record.accel_mps2.size() < 2)
        throw InputError(SourceLocation{record.source, 0, "samples"},
                         fmt::format("record \"{}\" has {} sample; expected at least 2 (one time "
                                     "step) for a response",
                                     record.name, record.accel_mps2.size()));
    if (dampings.empty())
        throw InputError(SourceLocation{"", 0, "damping"},
                         "no damping given; expected at least one");
    for (double z : dampings)
        require_in_range(z, 0.0, 1.0, SourceLocation{"", 0, "damping"}, true, false);
    if (frequency_hz.empty())
        throw InputError(SourceLocation{"", 0, "frequency_hz"},
                         "no frequency given; expected at least one");
    core::limits::require_within(static_cast<double>(frequency_hz.size()),
                                 core::limits::max_frequencies,
                                 SourceLocation{"", 0, "frequency_hz"}, "the spectrum's frequencies");
    for (double f : frequency_hz) {
        require_positive(f, SourceLocation{"", 0, "frequency_hz"});
        core::limits::require_within(f, core::limits::max_frequency_hz,
                                     SourceLocation{"", 0, "frequency_hz"},
                                     "a response-spectrum frequency (Hz)");
        core::limits::require_at_least(f, core::limits::min_frequency_hz,
                                       SourceLocation{"", 0, "frequency_hz"},
                                       "a response-spectrum frequency (Hz)");
    }
}

/// Validated inputs, then one stepper per (damping, frequency), damping-major.
std::vector<Stepper> steppers_for(const core::Record& record, const std::vector<double>& dampings,
                                  const std::vector<double>& frequency_hz,
                                  int min_steps_per_period) {
    check_inputs(record, dampings, frequency_hz);
    FREESTAND_EXPECT(min_steps_per_period >= 0, "0 (one step per sample) or more sub-steps per period");
    std::vector<Stepper> steppers;
    steppers.reserve(dampings.size() * frequency_hz.size());
    for (double zeta : dampings)
        for (double f : frequency_hz)
            steppers.push_back(make_stepper(f, zeta, record.dt_s, min_steps_per_period));
    return steppers;
}

}  // namespace

Spectrum ResponseSpectra::spectrum(std::size_t damping_index) const {
    if (damping_index >= dampings.size())
        throw InputError(SourceLocation{"", 0, "damping_index"},
                         fmt::format("damping index {} out of range; {} dampings computed",
                                     damping_index, dampings.size()));
    for (std::size_t i = 1; i < frequency_hz.size(); ++i) {
        if (!(frequency_hz[i] > frequency_hz[i - 1]))
            throw InputError(
                SourceLocation{"", 0, "frequency_hz"},
                "frequencies are not strictly increasing; a Spectrum needs them sorted");
    }
    Spectrum s;
    s.damping = dampings[damping_index];
    s.frequency_hz = frequency_hz;
    s.psa_g = psa_g[damping_index];
    return s;
}

ResponseSpectra response_spectra(const core::Record& record, const std::vector<double>& dampings,
                                 const std::vector<double>& frequency_hz,
                                 const ResponseOptions& options) {
    const std::vector<Stepper> steppers =
        steppers_for(record, dampings, frequency_hz, options.min_steps_per_period);
    ResponseSpectra out;
    out.frequency_hz = frequency_hz;
    out.dampings = dampings;
    const std::size_t nf = frequency_hz.size();
    out.psa_g.assign(dampings.size(), std::vector<double>(nf));
    out.sd_m.assign(dampings.size(), std::vector<double>(nf));
    out.psv_mps.assign(dampings.size(), std::vector<double>(nf));
    const std::vector<Peak> peaks = peaks_of<false>(steppers, record.accel_mps2);
    for (std::size_t d = 0; d < dampings.size(); ++d) {
        for (std::size_t i = 0; i < nf; ++i) {
            const double sd = peaks[d * nf + i].abs_m;
            const double w = steppers[d * nf + i].omega_radps;
            out.sd_m[d][i] = sd;
            out.psv_mps[d][i] = w * sd;
            out.psa_g[d][i] = w * w * sd / units::g_mps2;
        }
    }
    return out;
}

ResponseSpectra response_spectra(const core::Record& record, const std::vector<double>& dampings,
                                 const std::vector<double>& frequency_hz) {
    return response_spectra(record, dampings, frequency_hz, ResponseOptions{});
}

std::vector<double> psa_g(const core::Record& record, double damping,
                          const std::vector<double>& frequency_hz) {
    const std::vector<Stepper> steppers =
        steppers_for(record, {damping}, frequency_hz, ResponseOptions{}.min_steps_per_period);
    const std::vector<Peak> peaks = peaks_of<false>(steppers, record.accel_mps2);
    std::vector<double> out(peaks.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
        const double w = steppers[i].omega_radps;
        out[i] = w * w * peaks[i].abs_m / units::g_mps2;
    }
    return out;
}

std::vector<OscillatorPeak> peak_responses(const core::Record& record, double damping,
                                           const std::vector<double>& frequency_hz) {
    const std::vector<Stepper> steppers =
        steppers_for(record, {damping}, frequency_hz, ResponseOptions{}.min_steps_per_period);
    const std::vector<Peak> peaks = peaks_of<true>(steppers, record.accel_mps2);
    std::vector<OscillatorPeak> out(peaks.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
        const double h = record.dt_s / static_cast<double>(steppers[i].sub_u.size());
        out[i] = OscillatorPeak{peaks[i].signed_m, peaks[i].index * h};
    }
    return out;
}

}  // namespace freestand::spectra
