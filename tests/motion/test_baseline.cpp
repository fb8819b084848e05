// The displacement-aware baseline correction (src/motion/baseline.hpp): exact rest at both ends,
// less peak displacement than the classic two-pulse correction, and no change where none is due.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <thread>
#include <vector>

#include "core/measures.hpp"
#include "core/units.hpp"
#include "motion/baseline.hpp"
#include "motion/criteria.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_motion_test_baseline {

using namespace freestand;

namespace {

constexpr double kDt_s = 0.005;
constexpr std::size_t kSamples = 4001;  // 20 s

// Band-limited noise in a 2-12 s window with a drift: a raw record that does not end at rest.
std::vector<double> drifting_record() {
    std::mt19937_64 rng(11);
    std::normal_distribution<double> n01(0.0, 1.0);
    std::vector<double> a(kSamples, 0.0), smooth(kSamples, 0.0);
    for (double& x : a) x = n01(rng);
    for (std::size_t i = 10; i < kSamples; ++i) {
        double s = 0.0;
        for (std::size_t k = 0; k < 10; ++k) s += a[i - k];
        const double t = static_cast<double>(i) * kDt_s;
        smooth[i] = (t > 2.0 && t < 12.0 ? 0.8 : 0.05) * s + 0.02;
    }
    return smooth;
}

double peak_abs(const std::vector<double>& v) {
    double p = 0.0;
    for (double x : v) p = std::max(p, std::abs(x));
    return p;
}

// The classic correction: two Gaussian velocity steps sized to zero the final velocity and
// displacement, nothing else.
std::vector<double> two_pulse_correction(std::vector<double> a) {
    const motion::EndWeights ends = motion::end_weights(kSamples, kDt_s);
    std::array<std::vector<double>, 2> p;
    const auto pulses = motion::BaselineCorrector::pulses(static_cast<double>(kSamples - 1) * kDt_s);
    for (std::size_t k = 0; k < 2; ++k) {
        p[k].assign(kSamples, 0.0);
        motion::add_wavelet(pulses[k], 1.0, kDt_s, p[k]);
    }
    auto dot = [](const std::vector<double>& x, const std::vector<double>& y) {
        double s = 0.0;
        for (std::size_t i = 0; i < x.size(); ++i) s += x[i] * y[i];
        return s;
    };
    const double v = dot(ends.velocity, a), d = dot(ends.displacement, a);
    const double pv0 = dot(ends.velocity, p[0]), pv1 = dot(ends.velocity, p[1]);
    const double pd0 = dot(ends.displacement, p[0]), pd1 = dot(ends.displacement, p[1]);
    const double det = pv0 * pd1 - pv1 * pd0;
    const double c0 = (-v * pd1 + d * pv1) / det, c1 = (-d * pv0 + v * pd0) / det;
    for (std::size_t i = 0; i < kSamples; ++i) a[i] += c0 * p[0][i] + c1 * p[1][i];
    return a;
}

}  // namespace

TEST_CASE("baseline correction: the record starts and ends at rest exactly", "[motion][baseline]") {
    std::vector<double> a = drifting_record();
    const motion::BaselineCorrector corrector(kSamples, kDt_s);
    corrector.correct(a);
    const std::vector<double> v = core::velocity_mps(a, kDt_s);
    const std::vector<double> d = core::displacement_m(a, kDt_s);
    CHECK(std::abs(v.back()) < 1e-10);
    CHECK(std::abs(d.back()) < 1e-10);
    // Zero acceleration at both ends but for the exact step's pulses (exp(-16) of their size).
    CHECK(std::abs(a.front()) < 1e-6 * peak_abs(a));
    CHECK(std::abs(a.back()) < 1e-6 * peak_abs(a));
    // The end tapers leave the first and last second smooth: no step larger than the record's.
    CHECK(std::abs(a[1] - a[0]) < 1e-3 * peak_abs(a));
}

TEST_CASE("baseline correction: far less peak displacement than two velocity steps",
          "[motion][baseline]") {
    const std::vector<double> raw = drifting_record();
    std::vector<double> ours = raw;
    motion::BaselineCorrector(kSamples, kDt_s).correct(ours);
    const std::vector<double> classic = two_pulse_correction(raw);
    const double pgd_ours = peak_abs(core::displacement_m(ours, kDt_s));
    const double pgd_classic = peak_abs(core::displacement_m(classic, kDt_s));
    INFO("PGD ours " << pgd_ours << " m, two pulses " << pgd_classic << " m");
    CHECK(pgd_ours < 0.5 * pgd_classic);
    CHECK(std::abs(core::displacement_m(classic, kDt_s).back()) < 1e-9);
}

TEST_CASE("baseline correction: a burst already at rest is left as it is", "[motion][baseline]") {
    // A 5 Hz burst in 8-12 s whose velocity and displacement return to zero: nothing to correct.
    std::vector<double> a(kSamples, 0.0);
    for (std::size_t i = 0; i < kSamples; ++i) {
        const double t = static_cast<double>(i) * kDt_s;
        if (t > 8.0 && t < 12.0)
            a[i] = std::pow(std::sin(units::pi * (t - 8.0) / 4.0), 2) *
                   std::sin(units::two_pi * 5.0 * t);
    }
    std::vector<double> corrected = a;
    motion::BaselineCorrector(kSamples, kDt_s).correct(corrected);
    double change = 0.0;
    for (std::size_t i = 0; i < kSamples; ++i) change = std::max(change, std::abs(corrected[i] - a[i]));
    CHECK(change < 1e-3 * peak_abs(a));
}

TEST_CASE("a shared corrector corrects as a fresh one, bit for bit, from several threads",
          "[motion][baseline]") {
    const std::vector<double> raw = drifting_record();
    std::vector<double> fresh = raw;
    motion::BaselineCorrector(kSamples, kDt_s).correct(fresh);
    const auto shared = motion::BaselineCorrector::shared(kSamples, kDt_s);
    CHECK(motion::BaselineCorrector::shared(kSamples, kDt_s) == shared);
    // Other lengths in between: the last few are kept, and one in use stays alive.
    for (std::size_t n : {std::size_t{1001}, std::size_t{2001}, std::size_t{3001},
                          std::size_t{4002}, std::size_t{4003}})
        CHECK(motion::BaselineCorrector::shared(n, kDt_s) != nullptr);
    std::vector<std::vector<double>> out(4, raw);
    std::vector<std::thread> threads;
    for (auto& a : out)
        threads.emplace_back(
            [&a] { motion::BaselineCorrector::shared(kSamples, kDt_s)->correct(a); });
    for (auto& t : threads) t.join();
    std::vector<double> again = raw;
    shared->correct(again);
    CHECK(again == fresh);
    for (const auto& a : out) CHECK(a == fresh);
}

}  // namespace freestand_test_motion_test_baseline
