#include "motion/faddeeva.hpp"

#include <array>
#include <cmath>
#include <numbers>

namespace freestand::motion {
namespace {

constexpr int kTerms = 36;  // Weideman's N
constexpr double kAsymptoticRadius = 8.0;

struct Coefficients {
    double L = 0.0;                  // scale of the Moebius map
    std::array<double, kTerms> a{};  // a_1..a_N of eq. 3.11
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
    // Horner on p(Z) = sum_{n=1}^{N} a_n Z^(n-1).
    std::complex<double> p = c.a[kTerms - 1];
    for (int n = kTerms - 2; n >= 0; --n) p = p * Z + c.a[static_cast<std::size_t>(n)];
    return 2.0 * p / (lmiz * lmiz) + (1.0 / std::sqrt(std::numbers::pi)) / lmiz;
}

}  // namespace freestand::motion
