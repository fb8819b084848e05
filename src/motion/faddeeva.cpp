#include "motion/faddeeva.hpp"

#include <array>
#include <cmath>
#include <numbers>

namespace freestand::motion {
namespace {

constexpr int kTerms = 36;  // Weideman's N
constexpr double kAsymptoticRadius = 8.0;
// Series evaluations interleaved by the batch form: one chain of dependent steps leaves the
// floating-point units idle most of the time, four keep them busy.
constexpr std::size_t kFaddeevaChains = 4;

using Pair = double __attribute__((vector_size(16)));

struct Coefficients {
    double L = 0.0;                  // scale of the Moebius map
    std::array<double, kTerms> a{};  // a_1..a_N of eq. 3.11
    std::array<Pair, kTerms> a_re;   // (a_n, -0): adds a_n to a real part, nothing to an imaginary
};

// a_n are the Fourier coefficients of f(t) = exp(-t^2) (L^2 + t^2) on the mapped grid
// t = L tan(theta / 2), computed by a direct DFT of 4N points (Weideman 1994, section 3;
// his Matlab cef.m does the same with an FFT).
Coefficients make_coefficients() {
    Coefficients c;
    const int m = 2 * kTerms;
    const int m2 = 2 * m;
    c.L = std::sqrt(static_cast<double>(kTerms) / std::numbers::sqrt2);
    std::array<double, 2 * 2 * kTerms> shifted{};
    // f_k for k = -M+1..M-1 with f(-M) = 0 stored after the fftshift that puts k = 0 first.
    for (int k = -m + 1; k <= m - 1; ++k) {
        const double theta = static_cast<double>(k) * std::numbers::pi / static_cast<double>(m);
        const double t = c.L * std::tan(theta / 2.0);
        const double f = std::exp(-t * t) * (c.L * c.L + t * t);
        shifted[static_cast<std::size_t>((k + m2) % m2)] = f;
    }
    for (int n = 1; n <= kTerms; ++n) {
        double re = 0.0;
        for (int j = 0; j < m2; ++j)
            re += shifted[static_cast<std::size_t>(j)] *
                  std::cos(2.0 * std::numbers::pi * static_cast<double>(n) *
                           static_cast<double>(j) / static_cast<double>(m2));
        c.a[static_cast<std::size_t>(n - 1)] = re / static_cast<double>(m2);
    }
    for (std::size_t n = 0; n < c.a.size(); ++n) c.a_re[n] = Pair{c.a[n], -0.0};
    return c;
}

const Coefficients& coefficients() {
    static const Coefficients c = make_coefficients();
    return c;
}

bool asymptotic(std::complex<double> z) {
    return std::norm(z) >= kAsymptoticRadius * kAsymptoticRadius;
}

// w(z) ~ i / (sqrt(pi) z) sum_k (2k-1)!! / (2 z^2)^k (Abramowitz & Stegun 7.1.23); k <= 5 leaves a
// relative error below 3e-9 for |z| >= 8.
std::complex<double> asymptotic_value(std::complex<double> z) {
    const std::complex<double> i(0.0, 1.0);
    const std::complex<double> u = 1.0 / (2.0 * z * z);
    std::complex<double> sum = 1.0;
    std::complex<double> term = 1.0;
    for (int k = 1; k <= 5; ++k) {
        term *= static_cast<double>(2 * k - 1) * u;
        sum += term;
    }
    return i * sum / (std::sqrt(std::numbers::pi) * z);
}

// The series' Moebius map of z: Z = (L + i z) / (L - i z), with Z's parts as the Horner loop
// multiplies by them, and L - i z for the final step.
struct Mapped {
    std::complex<double> lmiz;
    Pair zr, zi;
};

Mapped mapped(std::complex<double> z) {
    const std::complex<double> i(0.0, 1.0);
    const Coefficients& c = coefficients();
    const std::complex<double> lmiz = c.L - i * z;
    const std::complex<double> Z = (c.L + i * z) / lmiz;
    return {lmiz, Pair{Z.real(), Z.real()}, Pair{-Z.imag(), Z.imag()}};
}

// Horner on p(Z) = sum_{n=1}^{N} a_n Z^(n-1), p <- p Z + a_n, for K arguments at once, each p =
// (re, im) in one vector: (re, im) Zr + (im, re) (-Zi, Zi) + (a_n, -0) performs the operations of
// the complex multiply-add, re Zr - im Zi + a_n and im Zr + re Zi (x + (-y) is x - y, addition
// commutes, and adding -0 leaves every value as it is), so the bits are the same. Each argument's
// recurrence is a chain of 35 dependent multiply-adds; K chains side by side overlap their
// latencies (each keeps its own operations in its own order: the same bits for any K).
template <std::size_t K>
void horner(const Mapped* m, Pair* p) {
    const Coefficients& c = coefficients();
    for (std::size_t k = 0; k < K; ++k) p[k] = Pair{c.a[kTerms - 1], 0.0};
#pragma GCC unroll 35
    for (int n = kTerms - 2; n >= 0; --n)
        for (std::size_t k = 0; k < K; ++k) {
            const Pair swapped{p[k][1], p[k][0]};
            p[k] = (p[k] * m[k].zr + swapped * m[k].zi) + c.a_re[static_cast<std::size_t>(n)];
        }
}

std::complex<double> series_value(const Pair& p, std::complex<double> lmiz) {
    const std::complex<double> series(p[0], p[1]);
    return 2.0 * series / (lmiz * lmiz) + (1.0 / std::sqrt(std::numbers::pi)) / lmiz;
}

// The series at K arguments of the series region, z[at[k]], into w[at[k]].
template <std::size_t K>
void series_at(const std::complex<double>* z, const std::size_t* at, std::complex<double>* w) {
    std::array<Mapped, K> m;
    for (std::size_t k = 0; k < K; ++k) m[k] = mapped(z[at[k]]);
    std::array<Pair, K> p;
    horner<K>(m.data(), p.data());
    for (std::size_t k = 0; k < K; ++k) w[at[k]] = series_value(p[k], m[k].lmiz);
}

}  // namespace

std::complex<double> faddeeva_upper(std::complex<double> z) {
    if (asymptotic(z)) return asymptotic_value(z);
    const Mapped m = mapped(z);
    Pair p;
    horner<1>(&m, &p);
    return series_value(p, m.lmiz);
}

void faddeeva_upper(const std::complex<double>* z, std::complex<double>* w, std::size_t n) {
    std::array<std::size_t, kFaddeevaChains> series{};  // arguments waiting for the series
    std::size_t waiting = 0;
    for (std::size_t j = 0; j < n; ++j) {
        if (asymptotic(z[j])) {
            w[j] = asymptotic_value(z[j]);
            continue;
        }
        series[waiting++] = j;
        if (waiting < kFaddeevaChains) continue;
        series_at<kFaddeevaChains>(z, series.data(), w);
        waiting = 0;
    }
    static_assert(kFaddeevaChains == 4, "the remainders below");
    if (waiting == 3) series_at<3>(z, series.data(), w);
    if (waiting == 2) series_at<2>(z, series.data(), w);
    if (waiting == 1) series_at<1>(z, series.data(), w);
}

}  // namespace freestand::motion
