#pragma once
/// Real FFTs of one length through FFTW, planned with FFTW_ESTIMATE (deterministic plans) once
/// per length and direction for the whole process, on first use (FFTW's planner is not thread-safe,
/// so planning is serialised by a mutex; the plans are executed on each object's own arrays).
#include <complex>
#include <cstddef>
#include <vector>

namespace freestand::core {

/// r2c / c2r pair for one length n, with FFTW-aligned buffers owned by the object and the
/// length's shared plans. Unnormalised like FFTW: inverse(forward(x)) = n x. Not copyable; use
/// one per thread (objects of one length in several threads at once are safe).
class RealFft {
  public:
    explicit RealFft(std::size_t n);
    ~RealFft();
    RealFft(const RealFft&) = delete;
    RealFft& operator=(const RealFft&) = delete;

    std::size_t size() const { return n_; }
    std::size_t bins() const { return n_ / 2 + 1; }
    /// X_k = sum_j x_j exp(-2 pi i j k / n), k = 0..n/2; x is zero-padded (or cut) to n.
    std::vector<std::complex<double>> forward(const std::vector<double>& x);
    /// x_j = sum over the full Hermitian spectrum (no 1/n), j = 0..n-1.
    std::vector<double> inverse(const std::vector<std::complex<double>>& spectrum);

  private:
    std::size_t n_;
    double* real_ = nullptr;
    void* complex_ = nullptr;  // fftw_complex*
    void* forward_plan_ = nullptr;  // fftw_plan, shared, taken on first use
    void* inverse_plan_ = nullptr;
};

/// Smallest n' >= n of the form 2^a 3^b 5^c (fast FFT lengths).
std::size_t fft_size(std::size_t n);

}  // namespace freestand::core
