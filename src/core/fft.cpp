#include "core/fft.hpp"

#include <fftw3.h>

#include <algorithm>
#include <map>
#include <mutex>
#include <new>
#include <utility>

namespace freestand::core {
namespace {

enum class Direction { forward, inverse };

/// The r2c and c2r plans by length, made on first use and kept for the process: planning (even
/// FFTW_ESTIMATE's, which hashes every sub-problem) costs as much as tens of transforms of the
/// length, and a generated set would otherwise plan ten times. Planning is serialised (FFTW's
/// planner is not thread-safe); executing one plan on different arrays from several threads at once
/// is safe with the new-array execute functions, given arrays of the planning arrays' alignment
/// (fftw_alloc_*).
class PlanCache {
  public:
    ~PlanCache() {
        for (const auto& [key, plan] : plans_) fftw_destroy_plan(plan);
    }

    fftw_plan plan(std::size_t n, Direction direction) {
        const std::lock_guard<std::mutex> lock(mutex_);
        const auto key = std::make_pair(n, direction);
        const auto it = plans_.find(key);
        if (it != plans_.end()) return it->second;
        const fftw_plan made = make(n, direction);
        plans_.emplace(key, made);
        return made;
    }

  private:
    std::mutex mutex_;
    std::map<std::pair<std::size_t, Direction>, fftw_plan> plans_;

    static fftw_plan make(std::size_t n, Direction direction) {
        double* real = fftw_alloc_real(n);
        fftw_complex* c = fftw_alloc_complex(n / 2 + 1);
        if (real == nullptr || c == nullptr) {
            fftw_free(real);
            fftw_free(c);
            throw std::bad_alloc();
        }
        const int len = static_cast<int>(n);
        const fftw_plan plan = direction == Direction::forward
                                   ? fftw_plan_dft_r2c_1d(len, real, c, FFTW_ESTIMATE)
                                   : fftw_plan_dft_c2r_1d(len, c, real, FFTW_ESTIMATE);
        fftw_free(real);
        fftw_free(c);
        return plan;
    }
};

fftw_plan plan_for(std::size_t n, Direction direction) {
    static PlanCache cache;
    return cache.plan(n, direction);
}

}  // namespace

RealFft::RealFft(std::size_t n) : n_(n) {
    real_ = fftw_alloc_real(n_);
    complex_ = fftw_alloc_complex(bins());
    if (real_ == nullptr || complex_ == nullptr) {
        fftw_free(real_);
        fftw_free(complex_);
        throw std::bad_alloc();
    }
}

RealFft::~RealFft() {
    fftw_free(real_);
    fftw_free(complex_);
}

std::vector<std::complex<double>> RealFft::forward(const std::vector<double>& x) {
    const std::size_t m = std::min(x.size(), n_);
    std::copy_n(x.begin(), m, real_);
    std::fill(real_ + m, real_ + n_, 0.0);
    if (forward_plan_ == nullptr) forward_plan_ = plan_for(n_, Direction::forward);
    auto* c = static_cast<fftw_complex*>(complex_);
    fftw_execute_dft_r2c(static_cast<fftw_plan>(forward_plan_), real_, c);
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
    if (inverse_plan_ == nullptr) inverse_plan_ = plan_for(n_, Direction::inverse);
    fftw_execute_dft_c2r(static_cast<fftw_plan>(inverse_plan_), c, real_);
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

}  // namespace freestand::core
