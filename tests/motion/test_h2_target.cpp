// TargetSet::horizontal_2: component h2 matched to its own target (per-direction targets,
// README "Case files"); absent, h2 follows the common horizontal target exactly.
#include <catch2/catch.hpp>

#include "motion/motion.hpp"
#include "own_check.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_motion_test_h2_target {

using namespace freestand;

TEST_CASE("h2 matches horizontal_2 when it is set, h1 still matches horizontal",
          "[motion][generate][h2]") {
    motion::TargetSet ts = motion::rg160_targets(0.2);
    ts.horizontal_2 = motion::rg160_targets(0.4).horizontal;
    motion::GenerateOptions o;
    o.components = {"h1", "h2"};
    o.seed = 7;
    const motion::GeneratedSet s = motion::generate_set(ts, o);
    REQUIRE(s.components.size() == 2);
    test::require_srp(s.components[0].record, ts.horizontal);
    test::require_srp(s.components[1].record, *ts.horizontal_2);
    // h2's spectrum is twice h1's target: against the 0.2 g target its ratios are about 2.
    const test::OwnCheck wrong = test::own_check(s.components[1].record, ts.horizontal.psa_5pct);
    CHECK(wrong.min_ratio > 1.7);
}

TEST_CASE("horizontal_2 equal to horizontal reproduces the unset records byte for byte",
          "[motion][generate][h2]") {
    motion::TargetSet one = motion::rg160_targets(0.3);
    motion::TargetSet two = one;
    two.horizontal_2 = one.horizontal;
    motion::GenerateOptions o;
    o.components = {"h1", "h2"};
    o.seed = 11;
    const motion::GeneratedSet a = motion::generate_set(one, o);
    const motion::GeneratedSet b = motion::generate_set(two, o);
    REQUIRE(a.components.size() == b.components.size());
    for (std::size_t i = 0; i < a.components.size(); ++i)
        CHECK(a.components[i].record.accel_mps2 == b.components[i].record.accel_mps2);
}

}  // namespace freestand_test_motion_test_h2_target
