// The tunnel check of two joined units (docs/methods.md s.10) deciding a pair's verdict.
#include <catch2/catch.hpp>

#include <string>

#include "assess/joined.hpp"
#include "assess/pipeline.hpp"
#include "assess/verdict.hpp"

using namespace freestand;
using namespace freestand::assess;

namespace {

// Squat units that only slide (tan(alpha) = 2), the allowable slide far above any demand.
std::string unit(const std::string& name, const std::string& friction) {
    return "[[unit]]\nname = \"" + name +
           "\"\nmass_kg = 400.0\ncg_height_m = 0.5\ncg_to_edge_x_m = [1.0, 1.0]\n"
           "cg_to_edge_y_m = [1.0, 1.0]\n" + friction + "allowable_slide_m = 5.0\n";
}

Case pair_case(const std::string& friction1, const std::string& friction2, double slack_m) {
    return parse_case(unit("A", friction1) + unit("B", friction2) +
                          "[tunnel]\nheight_m = 1.0\nallowable_relative_m = " +
                          std::to_string(slack_m) +
                          "\n[site]\npga_g = [0.3]\n[options]\nhistories_per_level = 1\n"
                          "simulate = \"always\"\n",
                      "pair.toml");
}

}  // namespace

TEST_CASE("joined: units differing in friction unseat a tight tunnel: brace them",
          "[assess][joined]") {
    const Case c = pair_case("mu_s = 0.1\n", "mu_s = 0.3\n", 0.001);
    const AssessmentResult r = assess::assess(c);
    REQUIRE(r.joined);
    const JoinedResult& j = *r.joined;
    REQUIRE(j.levels.size() == 1);
    CHECK(j.levels[0].demand_m > 0.001);
    CHECK_FALSE(j.levels[0].passes);
    CHECK(j.levels[0].model == pair_model_name);
    CHECK_FALSE(j.tunnel_passes);
    CHECK_FALSE(j.passes);
    // The units themselves pass: the tunnel alone decides, and the verdict names the remedy.
    CHECK(passes(j.units[0].overall.verdict));
    CHECK(passes(j.units[1].overall.verdict));
    CHECK(j.verdict.find("tunnel fails at PGA 0.300 g") == 0);
    CHECK(j.verdict.find("brace the units together into one body") != std::string::npos);
    CHECK(j.verdict.find("acceptable") == std::string::npos);
}

TEST_CASE("joined: the same demand with a wide slack passes", "[assess][joined]") {
    const AssessmentResult r = assess::assess(pair_case("mu_s = 0.1\n", "mu_s = 0.3\n", 5.0));
    REQUIRE(r.joined);
    CHECK(r.joined->tunnel_passes);
    CHECK(r.joined->passes);
    REQUIRE(r.joined->levels[0].margin);
    CHECK(*r.joined->levels[0].margin > 1.0);
    CHECK(r.joined->remedy.empty());
}

TEST_CASE("joined: identical units with one friction value move together", "[assess][joined]") {
    const std::string exact = "mu_s = 0.15\nmu_s_range = [0.15, 0.15]\n";
    const AssessmentResult r = assess::assess(pair_case(exact, exact, 0.001));
    REQUIRE(r.joined);
    const TunnelLevel& l = r.joined->levels[0];
    for (const TunnelDirection& d : l.directions) {
        CHECK(d.relative_m.max == 0.0);
        CHECK(d.relative_common_m.max == 0.0);
    }
    CHECK(l.passes);
    CHECK_FALSE(l.margin);  // no relative motion
    CHECK(r.joined->tunnel_passes);
}
