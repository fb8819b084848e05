#include "motion/fft.hpp"

#include <fftw3.h>

#include <algorithm>
#include <mutex>
#include <new>

namespace freestand::motion {
namespace {
std::mutex& planner_mutex() {
    static std::mutex m;
    return m;
}
}  // namespace

RealFft::RealFft(std::size_t n) : n_(n) {
    const std::lock_guard<std::mutex> lock(planner_mutex());
    real_ = fftw_alloc_real(n_);
    auto* c = fftw_alloc_complex(bins());
    complex_ = c;
    if (real_ == nullptr || c == nullptr) throw std::bad_alloc();
    const int len = static_cast<int>(n_);
    forward_plan_ = fftw_plan_dft_r2c_1d(len, real_, c, FFTW_ESTIMATE);
    inverse_plan_ = fftw_plan_dft_c2r_1d(len, c, real_, FFTW_ESTIMATE);
}

RealFft::~RealFft() {
    const std::lock_guard<std::mutex> lock(planner_mutex());
    fftw_destroy_plan(static_cast<fftw_plan>(forward_plan_));
    fftw_destroy_plan(static_cast<fftw_plan>(inverse_plan_));
    fftw_free(real_);
    fftw_free(complex_);
}

std::vector<std::complex<double>> RealFft::forward(const std::vector<double>& x) {
    const std::size_t m = std::min(x.size(), n_);
    std::copy_n(x.begin(), m, real_);
    std::fill(real_ + m, real_ + n_, 0.0);
    fftw_execute(static_cast<fftw_plan>(forward_plan_));
    const auto* c = static_cast<const fftw_complex*>(complex_);
    std::vector<std::complex<double>> out(bins());
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = {c[k][0], c[k][1]};
    return out;
}

std::vector<double> RealFft::inverse(const std::vector<std::complex<double>>& spectrum) {
    auto* c = static_cast<fftw_complex*>(complex_);
    for (std::size_t k = 0; k < bins(); ++k) {
        const std::complex<double> v = k < spectrum.size() ? spectrum[k] : 0.0;
        c[k][0] = v.real();
        c[k][1] = v.imag();
    }
    // c2r destroys its input; the buffer is refilled on every call.
    fftw_execute(static_cast<fftw_plan>(inverse_plan_));
    return std::vector<double>(real_, real_ + n_);
}

std::size_t fft_size(std::size_t n) {
    for (std::size_t m = std::max<std::size_t>(n, 1);; ++m) {
        std::size_t r = m;
        for (std::size_t p : {2u, 3u, 5u})
            while (r % p == 0) r /= p;
        if (r == 1) return m;
    }
}

}  // namespace freestand::motion
