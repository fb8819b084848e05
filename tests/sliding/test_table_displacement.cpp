// DeltaD of the energy method: peak displacement after a zero-phase high-pass (docs/methods.md s.4).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/errors.hpp"
#include "sliding/table_displacement.hpp"
#include "support/sampled_record.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_sliding_test_table_displacement {

using namespace freestand;

namespace {
// Samples from t = 0 to duration_s inclusive.
std::size_t samples(double duration_s, double dt_s) {
    return static_cast<std::size_t>(std::round(duration_s / dt_s)) + 1;
}

core::Record sine(double amplitude_mps2, double f_hz, double duration_s, double dt_s = 0.005) {
    const double w = 2.0 * std::numbers::pi * f_hz;
    return freestand::test::sampled_record(
        dt_s, samples(duration_s, dt_s), [&](double t) { return amplitude_mps2 * std::sin(w * t); });
}
}  // namespace

TEST_CASE("the zero-phase response is one half at the corner and goes as f^4 below it",
          "[sliding][table_displacement]") {
    CHECK(sliding::highpass_gain(0.5, 0.5) == Approx(0.5));
    CHECK(sliding::highpass_gain(5.0, 0.5) == Approx(1.0 / (1.0 + 1e-4)));
    CHECK(sliding::highpass_gain(0.1, 0.5) == Approx(1.0 / (1.0 + std::pow(5.0, 4))));
    CHECK(sliding::highpass_gain(0.0, 0.5) == 0.0);
}

// Acceleration of the drift-free displacement d(t) = D sin^2(pi t / T) sin(w t), exactly.
static core::Record windowed_burst(double d_m, double f_hz, double duration_s, double dt_s = 0.005) {
    const double w = 2.0 * std::numbers::pi * f_hz;
    const double u = 2.0 * std::numbers::pi / duration_s;
    return freestand::test::sampled_record(dt_s, samples(duration_s, dt_s), [&](double t) {
        const double win = (1.0 - std::cos(u * t)) / 2.0;
        const double win1 = u * std::sin(u * t) / 2.0;
        const double win2 = u * u * std::cos(u * t) / 2.0;
        return d_m * (win2 * std::sin(w * t) + 2.0 * win1 * w * std::cos(w * t) -
                      win * w * w * std::sin(w * t));
    });
}

TEST_CASE("a drift-free burst well above the corner keeps its displacement",
          "[sliding][table_displacement]") {
    // d = 20 mm at 4 Hz under a 20 s window: the 0.5 Hz high-pass scales it by its gain at
    // 4 Hz (1 - 2.4e-4), the window's spectrum being narrow around 4 Hz.
    const core::Record burst = windowed_burst(0.020, 4.0, 20.0);
    double sampled_peak_m = 0.0;  // the crests fall between samples
    for (std::size_t i = 0; i < burst.size(); ++i) {
        const double t = burst.time_s(i);
        sampled_peak_m = std::max(sampled_peak_m,
                                  std::abs(0.020 * std::pow(std::sin(std::numbers::pi * t / 20.0), 2) *
                                           std::sin(2.0 * std::numbers::pi * 4.0 * t)));
    }
    const double d = sliding::highpass_peak_displacement_m(burst, 0.5);
    CHECK(d == Approx(sampled_peak_m * sliding::highpass_gain(4.0, 0.5)).epsilon(1e-4));
}

TEST_CASE("a sine started from rest loses its drift but keeps its oscillation",
          "[sliding][table_displacement]") {
    // 20 s of 1 m/s^2 at 4 Hz from rest: the raw double integral drifts by the mean velocity
    // A / w (0.8 m over 20 s); high-passed, the oscillation A / w^2 remains plus the filtered
    // kinks of that drift at start and end, far below the drift.
    const double w = 2.0 * std::numbers::pi * 4.0;
    const double d = sliding::highpass_peak_displacement_m(sine(1.0, 4.0, 20.0), 0.5);
    CHECK(d > 1.0 / (w * w));
    CHECK(d < 0.01 * 20.0 / w);
}

TEST_CASE("content below the corner is removed", "[sliding][table_displacement]") {
    // 0.1 Hz carries 2.5 m of displacement per m/s^2; at a 0.5 Hz corner almost none is left.
    const double raw = 1.0 / std::pow(2.0 * std::numbers::pi * 0.1, 2);
    const double d = sliding::highpass_peak_displacement_m(sine(1.0, 0.1, 40.0), 0.5);
    CHECK(d < 0.01 * raw);
    // The corner itself is settable: at 0.05 Hz the 0.1 Hz sine keeps most of it.
    CHECK(sliding::highpass_peak_displacement_m(sine(1.0, 0.1, 40.0), 0.05) > 0.5 * raw);
}

TEST_CASE("a corner outside (0, Nyquist) is an input error naming the key",
          "[sliding][table_displacement]") {
    const core::Record r = sine(1.0, 4.0, 2.0);
    for (double bad : {0.0, -1.0, 100.0, std::nan("")}) {
        try {
            sliding::highpass_peak_displacement_m(r, bad);
            FAIL("no error");
        } catch (const InputError& e) {
            CHECK(std::string(e.what()).find("energy_highpass_hz") != std::string::npos);
        }
    }
}

}  // namespace freestand_test_sliding_test_table_displacement
