// Settled decisions (docs/methods.md s.6 step 4): the bootstrap of a level's decision, its seed
// determinism, and a level that grows its sets or fails unsettled at the cap.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <filesystem>
#include <string>
#include <vector>

#include "assess/level_runs.hpp"
#include "assess/pipeline.hpp"
#include "assess/settle.hpp"
#include "assess/verdict.hpp"
#include "support/paths.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_assess_test_settle {

namespace fs = std::filesystem;
using namespace freestand::assess;

namespace {

constexpr double allowable = 0.05;
constexpr double fs_required = 1.5;

// The same values bit for bit (an overturned set's NaN included).
bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() &&
           std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// A level the screen failed, decided by a rigid simulation whose sets slide the given peaks.
LevelResult sliding_level(const std::vector<double>& slide_m) {
    LevelResult l;
    l.screen.passed = false;
    Simulation s;
    s.histories = static_cast<int>(slide_m.size());
    s.slide_m = stats_of(slide_m);
    s.rock_over_alpha = stats_of(std::vector<double>(slide_m.size(), 0.0));
    s.rock_rad = stats_of(std::vector<double>(slide_m.size(), 0.0));
    s.overturned_sets.assign(slide_m.size(), 0);
    l.simulation = s;
    l.verdict = decide_level(l, allowable, fs_required);
    return l;
}

std::vector<std::size_t> all_of(std::size_t n) {
    std::vector<std::size_t> v(n);
    for (std::size_t k = 0; k < n; ++k) v[k] = k;
    return v;
}

}  // namespace

TEST_CASE("the decision redone on all sets is the level's decision", "[assess][settle]") {
    const LevelResult pass = sliding_level(std::vector<double>(30, 0.02));
    CHECK(passes(pass.verdict));
    CHECK(passes_on(pass, all_of(30), allowable, fs_required));
    std::vector<double> high(30, 0.02);
    for (int k = 0; k < 10; ++k) high[static_cast<std::size_t>(k)] = 0.08;  // 10 of 30 beyond
    const LevelResult fail = sliding_level(high);
    CHECK_FALSE(passes(fail.verdict));  // the 26th smallest is 0.08
    CHECK_FALSE(passes_on(fail, all_of(30), allowable, fs_required));
    // The sets beyond the allowable alone pass nothing; those below alone pass.
    CHECK(passes_on(fail, std::vector<std::size_t>(30, 20), allowable, fs_required));
}

TEST_CASE("a clear decision is settled, a borderline one is not", "[assess][settle]") {
    const Settling clear = settle(sliding_level(std::vector<double>(30, 0.02)), 7, allowable,
                                  fs_required);
    CHECK(clear.settled_fraction == 1.0);
    CHECK(clear.settled);
    CHECK(clear.n_sets == 30);
    CHECK(clear.resamples == bootstrap_resamples);
    // 4 of 30 sets beyond the allowable: the 26th smallest is below it, so the level passes,
    // but a resample holding 5 or more of them fails (binomial(30, 4/30): P = 0.37).
    std::vector<double> edge(30, 0.02);
    for (int k = 0; k < 4; ++k) edge[static_cast<std::size_t>(k)] = 0.08;
    const LevelResult l = sliding_level(edge);
    CHECK(passes(l.verdict));
    const Settling s = settle(l, 7, allowable, fs_required);
    CHECK_FALSE(s.settled);
    CHECK(s.settled_fraction == Approx(0.63).margin(0.04));
    // The same seed gives the same fraction; another seed a close one.
    CHECK(settle(l, 7, allowable, fs_required).settled_fraction == s.settled_fraction);
    CHECK(settle(l, 8, allowable, fs_required).settled_fraction ==
          Approx(s.settled_fraction).margin(0.05));
}

TEST_CASE("an overturned set fails every resample that holds it", "[assess][settle]") {
    LevelResult l = sliding_level(std::vector<double>(30, 0.0));
    l.simulation->overturned_sets[3] = 1;
    l.simulation->overturned = 1;
    l.verdict = decide_level(l, allowable, fs_required);
    CHECK(l.verdict.failure == Failure::overturns);
    // P(a resample of 30 holds set 3) = 1 - (29/30)^30 = 0.64: the failure is not settled.
    const Settling s = settle(l, 11, allowable, fs_required);
    CHECK(s.settled_fraction == Approx(1.0 - std::pow(29.0 / 30.0, 30)).margin(0.03));
    CHECK_FALSE(s.settled);
}

TEST_CASE("a pass of a level that can uplift is settled only once its sets bound the overturn "
          "rate at 5%",
          "[assess][settle]") {
    // No overturn in any set: every resample agrees, yet 0 of N bounds the rate only below
    // 1 - 0.025^(1/N) (Clopper-Pearson 95%): 11.6% at 30, 5.06% at 71, 4.99% at 72.
    auto rocking = [](std::size_t n) {
        LevelResult l = sliding_level(std::vector<double>(n, 0.0));
        l.initiation.mode = Mode::rock;
        return l;
    };
    const Settling at30 = settle(rocking(30), 5, allowable, fs_required);
    CHECK(at30.settled_fraction == 1.0);
    REQUIRE(at30.overturn_rate_upper.has_value());
    CHECK(*at30.overturn_rate_upper == Approx(1.0 - std::pow(0.025, 1.0 / 30.0)));
    CHECK_FALSE(at30.settled);
    CHECK_FALSE(settle(rocking(71), 5, allowable, fs_required).settled);
    const Settling at72 = settle(rocking(72), 5, allowable, fs_required);
    CHECK(at72.settled);
    CHECK(*at72.overturn_rate_upper == Approx(0.04994).margin(1e-5));
    CHECK(not_settled_text(at30, true) ==
          "not settled: no overturn in N = 30 sets (cap) bounds the overturn rate only below "
          "11.6% (Clopper-Pearson 95%; 5% needed)");
    // A level that only slides cannot overturn: 30 sets settle it, with no bound.
    const Settling sliding = settle(sliding_level(std::vector<double>(30, 0.0)), 5, allowable,
                                    fs_required);
    CHECK(sliding.settled);
    CHECK_FALSE(sliding.overturn_rate_upper.has_value());
    // A failing level is not bounded: its failure is what the bootstrap settles.
    LevelResult failing = rocking(30);
    failing.simulation->slide_m = stats_of(std::vector<double>(30, 0.08));
    failing.verdict = decide_level(failing, allowable, fs_required);
    REQUIRE_FALSE(passes(failing.verdict));
    CHECK_FALSE(settle(failing, 5, allowable, fs_required).overturn_rate_upper.has_value());
}

TEST_CASE("a flexible body is held to the overturn bound once its base lifted in some set",
          "[assess][settle]") {
    LevelResult l = sliding_level(std::vector<double>(30, 0.0));
    l.flexible_simulation = FlexibleSimulation{};
    l.flexible_simulation->sim = *l.simulation;
    CHECK_FALSE(can_overturn(l));
    CHECK(settle(l, 5, allowable, fs_required).settled);
    l.flexible_simulation->uplifted = 1;
    CHECK(can_overturn(l));
    CHECK_FALSE(settle(l, 5, allowable, fs_required).settled);
    // The 3D body runs only where a direction can uplift: it holds the level to the bound too.
    LevelResult b = sliding_level(std::vector<double>(30, 0.0));
    b.body3d = Body3dLevel{};
    CHECK_FALSE(can_overturn(b));
    b.body3d->ran = true;
    CHECK(can_overturn(b));
}

TEST_CASE("evaluate_settled grows an unsettled level by batches up to the cap, then fails it",
          "[assess][settle]") {
    Case c = read_case(fs::path(freestand::test::source_dir()) / "cases" / "glovebox-single.toml");
    c = with_pga_levels(c, {0.3});
    c.options.histories_per_level = 3;
    c.options.max_histories_per_level = 3;
    c.options.search_materials = false;
    // The allowable slide between the least and the largest biaxial peak of the 3 sets: a
    // resample without the largest passes, one with it fails, so the level cannot settle.
    {
        const AssessmentResult first = assess(c);
        REQUIRE(first.levels.at(0).biaxial.has_value());
        const std::vector<double>& peaks = first.levels[0].biaxial->slide_m.values;
        const auto [lo, hi] = std::minmax_element(peaks.begin(), peaks.end());
        REQUIRE(*lo < *hi);
        c.component.allowable_slide_m = 0.5 * (*lo + *hi);
    }
    const AssessmentResult r = assess(c);
    CHECK_FALSE(r.levels.at(0).settling->settled);
    for (const LevelResult& l : r.levels) {
        INFO(to_string(l.direction));
        REQUIRE(l.settling.has_value());
        CHECK(l.settling->n_sets == 3);
        CHECK(l.settling->rounds == 1);
        if (!l.settling->settled) {
            CHECK(l.verdict.failure == Failure::not_settled);
            CHECK(l.verdict.margin_basis.rfind("not settled: ", 0) == 0);
        }
    }
    // With room to grow, a PGA level unsettled in either direction on 3 sets takes a batch more
    // in both (the biaxial run joins them): 30, or up to the cap, here 6.
    c.options.max_histories_per_level = 6;
    const AssessmentResult grown = assess(c);
    for (const LevelResult& l : grown.levels) {
        CHECK(l.settling->n_sets == 6);
        CHECK(l.settling->rounds == 2);
    }
    // The grown level kept its first 3 sets' runs and simulated the new ones: its peaks are the
    // bits of a level that ran all 6 sets from the start.
    c.options.histories_per_level = grown.levels[0].settling->n_sets;
    c.options.max_histories_per_level = c.options.histories_per_level;
    const AssessmentResult direct = assess(c);
    REQUIRE(direct.levels.size() == grown.levels.size());
    for (std::size_t i = 0; i < grown.levels.size(); ++i) {
        const LevelResult& a = grown.levels[i];
        const LevelResult& b = direct.levels[i];
        REQUIRE(a.simulation.has_value() == b.simulation.has_value());
        if (!a.simulation) continue;
        CHECK(same_bits(a.simulation->slide_m.values, b.simulation->slide_m.values));
        CHECK(same_bits(a.simulation->rock_over_alpha.values, b.simulation->rock_over_alpha.values));
        REQUIRE(a.flexible_simulation.has_value() == b.flexible_simulation.has_value());
        if (a.flexible_simulation)
            CHECK(same_bits(a.flexible_simulation->sim.rock_over_alpha.values,
                            b.flexible_simulation->sim.rock_over_alpha.values));
        REQUIRE(a.biaxial.has_value() == b.biaxial.has_value());
        if (a.biaxial) CHECK(same_bits(a.biaxial->slide_m.values, b.biaxial->slide_m.values));
    }
}

TEST_CASE("a level's kept runs are made once per set and model", "[assess][settle]") {
    LevelRuns runs;
    int made = 0;
    const auto make = [&made] { return static_cast<double>(++made); };
    RunTable<double>& t = runs.biaxial(2);
    CHECK(remembered(&t, 1, make) == 1.0);
    CHECK(remembered(&t, 1, make) == 1.0);
    // Growing the table keeps what it holds.
    RunTable<double>& grown = runs.biaxial(5);
    CHECK(&grown == &t);
    CHECK(remembered(&grown, 1, make) == 1.0);
    CHECK(remembered(&grown, 4, make) == 2.0);
    CHECK(remembered<double>(nullptr, 4, make) == 3.0);
    // Directions and slots are tables of their own.
    CHECK(&runs.rigid(Direction::x, 0, 3) != &runs.rigid(Direction::y, 0, 3));
    CHECK(&runs.rigid(Direction::x, 0, 3) != &runs.rigid(Direction::x, 1, 3));
    CHECK(runs.flexible(Direction::y, 2, 7).size() == 7);
}

TEST_CASE("the glove box's verdict and material do not follow the seed",
          "[assess][settle][seed]") {
    // At 0.4 g, where the base and the materials decide (docs/methods.md s.6 steps 3, 4 and 7);
    // seed 4 once turned HDPE from a pass into a failure. The goal is left out: the levels are
    // what the seed moved.
    Case c = read_case(fs::path(freestand::test::source_dir()) / "cases" / "glovebox-single.toml");
    c = with_pga_levels(c, {0.4});
    c.site.dbe_pga_g.reset();
    std::optional<AssessmentResult> first;
    for (const std::uint64_t seed : {std::uint64_t{1}, std::uint64_t{4}}) {
        INFO("seed " << seed);
        c.options.seed = seed;
        const AssessmentResult r = assess(c);
        if (!first) {
            first = r;
            continue;
        }
        CHECK(r.overall.verdict.kind == first->overall.verdict.kind);
        CHECK(r.upgrade.recommended == first->upgrade.recommended);
        REQUIRE(r.upgrade.trials.size() == first->upgrade.trials.size());
        for (std::size_t i = 0; i < r.upgrade.trials.size(); ++i) {
            INFO(r.upgrade.trials[i].material);
            CHECK(passes(r.upgrade.trials[i].governing.verdict) ==
                  passes(first->upgrade.trials[i].governing.verdict));
        }
    }
}

TEST_CASE("the cabinet on steel fails at 0.3 g under a seed whose first 30 sets hold no "
          "overturn",
          "[assess][settle][seed]") {
    // The 3D body overturns the cabinet in a few percent of the sets at 0.3 g. Seed 12's first
    // 30 sets hold none, which the bootstrap alone settled as a pass (margin 8.19) while the
    // shipped seed 1 fails (reports/cabinet-user-target); the overturn bound grows the sets
    // until one shows.
    Case c = read_case(fs::path(freestand::test::source_dir()) / "cases" /
                       "cabinet-user-target.toml");
    c = with_pga_levels(c, {0.3});
    c.options.search_materials = false;
    // At 60 sets the level fails either way: an overturn shows, or 0 of 60 bounds the rate only
    // below 6.0%.
    c.options.max_histories_per_level = 60;
    c.options.seed = 12;
    {
        const AssessmentResult r = assess(c);
        const LevelResult& x = r.levels.at(0);
        REQUIRE(x.body3d.has_value());
        CHECK(x.body3d->ran);
        CHECK(x.settling->n_sets > 30);
        CHECK_FALSE(passes(r.overall.verdict));
    }
}

}  // namespace freestand_test_assess_test_settle
