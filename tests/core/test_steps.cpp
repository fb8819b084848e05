// The two rounding rules of the stepping engines (core/steps.hpp).
#include <catch2/catch.hpp>
#include <cmath>

#include "core/steps.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_core_test_steps {

namespace core = freestand::core;

TEST_CASE("steps_covering counts a whole number of steps written in binary as that number", "[core][steps]") {
    CHECK(core::steps_covering(5.0 / 0.01) == 500.0);
    CHECK(core::steps_covering(0.84 * 25.0) == 21.0);
    CHECK(core::steps_covering(0.047000000001 * 1000.0) == 47.0);
    CHECK(core::steps_covering(500.001) == 501.0);
}

TEST_CASE("step_to_sample ends a step on a sample it would miss by a rounding only", "[core][steps]") {
    const double sample_t = 32.0;
    const double h = 0.005;
    // Short of the sample by an ulp of t: the step ends on it.
    const double t_near = std::nextafter(sample_t - h, 0.0);
    CHECK(t_near + core::step_to_sample(t_near, h, sample_t) == sample_t);
    // Short by a microsecond: a real step, kept.
    const double t_far = sample_t - h - 1e-6;
    CHECK(core::step_to_sample(t_far, h, sample_t) == h);
}

}  // namespace freestand_test_core_test_steps
