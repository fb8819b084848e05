#pragma once
/// Faddeeva function w(z) = exp(-z^2) erfc(-i z), needed in closed form for the response of an
/// oscillator to a Gaussian-tapered cosine wavelet (wavelet.hpp). Hand-written because no
/// packaged library on the build machine provides a complex error function.
#include <complex>
#include <cstddef>

namespace freestand::motion {

/// w(z) for Im z >= 0: Weideman's rational series (SIAM J. Numer. Anal. 31 (1994) 1497,
/// eq. 3.11, N = 36 terms) for |z| < 8, the asymptotic series (Abramowitz & Stegun 7.1.23,
/// six terms) beyond; relative error below 1e-8 over the closed upper half plane.
/// Callers reflect with w(-z) = 2 exp(-z^2) - w(z) for Im z < 0.
std::complex<double> faddeeva_upper(std::complex<double> z);

/// w[j] = faddeeva_upper(z[j]) for j < n, the same bits, with the series of several arguments
/// evaluated side by side: each is a chain of 35 dependent complex multiply-adds, and chains
/// that run together overlap their latencies.
void faddeeva_upper(const std::complex<double>* z, std::complex<double>* w, std::size_t n);

}  // namespace freestand::motion
