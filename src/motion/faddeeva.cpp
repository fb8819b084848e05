#include "motion/faddeeva.hpp"

#include <array>
#include <cmath>
#include <numbers>

namespace freestand::motion {
namespace {

constexpr int kTerms = 36;  // Weideman's N
constexpr double kAsymptoticRadius = 8.0;

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

}  // namespace

std::complex<double> faddeeva_upper(std::complex<double> z) {
    const std::complex<double> i(0.0, 1.0);
    if (std::norm(z) >= kAsymptoticRadius * kAsymptoticRadius) {
        // w(z) ~ i / (sqrt(pi) z) sum_k (2k-1)!! / (2 z^2)^k (Abramowitz & Stegun 7.1.23);
        // k <= 5 leaves a relative error below 3e-9 for |z| >= 8.
        const std::complex<double> u = 1.0 / (2.0 * z * z);
        std::complex<double> sum = 1.0;
        std::complex<double> term = 1.0;
        for (int k = 1; k <= 5; ++k) {
            term *= static_cast<double>(2 * k - 1) * u;
            sum += term;
        }
        return i * sum / (std::sqrt(std::numbers::pi) * z);
    }
    const Coefficients& c = coefficients();
    const std::complex<double> lmiz = c.L - i * z;
    const std::complex<double> Z = (c.L + i * z) / lmiz;
    // Horner on p(Z) = sum_{n=1}^{N} a_n Z^(n-1), p <- p Z + a_n, with p = (re, im) in one
    // vector: (re, im) Zr + (im, re) (-Zi, Zi) + (a_n, -0) performs the operations of the
    // complex multiply-add, re Zr - im Zi + a_n and im Zr + re Zi (x + (-y) is x - y, addition
    // commutes, and adding -0 leaves every value as it is), so the bits are the same.
    const Pair zr{Z.real(), Z.real()}, zi{-Z.imag(), Z.imag()};
    Pair p{c.a[kTerms - 1], 0.0};
#pragma GCC unroll 35
    for (int n = kTerms - 2; n >= 0; --n) {
        const Pair swapped{p[1], p[0]};
        p = (p * zr + swapped * zi) + c.a_re[static_cast<std::size_t>(n)];
    }
    const std::complex<double> series(p[0], p[1]);
    return 2.0 * series / (lmiz * lmiz) + (1.0 / std::sqrt(std::numbers::pi)) / lmiz;
}

}  // namespace freestand::motion
