#include "motion/wavelet.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>

#include "core/units.hpp"
#include "motion/faddeeva.hpp"

namespace freestand::motion {
namespace {

constexpr double kSupportGammas = 4.0;  // exp(-16) ~ 1e-7
constexpr double kDecayed = 20.0;       // exp(-20) ~ 2e-9

// I(Omega) = int_{-inf}^{T} exp(-p (T - x)) exp(i Omega x) exp(-x^2 / gamma^2) dx, x = s - centre,
// p = zeta omega - i omega_d. Completing the square with q = p + i Omega:
//   I = gamma sqrt(pi) / 2 * exp(-p T + q^2 gamma^2 / 4) erfc(z),  z = q gamma / 2 - T / gamma.
// With erfc(z) = exp(-z^2) w(i z) the exponent simplifies to i Omega T - T^2 / gamma^2 (`tail`,
// below), which stays bounded; for Re z < 0 (late times) erfc(z) = 2 - exp(-z^2) w(-i z) keeps
// w's argument in the upper half plane. Split around its Faddeeva evaluation (`arg`), so that
// the evaluations of many integrals run as one batch (faddeeva.hpp).
struct HalfIntegral {
    std::complex<double> arg;   // i z, or -i z when late
    std::complex<double> full;  // exp(-p T + q^2 gamma^2 / 4), when late
    std::complex<double> tail;
    double scale = 0.0;
    bool late = false;  // Re z < 0
};

HalfIntegral half_integral(double omega_signed, double omega, double zeta, double omega_d,
                           double gamma, double T, std::complex<double> tail) {
    const std::complex<double> i(0.0, 1.0);
    const std::complex<double> p(zeta * omega, -omega_d);
    const std::complex<double> q = p + i * omega_signed;
    const std::complex<double> z = q * (gamma / 2.0) - T / gamma;
    HalfIntegral h;
    h.scale = gamma * std::sqrt(std::numbers::pi) / 2.0;
    h.tail = tail;
    h.late = !(z.real() >= 0.0);
    if (!h.late) {
        h.arg = i * z;
        return h;
    }
    h.full = std::exp(-p * T + q * q * (gamma * gamma / 4.0));
    h.arg = -i * z;
    return h;
}

// The integral given w(arg).
std::complex<double> integral(const HalfIntegral& h, std::complex<double> w) {
    if (!h.late) return h.scale * h.tail * w;
    return h.scale * (2.0 * h.full - h.tail * w);
}

// exp(i Omega T - T^2 / gamma^2) of half_integral. That of -Omega is its conjugate, bit for bit:
// the argument's imaginary part is exactly negated and its real part is -T^2 / gamma^2 either
// way (a zero of either sign at T = 0, where exp gives 1), and cexp(conj z) = conj(cexp z)
// (C11 Annex G.6.3.1; glibc's sin is odd and cos even to the bit).
std::complex<double> tail_of(double omega_signed, double gamma, double T) {
    const std::complex<double> i(0.0, 1.0);
    return std::exp(i * omega_signed * T - T * T / (gamma * gamma));
}

}  // namespace

Wavelet Wavelet::at(double frequency_hz, double damping, double t_peak_s) {
    Wavelet w;
    w.frequency_hz = frequency_hz;
    w.damping = damping;
    const double root = std::sqrt(1.0 - damping * damping);
    w.omega_d_radps = units::hz_to_radps(frequency_hz) * root;
    w.gamma_s = 1.178 * std::pow(frequency_hz, -0.93);                 // AA2010 eq. 17
    const double shift = std::atan(root / damping) / w.omega_d_radps;  // AA2010 eq. 14
    w.centre_s = t_peak_s - shift;
    return w;
}

Wavelet Wavelet::for_oscillator(double frequency_hz, double oscillator_hz, double damping,
                                double t_peak_s) {
    Wavelet w = at(frequency_hz, damping, t_peak_s);
    if (oscillator_hz <= frequency_hz) return w;
    const double r = frequency_hz / oscillator_hz;
    w.centre_s = t_peak_s - std::atan2(2.0 * damping * r, 1.0 - r * r) / w.omega_d_radps;
    return w;
}

Wavelet Wavelet::pulse(double centre_s, double gamma_s) {
    Wavelet w;
    w.gamma_s = gamma_s;
    w.centre_s = centre_s;
    return w;
}

double Wavelet::value(double t_s) const {
    const double x = t_s - centre_s;
    const double g = x / gamma_s;
    return std::cos(omega_d_radps * x) * std::exp(-g * g);
}

double Wavelet::start_s() const { return centre_s - kSupportGammas * gamma_s; }
double Wavelet::end_s() const { return centre_s + kSupportGammas * gamma_s; }

namespace {

struct State {
    double y = 0.0;     // pseudo-acceleration -omega^2 u
    double ydot = 0.0;  // its time derivative
};

// The oscillator (omega, damping) at t_s driven by the whole wavelet w.
struct FullStateArgs {
    const Wavelet* w = nullptr;
    double omega = 0.0, damping = 0.0, t_s = 0.0;
};

// full_state up to its two Faddeeva evaluations: nothing (zero) before the wavelet and once its
// free vibration has decayed, else the integrals of +Omega' and -Omega'.
struct FullStatePlan {
    bool zero = true;
    double omega = 0.0, damping = 0.0, omega_d = 0.0;
    std::array<HalfIntegral, 2> half;
};

// y and dy/dt of the oscillator driven by the whole (untruncated) wavelet. With
// S = I(Omega') + I(-Omega'): y = k Im S and dy/dt = k (omega_d Re S - zeta omega Im S),
// k = omega^2 / (2 omega_d) (differentiate exp(-zeta w tau) sin(w_d tau) under the integral).
FullStatePlan plan_full_state(const FullStateArgs& a) {
    const Wavelet& w = *a.w;
    FullStatePlan plan;
    plan.omega = a.omega;
    plan.damping = a.damping;
    plan.omega_d = a.omega * std::sqrt(1.0 - a.damping * a.damping);
    const double T = a.t_s - w.centre_s;
    if (T < -kSupportGammas * w.gamma_s) return plan;
    // Long after the wavelet the free vibration has decayed below exp(-kDecayed) of its size.
    if (T > kSupportGammas * w.gamma_s &&
        a.damping * a.omega * (T - kSupportGammas * w.gamma_s) > kDecayed)
        return plan;
    plan.zero = false;
    // cos(Omega x) = Re exp(i Omega x) and Im(A) Re(B) = Im(A B + A conj(B)) / 2.
    const std::complex<double> tail = tail_of(w.omega_d_radps, w.gamma_s, T);
    plan.half[0] =
        half_integral(w.omega_d_radps, a.omega, a.damping, plan.omega_d, w.gamma_s, T, tail);
    plan.half[1] = half_integral(-w.omega_d_radps, a.omega, a.damping, plan.omega_d, w.gamma_s, T,
                                 std::conj(tail));
    return plan;
}

State full_state(const FullStatePlan& plan, std::complex<double> w_plus,
                 std::complex<double> w_minus) {
    if (plan.zero) return {};
    const std::complex<double> sum =
        integral(plan.half[0], w_plus) + integral(plan.half[1], w_minus);
    const double k = plan.omega * plan.omega / (2.0 * plan.omega_d);
    return {k * sum.imag(),
            k * (plan.omega_d * sum.real() - plan.damping * plan.omega * sum.imag())};
}

// done(j, full_state(args_of(j))) for j < n, the Faddeeva evaluations of up to kBatch states at
// once.
template <class ArgsOf, class Done>
void full_states(std::size_t n, const ArgsOf& args_of, const Done& done) {
    constexpr std::size_t kBatch = 32;
    std::array<FullStatePlan, kBatch> plans;
    std::array<std::complex<double>, 2 * kBatch> z, w;
    for (std::size_t j0 = 0; j0 < n; j0 += kBatch) {
        const std::size_t count = std::min(kBatch, n - j0);
        std::size_t used = 0;
        for (std::size_t k = 0; k < count; ++k) {
            plans[k] = plan_full_state(args_of(j0 + k));
            if (plans[k].zero) continue;
            z[used++] = plans[k].half[0].arg;
            z[used++] = plans[k].half[1].arg;
        }
        faddeeva_upper(z.data(), w.data(), used);
        used = 0;
        for (std::size_t k = 0; k < count; ++k) {
            if (plans[k].zero) {
                done(j0 + k, State{});
                continue;
            }
            done(j0 + k, full_state(plans[k], w[used], w[used + 1]));
            used += 2;
        }
    }
}

State full_state(const Wavelet& w, double omega, double damping, double t_s) {
    const FullStatePlan plan = plan_full_state({&w, omega, damping, t_s});
    if (plan.zero) return {};
    const std::array<std::complex<double>, 2> z{plan.half[0].arg, plan.half[1].arg};
    std::array<std::complex<double>, 2> v;
    faddeeva_upper(z.data(), v.data(), 2);
    return full_state(plan, v[0], v[1]);
}

// The response to the wavelet cut off at t = 0 from the full one: the record starts at rest at
// t = 0, so the free vibration left there by the part of the wavelet before it (y and dy/dt at 0
// of the full response are exactly that part's) is removed.
double cut_response(const Wavelet& w, const OscillatorAt& o, const WaveletStart& start,
                    double full) {
    if (w.start_s() >= 0.0 || o.t_s < 0.0) return full;
    const double omega = units::hz_to_radps(o.f_hz);
    const double omega_d = omega * std::sqrt(1.0 - o.damping * o.damping);
    const double free =
        o.decay *
        (start.y * o.cos_wd_t + (start.ydot + o.damping * omega * start.y) / omega_d * o.sin_wd_t);
    return full - free;
}

}  // namespace

WaveletStart wavelet_start(const Wavelet& w, double f_hz, double damping) {
    const State s0 = full_state(w, units::hz_to_radps(f_hz), damping, 0.0);
    return {s0.y, s0.ydot};
}

OscillatorAt oscillator_at(double f_hz, double damping, double t_s) {
    const double omega = units::hz_to_radps(f_hz);
    const double omega_d = omega * std::sqrt(1.0 - damping * damping);
    OscillatorAt o;
    o.f_hz = f_hz;
    o.damping = damping;
    o.t_s = t_s;
    o.decay = std::exp(-damping * omega * t_s);
    o.cos_wd_t = std::cos(omega_d * t_s);
    o.sin_wd_t = std::sin(omega_d * t_s);
    return o;
}

double wavelet_response(const Wavelet& w, const OscillatorAt& o, const WaveletStart& start) {
    const double omega = units::hz_to_radps(o.f_hz);
    return cut_response(w, o, start, full_state(w, omega, o.damping, o.t_s).y);
}

void wavelet_starts(const StartRequest* r, std::size_t n) {
    full_states(
        n,
        [&](std::size_t j) {
            return FullStateArgs{r[j].wavelet, units::hz_to_radps(r[j].f_hz), r[j].damping, 0.0};
        },
        [&](std::size_t j, const State& s) {
            *r[j].out = {s.y, s.ydot};
        });
}

void wavelet_responses(const ResponseRequest* r, std::size_t n) {
    full_states(
        n,
        [&](std::size_t j) {
            const OscillatorAt& o = *r[j].at;
            return FullStateArgs{r[j].wavelet, units::hz_to_radps(o.f_hz), o.damping, o.t_s};
        },
        [&](std::size_t j, const State& s) {
            *r[j].out = cut_response(*r[j].wavelet, *r[j].at, *r[j].start, s.y);
        });
}

double wavelet_response(const Wavelet& w, double f_hz, double damping, double t_s,
                        const WaveletStart& start) {
    if (w.start_s() >= 0.0 || t_s < 0.0)
        return full_state(w, units::hz_to_radps(f_hz), damping, t_s).y;
    return wavelet_response(w, oscillator_at(f_hz, damping, t_s), start);
}

double wavelet_response(const Wavelet& w, double f_hz, double damping, double t_s) {
    const bool cut = w.start_s() < 0.0 && t_s >= 0.0;
    return wavelet_response(w, f_hz, damping, t_s,
                            cut ? wavelet_start(w, f_hz, damping) : WaveletStart{});
}

SampledWavelet sample_wavelet(const Wavelet& w, double dt_s, std::size_t samples) {
    SampledWavelet out;
    sample_wavelet(w, dt_s, samples, out);
    return out;
}

namespace {

using Pair = double __attribute__((vector_size(16)));

// One wavelet being sampled: x_k = (i0 + k) dt - centre; exp(i W x) rotates by exp(i W dt); the
// Gaussian ratio g_{k+1} / g_k = exp(-(2 x_k dt + dt^2) / gamma^2) itself changes by
// exp(-2 dt^2 / gamma^2). rot *= step with (re, im) in one vector: (re, im) sr + (im, re)
// (-si, si) performs the complex multiply's operations, re sr - im si and im sr + re si
// (x + (-y) is x - y and addition commutes), so the samples keep their bits.
struct Sampler {
    double* out = nullptr;  // the samples
    std::size_t count = 0;
    const double* wa = nullptr;  // the weights at the samples, or null
    const double* wb = nullptr;
    Pair sr{}, si{}, rot{};
    double gauss = 0.0, ratio = 0.0, ratio_step = 0.0;
    Pair sum{0.0, 0.0};  // the two weighted sums, each in order of k
};

// The sampler of w into out over its support inside the record (out.first and the size of
// out.values set; count 0 if the support misses the record).
Sampler sampler(const Wavelet& w, double dt_s, std::size_t samples, SampledWavelet& out,
                const double* weights_a, const double* weights_b) {
    Sampler s;
    out.first = 0;
    if (samples == 0 || w.end_s() < 0.0 || w.start_s() > static_cast<double>(samples - 1) * dt_s) {
        out.values.clear();
        return s;
    }
    const double last = static_cast<double>(samples - 1);
    const auto i0 = static_cast<std::size_t>(std::clamp(std::ceil(w.start_s() / dt_s), 0.0, last));
    const auto i1 = static_cast<std::size_t>(std::clamp(std::floor(w.end_s() / dt_s), 0.0, last));
    out.first = i0;
    out.values.resize(i1 - i0 + 1);  // every value is written by the steps
    s.out = out.values.data();
    s.count = out.values.size();
    if (weights_a != nullptr) {
        s.wa = weights_a + i0;
        s.wb = weights_b + i0;
    }
    const double x0 = static_cast<double>(i0) * dt_s - w.centre_s;
    const double g2 = w.gamma_s * w.gamma_s;
    const std::complex<double> step = std::polar(1.0, w.omega_d_radps * dt_s);
    const std::complex<double> phase = std::polar(1.0, w.omega_d_radps * x0);
    s.gauss = std::exp(-x0 * x0 / g2);
    s.ratio = std::exp(-(2.0 * x0 * dt_s + dt_s * dt_s) / g2);
    s.ratio_step = std::exp(-2.0 * dt_s * dt_s / g2);
    s.sr = Pair{step.real(), step.real()};
    s.si = Pair{-step.imag(), step.imag()};
    s.rot = Pair{phase.real(), phase.imag()};
    return s;
}

// Steps [from, to) of K samplers side by side: each is a chain of dependent multiplies and
// adds (the rotation, the Gaussian, the sums), which one at a time leaves the floating-point
// units idle; each keeps its own operations in its own order. The states are copied in and out
// so that they stay in registers (a store of a sample could alias a member).
template <std::size_t K, bool Weighted>
void run_together(Sampler* s, std::size_t from, std::size_t to) {
    Pair sr[K], si[K], rot[K], sum[K];
    double gauss[K], ratio[K], ratio_step[K];
    for (std::size_t l = 0; l < K; ++l) {
        sr[l] = s[l].sr;
        si[l] = s[l].si;
        rot[l] = s[l].rot;
        sum[l] = s[l].sum;
        gauss[l] = s[l].gauss;
        ratio[l] = s[l].ratio;
        ratio_step[l] = s[l].ratio_step;
    }
    for (std::size_t k = from; k < to; ++k)
#pragma GCC unroll 4
        for (std::size_t l = 0; l < K; ++l) {
            const double v = rot[l][0] * gauss[l];
            s[l].out[k] = v;
            if constexpr (Weighted) sum[l] += Pair{s[l].wa[k], s[l].wb[k]} * v;
            rot[l] = rot[l] * sr[l] + Pair{rot[l][1], rot[l][0]} * si[l];
            gauss[l] *= ratio[l];
            ratio[l] *= ratio_step[l];
        }
    for (std::size_t l = 0; l < K; ++l) {
        s[l].rot = rot[l];
        s[l].sum = sum[l];
        s[l].gauss = gauss[l];
        s[l].ratio = ratio[l];
    }
}

void run(Sampler& s) {
    if (s.wa != nullptr)
        run_together<1, true>(&s, 0, s.count);
    else
        run_together<1, false>(&s, 0, s.count);
}

}  // namespace

void sample_wavelet(const Wavelet& w, double dt_s, std::size_t samples, SampledWavelet& out) {
    Sampler s = sampler(w, dt_s, samples, out, nullptr, nullptr);
    run(s);
}

std::array<double, 2> sample_wavelet(const Wavelet& w, double dt_s, std::size_t samples,
                                     SampledWavelet& out, const std::vector<double>& weights_a,
                                     const std::vector<double>& weights_b) {
    Sampler s = sampler(w, dt_s, samples, out, weights_a.data(), weights_b.data());
    run(s);
    return {s.sum[0], s.sum[1]};
}

void sample_wavelets(const SampleRequest* r, std::size_t n, double dt_s, std::size_t samples,
                     const std::vector<double>& weights_a, const std::vector<double>& weights_b) {
    // In threes of about equal length (longest first): side by side over the shortest one's
    // samples, the rest of the others alone.
    constexpr std::size_t kTogether = 3;
    std::vector<Sampler> s(n);
    std::vector<std::size_t> order(n);
    for (std::size_t j = 0; j < n; ++j) {
        s[j] = sampler(*r[j].wavelet, dt_s, samples, *r[j].out, weights_a.data(), weights_b.data());
        order[j] = j;
    }
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return s[a].count > s[b].count; });
    std::array<Sampler, kTogether> group;
    for (std::size_t g = 0; g < n; g += kTogether) {
        const std::size_t size = std::min(kTogether, n - g);
        for (std::size_t l = 0; l < size; ++l) group[l] = s[order[g + l]];
        const std::size_t common = group[size - 1].count;
        if (size == kTogether) run_together<kTogether, true>(group.data(), 0, common);
        for (std::size_t l = 0; l < size; ++l) {
            run_together<1, true>(&group[l], size == kTogether ? common : 0, group[l].count);
            *r[order[g + l]].sum_a = group[l].sum[0];
            *r[order[g + l]].sum_b = group[l].sum[1];
        }
    }
}

void add_wavelet(const SampledWavelet& w, double amplitude, std::vector<double>& accel) {
    for (std::size_t k = 0; k < w.values.size(); ++k) accel[w.first + k] += amplitude * w.values[k];
}

void add_wavelet(const Wavelet& w, double amplitude, double dt_s, std::vector<double>& accel) {
    add_wavelet(sample_wavelet(w, dt_s, accel.size()), amplitude, accel);
}

}  // namespace freestand::motion
