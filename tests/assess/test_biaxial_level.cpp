// Biaxial sliding in assess (docs/methods.md s.10): a simulated level whose block
// slides without rocking takes its sliding demand from both horizontal components at once; a
// rocking level keeps the planar model and says why. The JSON: tests/report/test_biaxial_json.cpp.
#include <catch2/catch.hpp>
#include <algorithm>
#include <filesystem>

#include "support/shipped_case.hpp"
#include "assess/biaxial_level.hpp"
#include "assess/body3d_level.hpp"
#include "assess/level.hpp"
#include "assess/pipeline.hpp"
#include "assess/verdict.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_assess_test_biaxial_level {

using namespace freestand;
using namespace freestand::assess;
using freestand::test::shipped_case;
using freestand::test::trail_has;

namespace {

// The shipped glove box carries its fixed-base frequency and free-rocking bands, which raise the
// flexible-body flag, and the flexible model then decides its levels; without them it is the
// rigid body whose sliding the biaxial model decides.
Case rigid(Case c) {
    c.component.fixed_base_frequency_hz.reset();
    c.component.x.free_rocking_band_hz.reset();
    c.component.y.free_rocking_band_hz.reset();
    return c;
}

}  // namespace

TEST_CASE("a sliding level's verdict uses the biaxial peak, the planar stays for comparison",
          "[assess][biaxial]") {
    // The glove box slides at 0.2 g (mu_s 0.12 at the lower bound, tan(alpha) well above).
    const AssessmentResult r = assess::assess(rigid(shipped_case("glovebox-single.toml", {0.2}, 2)));
    REQUIRE(r.levels.size() == 2);
    const LevelResult& x = r.levels.at(0);
    const LevelResult& y = r.levels.at(1);
    for (const LevelResult* l : {&x, &y}) {
        INFO(to_string(l->direction));
        REQUIRE(l->simulation.has_value());
        REQUIRE(l->biaxial.has_value());
        CHECK(l->biaxial->ran);
        CHECK(l->model == biaxial_model_name);
        CHECK(l->model_reason.find("slides without rocking") != std::string::npos);
        CHECK(l->verdict.decided_by == Model::simulation_biaxial_slide);
        // Two histories: the 84th percentile is the larger (ceil(0.84 x 2) = 2nd smallest); the
        // margin is the allowable over the biaxial peak.
        CHECK(l->simulation->governing(l->biaxial->slide_m) == l->biaxial->slide_m.max);
        CHECK(*l->verdict.margin ==
              Approx(r.input.component.allowable_slide_m / l->biaxial->slide_m.max).epsilon(1e-12));
        CHECK(l->biaxial->slide_m.max != l->simulation->slide_m.max);
        CHECK(trail_has(*l, "biaxial sliding (h1 along x, h2 along y"));
        CHECK(trail_has(*l, "model: biaxial sliding"));
    }
    // One biaxial run per PGA level, shared by x and y; the ratio is to the larger planar peak.
    CHECK(x.biaxial->slide_m.mean == y.biaxial->slide_m.mean);
    const double planar = std::max(x.simulation->slide_m.max, y.simulation->slide_m.max);
    CHECK(x.biaxial->planar_governing_m == planar);
    CHECK(*x.biaxial->ratio == Approx(x.biaxial->slide_m.max / planar).epsilon(1e-12));
    CHECK(x.biaxial->planar_direction ==
          (x.simulation->slide_m.max >= y.simulation->slide_m.max ? Direction::x : Direction::y));
}

TEST_CASE("a rocking level does not take the biaxial model and says why",
          "[assess][biaxial]") {
    // The slender TS1 block rocks at 0.3 g at both friction bounds.
    const AssessmentResult r = assess::assess(shipped_case("block-ts1.toml", {0.3}, 1));
    const LevelResult& x = r.levels.at(0);
    REQUIRE(x.simulation.has_value());
    REQUIRE(x.biaxial.has_value());
    CHECK_FALSE(x.biaxial->ran);
    CHECK(x.biaxial->reason.find("does not slide alone at the sliding bound (mode rock)") !=
          std::string::npos);
    // It can uplift, so the 3D body decides it (tests/assess/test_body3d_level.cpp).
    CHECK(x.model == body3d_model_name);
    CHECK(x.verdict.decided_by != Model::simulation_biaxial_slide);
    CHECK(trail_has(x, "biaxial sliding not run: "));
}

}  // namespace freestand_test_assess_test_biaxial_level
