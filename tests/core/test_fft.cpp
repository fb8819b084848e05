// RealFft's plans are made once per length and direction and shared by every object and thread:
// each transform must be the one a plan made for it alone gives, bit for bit.
#include <fftw3.h>

#include <catch2/catch.hpp>
#include <complex>
#include <random>
#include <thread>
#include <vector>

#include "core/random.hpp"
#include "core/fft.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_core_test_fft {

using namespace freestand;
using namespace freestand::core;

namespace {

std::vector<double> noise(std::size_t n, std::uint64_t seed) {
    std::mt19937_64 g(seed);
    std::vector<double> x(n);
    for (double& v : x) v = core::uniform01(g()) - 0.5;
    return x;
}

/// Forward and inverse transforms of x through plans made here for this call alone (FFTW's
/// planner serialised by the caller).
struct Fresh {
    std::vector<std::complex<double>> spectrum;
    std::vector<double> back;
};

Fresh fresh_transforms(const std::vector<double>& x) {
    const std::size_t n = x.size();
    double* real = fftw_alloc_real(n);
    fftw_complex* c = fftw_alloc_complex(n / 2 + 1);
    const fftw_plan forward = fftw_plan_dft_r2c_1d(static_cast<int>(n), real, c, FFTW_ESTIMATE);
    const fftw_plan inverse = fftw_plan_dft_c2r_1d(static_cast<int>(n), c, real, FFTW_ESTIMATE);
    std::copy(x.begin(), x.end(), real);
    fftw_execute(forward);
    Fresh out;
    for (std::size_t k = 0; k <= n / 2; ++k) out.spectrum.emplace_back(c[k][0], c[k][1]);
    fftw_execute(inverse);
    out.back.assign(real, real + n);
    fftw_destroy_plan(forward);
    fftw_destroy_plan(inverse);
    fftw_free(real);
    fftw_free(c);
    return out;
}

}  // namespace

TEST_CASE("shared FFT plans used from several threads give a fresh plan's bits", "[core][fft]") {
    // 4050 = fft_size(4001) (a 20 s record at 5 ms) and 40000 (the PSD's 0.005 Hz bins); 1000
    // and 4050 again from other threads at the same time.
    const std::vector<std::size_t> lengths{4050, 40000, 1000, 4050, 40000, 1000};
    std::vector<std::vector<double>> inputs;
    std::vector<Fresh> expected;
    for (std::size_t k = 0; k < lengths.size(); ++k) {
        inputs.push_back(noise(lengths[k], 100 + k));
        expected.push_back(fresh_transforms(inputs.back()));
    }
    std::vector<std::vector<std::complex<double>>> spectra(lengths.size());
    std::vector<std::vector<double>> backs(lengths.size());
    std::vector<std::thread> threads;
    for (std::size_t k = 0; k < lengths.size(); ++k)
        threads.emplace_back([&, k] {
            for (int repeat = 0; repeat < 3; ++repeat) {
                RealFft fft(lengths[k]);
                spectra[k] = fft.forward(inputs[k]);
                backs[k] = fft.inverse(spectra[k]);
            }
        });
    for (auto& t : threads) t.join();
    for (std::size_t k = 0; k < lengths.size(); ++k) {
        INFO("length " << lengths[k]);
        CHECK(spectra[k] == expected[k].spectrum);
        CHECK(backs[k] == expected[k].back);
    }
}

TEST_CASE("RealFft zero-pads, cuts and round-trips as documented", "[core][fft]") {
    RealFft fft(8);
    CHECK(fft.size() == 8);
    CHECK(fft.bins() == 5);
    const auto x = fft.forward({1.0, 2.0});  // zero-padded to 8
    CHECK(x[0] == std::complex<double>(3.0, 0.0));
    CHECK(x[4] == std::complex<double>(-1.0, 0.0));
    const auto y = fft.inverse(fft.forward({1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0}));
    for (std::size_t j = 0; j < 8; ++j) CHECK(y[j] == Approx(8.0 * static_cast<double>(j + 1)));
    CHECK(fft_size(4001) == 4050);
    CHECK(fft_size(40000) == 40000);
}

}  // namespace freestand_test_core_test_fft
