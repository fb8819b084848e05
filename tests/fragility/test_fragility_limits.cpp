// A fragility run's size: its levels and its samples as a whole are bounded before the run
// allocates the samples' list (core/limits.hpp, README Limits).
#include <catch2/catch.hpp>

#include <vector>

#include "fragility/fragility.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_fragility_test_fragility_limits {

using namespace freestand;

namespace {

fragility::Config config_of(std::size_t levels, int samples) {
    fragility::Config cfg;
    for (std::size_t i = 1; i <= levels; ++i) cfg.pga_g.push_back(0.001 * static_cast<double>(i));
    cfg.samples = samples;
    return cfg;
}

}  // namespace

TEST_CASE("levels x samples is bounded, not only each of them", "[fragility][limits]") {
    // 1000 levels and 1e6 samples per level are each within their own limit: 1e9 samples.
    CHECK_THROWS_WITH(fragility::validate(config_of(1000, 1000000)),
                      "samples: the run's samples (levels x samples per level): 1e+09 is above "
                      "the limit 1e+06 (README, Limits)");
    CHECK_THROWS_WITH(fragility::validate(config_of(10, 100001)),
                      "samples: the run's samples (levels x samples per level): 1.00001e+06 is "
                      "above the limit 1e+06 (README, Limits)");
    CHECK_NOTHROW(fragility::validate(config_of(10, 100000)));
    CHECK_NOTHROW(fragility::validate(config_of(1000, 1000)));
}

TEST_CASE("a fragility level near zero is refused", "[fragility][limits]") {
    fragility::Config cfg = config_of(1, 10);
    cfg.pga_g = {1e-310, 0.1};
    CHECK_THROWS_WITH(fragility::validate(cfg),
                      "pga_g: value 1e-310 is out of range; expected [0.001, 3]");
}

}  // namespace freestand_test_fragility_test_fragility_limits
