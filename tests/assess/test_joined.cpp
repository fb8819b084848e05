// The tunnel check of two joined units (docs/methods.md s.10) deciding a pair's verdict.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "assess/histories.hpp"
#include "assess/joined.hpp"
#include "assess/pipeline.hpp"
#include "assess/verdict.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_assess_test_joined {

using namespace freestand;
using namespace freestand::assess;

namespace {

// Squat units that only slide (tan(alpha) = 2), the allowable slide far above any demand.
std::string unit(const std::string& name, const std::string& friction) {
    return "[[unit]]\nname = \"" + name +
           "\"\nmass_kg = 400.0\ncg_height_m = 0.5\ncg_to_edge_x_m = [1.0, 1.0]\n"
           "cg_to_edge_y_m = [1.0, 1.0]\n" + friction + "allowable_slide_m = 5.0\n";
}

Case pair_case(const std::string& friction1, const std::string& friction2, double slack_m,
               int sets = 1) {
    return parse_case(unit("A", friction1) + unit("B", friction2) +
                          "[tunnel]\nheight_m = 1.0\nallowable_relative_m = " +
                          std::to_string(slack_m) +
                          "\n[site]\npga_g = [0.3]\n[options]\nhistories_per_level = " +
                          std::to_string(sets) + "\nsimulate = \"always\"\n",
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

TEST_CASE("joined: the tunnel's decision is settled by a bootstrap of its sets, or fails",
          "[assess][joined][settle]") {
    Case c = pair_case("mu_s = 0.1\n", "mu_s = 0.3\n", 5.0, 3);
    c.options.max_histories_per_level = 3;
    HistoryBank bank(c);
    const TunnelLevel wide = tunnel_level(c, 0, bank);
    CHECK(wide.passes);
    CHECK(wide.settling.n_sets == 3);
    CHECK(wide.settling.resamples == 2000);
    CHECK(wide.settling.settled_fraction == 1.0);
    // Per set the larger relative peak of x and y; the slack between the largest two: the 84th
    // percentile of 3 (the largest) fails, a resample without that set passes (29.6% of them,
    // (2/3)^3), so the decision cannot settle on 3 sets.
    std::vector<double> peak_m(3);
    for (const TunnelDirection& d : wide.directions)
        for (std::size_t k = 0; k < 3; ++k) peak_m[k] = std::max(peak_m[k], d.relative_m.values[k]);
    std::sort(peak_m.begin(), peak_m.end());
    REQUIRE(peak_m[1] < peak_m[2]);
    c.tunnel->allowable_relative_m = 0.5 * (peak_m[1] + peak_m[2]);
    const TunnelLevel capped = tunnel_level(c, 0, bank);
    CHECK_FALSE(capped.passes);
    CHECK_FALSE(capped.settling.settled);
    CHECK(capped.settling.settled_fraction > 0.5);
    CHECK(capped.settling.settled_fraction < 0.95);
    CHECK(capped.text.rfind("not settled: ", 0) == 0);
    // With room to grow it takes a batch more (30, or up to the cap, here 6), keeping the
    // first 3.
    c.options.max_histories_per_level = 6;
    HistoryBank grown_bank(c);
    const TunnelLevel grown = tunnel_level(c, 0, grown_bank);
    CHECK(grown.settling.n_sets == 6);
    CHECK(grown.settling.rounds == 2);
    CHECK(grown.histories == 6);
    for (std::size_t i = 0; i < 2; ++i)
        for (std::size_t k = 0; k < 3; ++k)
            CHECK(grown.directions[i].relative_m.values[k] == capped.directions[i].relative_m.values[k]);
}

}  // namespace freestand_test_assess_test_joined
