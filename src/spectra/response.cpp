#include "spectra/response.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <new>
#include <utility>

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
    // A product meant to be whole (0.005 s x 10 x 200 Hz) is not rounded one sub-step up. Not
    // core::steps_covering: its larger guard could take a sub-step off a product a little above
    // a whole number and move the shipped spectra.
    constexpr double substep_rounding_guard = 1e-12;
    const double need = dt_s * static_cast<double>(min_steps_per_period) * f_hz;
    return std::max(1, static_cast<int>(std::ceil(need - substep_rounding_guard)));
}

Stepper make_stepper(double f_hz, double zeta, double dt_s, int min_steps_per_period) {
    const int n = substeps(f_hz, dt_s, min_steps_per_period);
    const double omega = units::hz_to_radps(f_hz);
    const StepMatrices m = step_matrices(omega, zeta, dt_s / static_cast<double>(n));
    Stepper st;
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

// ---- The oscillators advanced in lockstep ----
//
// Oscillators with the same sub-step count are packed W to a vector register (W = 2 with SSE2,
// 4 with AVX, 8 with AVX-512) and up to kMaxVectors registers are advanced together: the
// recurrences are independent, so one oscillator's latency chain (u -> u_next, three dependent
// flops per step) overlaps the others'. Every lane performs the scalar recurrence's IEEE operations
// in the same order (no fused multiply-add: this file is compiled with -ffp-contract=off), so the
// results do not depend on W, on the grouping or on the CPU.

constexpr std::size_t kMaxVectors = 4;
constexpr std::size_t kMaxLanes = 8;  // AVX-512
// Steps per block when peak times are wanted: the loop keeps only the running maximum (as for
// PSA) and logs each block's maximum and starting state; the one block holding an oscillator's
// peak is then run again with the time tracked (a blend per sub-point otherwise).
constexpr std::size_t kBlockSteps = 32;

using V2 = double __attribute__((vector_size(16), may_alias));
#if defined(__x86_64__) || defined(__i386__)
#define FREESTAND_RESPONSE_AVX 1
using V4 = double __attribute__((vector_size(32), may_alias));
using V8 = double __attribute__((vector_size(64), may_alias));
using L8 = long long __attribute__((vector_size(64)));  // lane indices of a V8
#endif

/// Doubles on a 64-byte boundary, so that packed coefficients load as aligned vectors.
struct AlignedFree {
    void operator()(double* p) const { ::operator delete[](p, std::align_val_t{64}); }
};
using AlignedDoubles = std::unique_ptr<double[], AlignedFree>;

AlignedDoubles aligned_doubles(std::size_t count) {
    return AlignedDoubles(
        static_cast<double*>(::operator new[](count * sizeof(double), std::align_val_t{64})));
}

/// Up to W x kMaxVectors oscillators with the same sub-step count n: lane l of vector p is
/// oscillator member[min(p W + l, size - 1)] (the last one repeats to fill the vectors).
struct Group {
    std::size_t n = 1;
    std::size_t vectors = 1;
    std::vector<std::size_t> member;
    AlignedDoubles cu;  // coefficient j of sub-point k, vector p, lane l: ((k 4 + j) P + p) W + l
    AlignedDoubles cv;  // coefficient j of v at the end of the sample:   (j P + p) W + l
};

enum class Watch {
    peak,        // the running maximum of |u|
    blocks,      // the maximum of |u| in each block, and the state at each block's start
    first_peak,  // also the signed u and the sub-point index where |u| first reaches its maximum
};

/// One run of the vectors [p0, p0 + P) of a group over the steps [first, end) of a record
/// (step i advances from sample i - 1 to sample i). State arrays hold P W lanes.
struct Pass {
    const double* cu = nullptr;
    const double* cv = nullptr;
    std::size_t n = 1;
    std::size_t stride = 1;  // the group's vector count
    std::size_t p0 = 0;
    const double* a = nullptr;
    std::size_t first = 1, end = 1;
    double* u = nullptr;  // in and out
    double* v = nullptr;
    double* peak = nullptr;         // running max |u|, in and out (peak, first_peak)
    double* peak_signed = nullptr;  // first_peak
    double* peak_index = nullptr;   // first_peak: sub-point index counted from the first sample
    double* block_max = nullptr;    // blocks: P W per block
    double* block_u = nullptr;
    double* block_v = nullptr;
};

// The loops below are always inlined into one function per vector type and count, so that the
// AVX instance is compiled with AVX throughout. They take no vector by value (a 256-bit vector
// argument of a function compiled without AVX would change the calling convention).

template <class V, std::size_t W>
[[gnu::always_inline]] inline void broadcast(V& out, double x) {
    if constexpr (W == 2) {
        out = V{x, x};
    } else if constexpr (W == 4) {
        out = V{x, x, x, x};
    } else {
        // x into lane 0, then lane 0 into every lane: one broadcast (an eight-lane initialiser
        // is built lane by lane).
#if defined(__clang__)
        out = __builtin_shufflevector(V{x}, V{x}, 0, 0, 0, 0, 0, 0, 0, 0);
#else
        out = __builtin_shuffle(V{x}, L8{});
#endif
    }
}

/// Peak bookkeeping of one vector after a new sub-point value un at sub-point index `at`.
template <class V, Watch M>
[[gnu::always_inline]] inline void watch(const V& un, const V& at, V& peak, V& peak_signed,
                                         V& peak_index) {
    // |un| as un < 0 ? -un : un, written as the maximum of -un and un (one instruction fewer):
    // the same value for every un, signed zeros and NaN included.
    const V neg = -un;
    const V m = neg > un ? neg : un;
    if constexpr (M == Watch::first_peak) {
        const auto larger = m > peak;
        peak_signed = larger ? un : peak_signed;
        peak_index = larger ? at : peak_index;
    }
    peak = peak > m ? peak : m;
}

/// Steps [first, end) of the P vectors, each step in N sub-steps (N = 0: s.n, not known at
/// compile time); c and d hold the u (of N = 1) and end-of-sample v coefficients, s.cu the
/// packed u coefficients of every sub-point.
template <class V, std::size_t W, std::size_t P, std::size_t N, Watch M>
[[gnu::always_inline]] inline void steps(const Pass& s, std::size_t first, std::size_t end,
                                         const V (&c)[4][P], const V (&d)[4][P], V (&u)[P],
                                         V (&v)[P], V (&peak)[P], V (&peak_signed)[P],
                                         V (&peak_index)[P]) {
    const double* a = s.a;
    V a0, a1, at{};
    broadcast<V, W>(a1, a[first - 1]);
    if constexpr (N == 1) {
        // T >= 20 dt: the common case, everything in registers.
        for (std::size_t i = first; i < end; ++i) {
            a0 = a1;
            broadcast<V, W>(a1, a[i]);
            if constexpr (M == Watch::first_peak) broadcast<V, W>(at, static_cast<double>(i));
            for (std::size_t q = 0; q < P; ++q) {
                const V un = (c[0][q] * u[q] + c[1][q] * v[q]) + (c[2][q] * a0 + c[3][q] * a1);
                v[q] = (d[0][q] * u[q] + d[1][q] * v[q]) + (d[2][q] * a0 + d[3][q] * a1);
                u[q] = un;
                watch<V, M>(un, at, peak[q], peak_signed[q], peak_index[q]);
            }
        }
        return;
    }
    const std::size_t n = N == 0 ? s.n : N;
    const double* cu = s.cu + s.p0 * W;
    const std::size_t stride = s.stride * W;
    for (std::size_t i = first; i < end; ++i) {
        a0 = a1;
        broadcast<V, W>(a1, a[i]);
        V un[P]{};
        for (std::size_t k = 0; k < n; ++k) {
            // Coefficient j of sub-point k, vector q at r + j stride + q W.
            const double* r = cu + k * 4 * stride;
            if constexpr (M == Watch::first_peak)
                broadcast<V, W>(at, static_cast<double>((i - 1) * n + k + 1));
            for (std::size_t q = 0; q < P; ++q) {
                const V& r0 = *reinterpret_cast<const V*>(r + q * W);
                const V& r1 = *reinterpret_cast<const V*>(r + stride + q * W);
                const V& r2 = *reinterpret_cast<const V*>(r + 2 * stride + q * W);
                const V& r3 = *reinterpret_cast<const V*>(r + 3 * stride + q * W);
                un[q] = (r0 * u[q] + r1 * v[q]) + (r2 * a0 + r3 * a1);
                watch<V, M>(un[q], at, peak[q], peak_signed[q], peak_index[q]);
            }
        }
        for (std::size_t q = 0; q < P; ++q) {
            v[q] = (d[0][q] * u[q] + d[1][q] * v[q]) + (d[2][q] * a0 + d[3][q] * a1);
            u[q] = un[q];
        }
    }
}

template <class V, std::size_t W, std::size_t P>
[[gnu::always_inline]] inline void load(V (&out)[P], const double* from) {
    for (std::size_t q = 0; q < P; ++q)
        for (std::size_t l = 0; l < W; ++l) out[q][l] = from[q * W + l];
}

template <class V, std::size_t W, std::size_t P>
[[gnu::always_inline]] inline void store(double* to, const V (&from)[P]) {
    for (std::size_t q = 0; q < P; ++q)
        for (std::size_t l = 0; l < W; ++l) to[q * W + l] = from[q][l];
}

template <class V, std::size_t W, std::size_t P, std::size_t N, Watch M>
[[gnu::always_inline]] inline void advance(const Pass& s) {
    V c[4][P], d[4][P];
    for (std::size_t j = 0; j < 4; ++j)
        for (std::size_t q = 0; q < P; ++q) {
            c[j][q] = *reinterpret_cast<const V*>(s.cu + (j * s.stride + s.p0 + q) * W);
            d[j][q] = *reinterpret_cast<const V*>(s.cv + (j * s.stride + s.p0 + q) * W);
        }
    V u[P]{}, v[P]{}, peak[P]{}, peak_signed[P]{}, peak_index[P]{};
    load<V, W, P>(u, s.u);
    load<V, W, P>(v, s.v);
    if constexpr (M == Watch::blocks) {
        std::size_t offset = 0;
        for (std::size_t first = s.first; first < s.end; first += kBlockSteps) {
            store<V, W, P>(s.block_u + offset, u);
            store<V, W, P>(s.block_v + offset, v);
            for (std::size_t q = 0; q < P; ++q) broadcast<V, W>(peak[q], 0.0);
            steps<V, W, P, N, M>(s, first, std::min(s.end, first + kBlockSteps), c, d, u, v, peak,
                                 peak_signed, peak_index);
            store<V, W, P>(s.block_max + offset, peak);
            offset += P * W;
        }
    } else {
        load<V, W, P>(peak, s.peak);
        if constexpr (M == Watch::first_peak) {
            load<V, W, P>(peak_signed, s.peak_signed);
            load<V, W, P>(peak_index, s.peak_index);
        }
        steps<V, W, P, N, M>(s, s.first, s.end, c, d, u, v, peak, peak_signed, peak_index);
        store<V, W, P>(s.peak, peak);
        if constexpr (M == Watch::first_peak) {
            store<V, W, P>(s.peak_signed, peak_signed);
            store<V, W, P>(s.peak_index, peak_index);
        }
    }
    store<V, W, P>(s.u, u);
    store<V, W, P>(s.v, v);
}

using Kernel = void (*)(const Pass&);

// Sub-step counts up to this have loops of their own, unrolled (no loop overhead per sub-point);
// 1-5 cover 0.1-50 Hz at dt = 0.005 s.
constexpr std::size_t kUnrolled = 5;
using Unrolled = std::make_index_sequence<kUnrolled + 1>;  // N = 0 (any count), 1 .. kUnrolled

// One instance of the loops per instruction set, each compiled for it (a target attribute is
// not a template argument), and the table of a set's instances by sub-step count.
template <std::size_t P, std::size_t N, Watch M>
struct Sse2 {
    static void run(const Pass& s) { advance<V2, 2, P, N, M>(s); }
};

#ifdef FREESTAND_RESPONSE_AVX
template <std::size_t P, std::size_t N, Watch M>
struct Avx {
    __attribute__((target("avx"))) static void run(const Pass& s) { advance<V4, 4, P, N, M>(s); }
};

// AVX-512 has fused multiply-adds too; -ffp-contract=off keeps them out, as everywhere here.
template <std::size_t P, std::size_t N, Watch M>
struct Avx512 {
    __attribute__((target("avx512f"))) static void run(const Pass& s) {
        advance<V8, 8, P, N, M>(s);
    }
};
#endif

template <template <std::size_t, std::size_t, Watch> class Isa, std::size_t P, Watch M,
          std::size_t... N>
constexpr std::array<Kernel, kUnrolled + 1> kernels(std::index_sequence<N...>) {
    return {&Isa<P, N, M>::run...};
}

/// The widest vectors of at most max_lanes lanes this CPU has: 8 (AVX-512), 4 (AVX) or 2.
std::size_t lanes_for(std::size_t max_lanes) {
#ifdef FREESTAND_RESPONSE_AVX
    static const bool avx512 = __builtin_cpu_supports("avx512f");
    static const bool avx = __builtin_cpu_supports("avx");
    if (max_lanes >= 8 && avx512) return 8;
    if (max_lanes >= 4 && avx) return 4;
#endif
    (void)max_lanes;
    return 2;
}

/// The loop for P vectors of `width` lanes and n sub-steps per step, watching M.
template <std::size_t P, Watch M>
Kernel kernel_for(std::size_t width, std::size_t n) {
    const std::size_t unrolled = n <= kUnrolled ? n : 0;
#ifdef FREESTAND_RESPONSE_AVX
    static constexpr std::array<Kernel, kUnrolled + 1> avx = kernels<Avx, P, M>(Unrolled{});
    if (width == 4) return avx[unrolled];
    static constexpr std::array<Kernel, kUnrolled + 1> avx512 = kernels<Avx512, P, M>(Unrolled{});
    if (width == 8) return avx512[unrolled];
#endif
    FREESTAND_EXPECT(width == 2, "vectors of 2 lanes, or of 4 with AVX, or of 8 with AVX-512");
    static constexpr std::array<Kernel, kUnrolled + 1> sse2 = kernels<Sse2, P, M>(Unrolled{});
    return sse2[unrolled];
}

template <Watch M>
Kernel kernel_for(std::size_t width, std::size_t vectors, std::size_t n) {
    switch (vectors) {
        case 1:
            return kernel_for<1, M>(width, n);
        case 2:
            return kernel_for<2, M>(width, n);
        case 3:
            return kernel_for<3, M>(width, n);
        default:
            FREESTAND_EXPECT(vectors == kMaxVectors, "1 to kMaxVectors vectors");
            return kernel_for<4, M>(width, n);
    }
}

/// The group's coefficients packed for vectors of `width` lanes.
Group pack(const std::vector<Stepper>& steppers, const std::vector<std::size_t>& member,
           std::size_t width) {
    Group g;
    g.member = member;
    g.n = steppers[member.front()].sub_u.size();
    g.vectors = (member.size() + width - 1) / width;
    const std::size_t lanes = g.vectors * width;
    g.cu = aligned_doubles(g.n * 4 * lanes);
    g.cv = aligned_doubles(4 * lanes);
    for (std::size_t lane = 0; lane < lanes; ++lane) {
        const Stepper& st = steppers[member[std::min(lane, member.size() - 1)]];
        for (std::size_t j = 0; j < 4; ++j) {
            for (std::size_t k = 0; k < g.n; ++k) g.cu[(k * 4 + j) * lanes + lane] = st.sub_u[k][j];
            g.cv[j * lanes + lane] = st.end_v[j];
        }
    }
    return g;
}

/// Groups of equal sub-step counts, in order of the count, of up to width x kMaxVectors.
std::vector<Group> groups_of(const std::vector<Stepper>& steppers, std::size_t width) {
    std::vector<std::size_t> order(steppers.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
        return steppers[x].sub_u.size() < steppers[y].sub_u.size();
    });
    const std::size_t most = width * kMaxVectors;
    std::vector<Group> groups;
    std::size_t i = 0;
    while (i < order.size()) {
        std::vector<std::size_t> member{order[i]};
        while (member.size() < most && i + member.size() < order.size() &&
               steppers[order[i + member.size()]].sub_u.size() == steppers[order[i]].sub_u.size())
            member.push_back(order[i + member.size()]);
        i += member.size();
        groups.push_back(pack(steppers, member, width));
    }
    return groups;
}

/// Lane storage of one group's run: kMaxVectors x kMaxLanes lanes at most.
using LaneArray = std::array<double, kMaxVectors * kMaxLanes>;

Pass pass_over(const Group& g, const std::vector<double>& a) {
    Pass s;
    s.cu = g.cu.get();
    s.cv = g.cv.get();
    s.n = g.n;
    s.stride = g.vectors;
    s.a = a.data();
    s.first = 1;
    s.end = a.size();
    return s;
}

void check_record(const core::Record& record) {
    core::validate(record);
    if (record.accel_mps2.size() < 2)
        throw InputError(SourceLocation{record.source, 0, "samples"},
                         fmt::format("record \"{}\" has {} sample; expected at least 2 (one time "
                                     "step) for a response",
                                     record.name, record.accel_mps2.size()));
}

void check_dampings(const std::vector<double>& dampings) {
    if (dampings.empty())
        throw InputError(SourceLocation{"", 0, "damping"},
                         "no damping given; expected at least one");
    for (double z : dampings)
        require_in_range(z, 0.0, 1.0, SourceLocation{"", 0, "damping"}, true, false);
}

void check_frequencies(const std::vector<double>& frequency_hz) {
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

void check_inputs(const core::Record& record, const std::vector<double>& dampings,
                  const std::vector<double>& frequency_hz) {
    check_record(record);
    check_dampings(dampings);
    check_frequencies(frequency_hz);
}

/// Max of two peaks as the vector loops take it (b replaces a only if larger).
double larger_of(double a, double b) { return a > b ? a : b; }

}  // namespace

struct OscillatorSet::Prepared {
    double damping = 0.0;
    double dt_s = 0.0;
    std::vector<double> frequency_hz;
    std::vector<std::size_t> substeps;
    std::size_t width = 2;  // lanes per vector
    std::vector<Group> groups;

    void check(const core::Record& record) const {
        check_record(record);
        if (record.dt_s != dt_s)
            throw InputError(SourceLocation{record.source, 0, "dt"},
                             fmt::format("record \"{}\" is sampled at dt {} s; these oscillators "
                                         "were set up for dt {} s",
                                         record.name, record.dt_s, dt_s));
    }

    /// max |u| of every oscillator over the record.
    std::vector<double> peaks(const std::vector<double>& a) const {
        std::vector<double> out(frequency_hz.size());
        for (const Group& g : groups) {
            LaneArray u{}, v{}, peak{};
            Pass s = pass_over(g, a);
            s.u = u.data();
            s.v = v.data();
            s.peak = peak.data();
            kernel_for<Watch::peak>(width, g.vectors, g.n)(s);
            for (std::size_t lane = 0; lane < g.member.size(); ++lane)
                out[g.member[lane]] = peak[lane];
        }
        return out;
    }

    /// The signed u at the first sub-point where |u| reaches its maximum, and that sub-point's
    /// index (0 and 0 if u stays 0), of every oscillator.
    void first_peaks(const std::vector<double>& a, std::vector<double>& signed_m,
                     std::vector<double>& index) const {
        signed_m.assign(frequency_hz.size(), 0.0);
        index.assign(frequency_hz.size(), 0.0);
        const std::size_t blocks = (a.size() - 1 + kBlockSteps - 1) / kBlockSteps;
        // Written by the loops before they are read; sized for the widest group.
        const std::size_t size = blocks * kMaxVectors * width;
        const std::unique_ptr<double[]> block_max(new double[size]);
        const std::unique_ptr<double[]> block_u(new double[size]);
        const std::unique_ptr<double[]> block_v(new double[size]);
        for (const Group& g : groups) {
            const std::size_t lanes = g.vectors * width;
            LaneArray u{}, v{};
            Pass s = pass_over(g, a);
            s.u = u.data();
            s.v = v.data();
            s.block_max = block_max.get();
            s.block_u = block_u.get();
            s.block_v = block_v.get();
            kernel_for<Watch::blocks>(width, g.vectors, g.n)(s);
            // Each lane's peak is in the first block whose maximum equals the overall one.
            std::array<std::size_t, kMaxVectors * kMaxLanes> in_block{};
            for (std::size_t lane = 0; lane < g.member.size(); ++lane) {
                double most = 0.0;
                for (std::size_t b = 0; b < blocks; ++b)
                    most = larger_of(most, block_max[b * lanes + lane]);
                std::size_t b = 0;
                while (b + 1 < blocks && block_max[b * lanes + lane] != most) ++b;
                in_block[lane] = b;
            }
            for (std::size_t lane = 0; lane < g.member.size(); ++lane) {
                const std::size_t p = lane / width;
                const std::size_t b = in_block[lane];
                bool done = false;  // an earlier lane of this vector needed the same block
                for (std::size_t other = p * width; other < lane; ++other)
                    done = done || in_block[other] == b;
                if (done) continue;
                const LaneArray tracked = rerun(g, a, p, b, block_u.get(), block_v.get());
                for (std::size_t l = lane; l < std::min(g.member.size(), (p + 1) * width); ++l) {
                    if (in_block[l] != b) continue;
                    signed_m[g.member[l]] = tracked[l - p * width];
                    index[g.member[l]] = tracked[width + l - p * width];
                }
            }
        }
    }

    /// Vector p of the group over block b from its logged starting state, with the peak's
    /// signed value (lanes [0, width)) and index (lanes [width, 2 width)) tracked from zero.
    LaneArray rerun(const Group& g, const std::vector<double>& a, std::size_t p, std::size_t b,
                    const double* block_u, const double* block_v) const {
        const std::size_t lanes = g.vectors * width;
        LaneArray u{}, v{}, peak{}, peak_signed{}, peak_index{};
        std::copy_n(block_u + b * lanes + p * width, width, u.begin());
        std::copy_n(block_v + b * lanes + p * width, width, v.begin());
        Pass s = pass_over(g, a);
        s.p0 = p;
        s.first = 1 + b * kBlockSteps;
        s.end = std::min(a.size(), s.first + kBlockSteps);
        s.u = u.data();
        s.v = v.data();
        s.peak = peak.data();
        s.peak_signed = peak_signed.data();
        s.peak_index = peak_index.data();
        kernel_for<1, Watch::first_peak>(width, g.n)(s);
        LaneArray out{};
        std::copy_n(peak_signed.begin(), width, out.begin());
        std::copy_n(peak_index.begin(), width, out.begin() + static_cast<std::ptrdiff_t>(width));
        return out;
    }
};

OscillatorSet::OscillatorSet(double damping, const std::vector<double>& frequency_hz, double dt_s,
                             const ResponseOptions& options) {
    check_dampings({damping});
    check_frequencies(frequency_hz);
    require_positive(dt_s, SourceLocation{"", 0, "dt_s"});
    FREESTAND_EXPECT(options.min_steps_per_period >= 0,
                     "0 (one step per sample) or more sub-steps per period");
    auto p = std::make_shared<Prepared>();
    p->damping = damping;
    p->dt_s = dt_s;
    p->frequency_hz = frequency_hz;
    FREESTAND_EXPECT(options.max_lanes >= 2, "at least the two lanes of SSE2");
    p->width = lanes_for(static_cast<std::size_t>(options.max_lanes));
    std::vector<Stepper> steppers;
    steppers.reserve(frequency_hz.size());
    for (double f : frequency_hz) {
        steppers.push_back(make_stepper(f, damping, dt_s, options.min_steps_per_period));
        p->substeps.push_back(steppers.back().sub_u.size());
    }
    p->groups = groups_of(steppers, p->width);
    prepared_ = std::move(p);
}

const std::vector<double>& OscillatorSet::frequency_hz() const { return prepared_->frequency_hz; }
double OscillatorSet::damping() const { return prepared_->damping; }
double OscillatorSet::dt_s() const { return prepared_->dt_s; }

std::vector<double> OscillatorSet::sd_m(const core::Record& record) const {
    prepared_->check(record);
    return prepared_->peaks(record.accel_mps2);
}

std::vector<double> OscillatorSet::psa_g(const core::Record& record, double g_mps2) const {
    std::vector<double> out = sd_m(record);
    for (std::size_t i = 0; i < out.size(); ++i) {
        const double w = units::hz_to_radps(prepared_->frequency_hz[i]);
        out[i] = w * w * out[i] / g_mps2;
    }
    return out;
}

std::vector<OscillatorPeak> OscillatorSet::peak_responses(const core::Record& record) const {
    prepared_->check(record);
    std::vector<double> signed_m, index;
    prepared_->first_peaks(record.accel_mps2, signed_m, index);
    std::vector<OscillatorPeak> out(signed_m.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
        const double h = record.dt_s / static_cast<double>(prepared_->substeps[i]);
        out[i] = OscillatorPeak{signed_m[i], index[i] * h};
    }
    return out;
}

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
                                 const ResponseOptions& options, double g_mps2) {
    check_inputs(record, dampings, frequency_hz);
    ResponseSpectra out;
    out.frequency_hz = frequency_hz;
    out.dampings = dampings;
    for (double zeta : dampings) {
        const std::vector<double> sd =
            OscillatorSet(zeta, frequency_hz, record.dt_s, options).sd_m(record);
        std::vector<double> psv(sd.size()), psa(sd.size());
        for (std::size_t i = 0; i < sd.size(); ++i) {
            const double w = units::hz_to_radps(frequency_hz[i]);
            psv[i] = w * sd[i];
            psa[i] = w * w * sd[i] / g_mps2;
        }
        out.sd_m.push_back(sd);
        out.psv_mps.push_back(std::move(psv));
        out.psa_g.push_back(std::move(psa));
    }
    return out;
}

ResponseSpectra response_spectra(const core::Record& record, const std::vector<double>& dampings,
                                 const std::vector<double>& frequency_hz) {
    return response_spectra(record, dampings, frequency_hz, ResponseOptions{});
}

std::vector<double> psa_g(const core::Record& record, double damping,
                          const std::vector<double>& frequency_hz, double g_mps2) {
    check_inputs(record, {damping}, frequency_hz);
    return OscillatorSet(damping, frequency_hz, record.dt_s).psa_g(record, g_mps2);
}

std::vector<OscillatorPeak> peak_responses(const core::Record& record, double damping,
                                           const std::vector<double>& frequency_hz) {
    check_inputs(record, {damping}, frequency_hz);
    return OscillatorSet(damping, frequency_hz, record.dt_s).peak_responses(record);
}

}  // namespace freestand::spectra
