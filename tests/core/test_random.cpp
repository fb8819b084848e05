// The seed mixers of core/random.hpp: every stream seed of the project is one of these.
#include <catch2/catch.hpp>
#include <cstdint>

#include "core/random.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_core_test_random {

namespace core = freestand::core;

TEST_CASE("sequence_seed is the k-th output of a splitmix64 generator started at the seed", "[core][rng]") {
    // splitmix64 as a generator (Steele, Lea & Flood 2014): the state advances by gamma, each
    // output is the mix of the state before the advance.
    const std::uint64_t seed = 20240601;
    std::uint64_t state = seed;
    for (std::uint64_t k = 0; k < 5; ++k) {
        CHECK(core::sequence_seed(seed, k) == core::splitmix64(state));
        state += core::splitmix64_gamma;
    }
}

TEST_CASE("component_seed separates components and retries of one seed", "[core][rng]") {
    CHECK(core::component_seed(7, 0, 0) == core::splitmix64(7));
    CHECK(core::component_seed(7, 1, 0) == core::splitmix64(7 ^ core::splitmix64_gamma));
    CHECK(core::component_seed(7, 0, 1) != core::component_seed(7, 1, 0));
    CHECK(core::component_seed(7, 2, 3) != core::component_seed(7, 3, 2));
}

}  // namespace freestand_test_core_test_random
