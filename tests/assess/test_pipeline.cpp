// The pipeline end to end on small cases (one level, at most one history).
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "support/paths.hpp"
#include "assess/flexible_level.hpp"
#include "assess/level.hpp"
#include "assess/pipeline.hpp"
#include "assess/verdict.hpp"
#include "core/errors.hpp"
#include "core/file_io.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_assess_test_pipeline {

namespace fs = std::filesystem;
using namespace freestand;
using namespace freestand::assess;

namespace {
Case glovebox(const std::vector<double>& pga, int histories) {
    Case c = read_case(fs::path(freestand::test::source_dir()) / "cases" / "glovebox-single.toml");
    c.options.histories_per_level = histories;
    c.options.max_histories_per_level = c.options.histories_per_level;
    return with_pga_levels(c, pga);
}

// The glove box without the flexible-body screen's inputs: the rigid models decide.
Case rigid_glovebox(const std::vector<double>& pga, int histories) {
    Case c = glovebox(pga, histories);
    c.component.fixed_base_frequency_hz.reset();
    c.component.x.free_rocking_band_hz.reset();
    c.component.y.free_rocking_band_hz.reset();
    return c;
}
}  // namespace

TEST_CASE("at rest everywhere: no histories, no simulation", "[assess][pipeline]") {
    const AssessmentResult r = assess::assess(glovebox({0.05}, 5));
    REQUIRE(r.levels.size() == 2);
    CHECK(r.histories_generated == 0);
    CHECK(r.simulations_run == 0);
    CHECK(r.levels.at(0).model.empty());
    CHECK(r.overall.verdict.kind == VerdictKind::acceptable);
    // A = 0.05 / (1 - 0.0333) = 0.05172; margin = lower mu_s / A = 0.12 / 0.05172 = 2.3.
    CHECK(*r.overall.verdict.margin ==
          Approx(0.8 * 0.15 / (0.05 / (1.0 - 0.05 * 2.0 / 3.0))).epsilon(1e-9));
    CHECK_FALSE(r.upgrade.needed);
    CHECK(r.plots.ground_motion.empty());
    CHECK(r.plots.initiation.size() == 2);
}

TEST_CASE("glove box at 0.2 g: the ASCE 4 estimate by hand at the lower friction bound",
          "[assess][pipeline]") {
    const AssessmentResult r = assess::assess(glovebox({0.2}, 1));
    const LevelResult& x = r.levels.at(0);
    CHECK(x.initiation.mode == Mode::slide);
    CHECK(x.initiation_lower.mode == Mode::slide);
    // Bounds of docs/methods.md s.7 around the PVC sheet's 0.15: 0.12 and 0.18.
    CHECK(x.bounds.sliding.mu_s == Approx(0.12));
    CHECK(x.bounds.rocking.mu_s == Approx(0.18));
    CHECK(x.initiation.mu_s == Approx(0.18));
    CHECK(x.sliding.mu_s == Approx(0.12));
    // A_v = 2/3 x 0.2 g: mu_e = 0.12 (1 - 0.4 x 0.13333) = 0.1136, C_s = 2 mu_e g.
    CHECK(x.sliding.mu_e == Approx(0.1136).epsilon(1e-12));
    CHECK(x.sliding.c_s_mps2 == Approx(2.0 * 0.1136 * 9.81).epsilon(1e-12));
    const double w = 2.0 * 3.141592653589793 * *x.sliding.f_es_hz;
    CHECK(*x.sliding.slide_asce_m == Approx(x.sliding.c_s_mps2 / (w * w)).epsilon(1e-12));
    // With mu 0.15 the worked example gives 0.047 m; the lower bound slides further.
    CHECK(*x.sliding.slide_asce_m > 0.047);
    // The ASCE 4 screen fails at 50 mm, so the level is simulated and the simulation governs
    // (biaxially: the block slides without rocking; test_biaxial_level.cpp).
    CHECK_FALSE(x.screen.passed);
    REQUIRE(x.simulation.has_value());
    // The flexible-body flag is raised (fixed-base 7.5 Hz in the band): the flexible model
    // decides, the rigid planar simulation stays beside it (docs/methods.md s.10); the block
    // slides without rocking, so biaxial sliding runs too and the larger sliding demand governs.
    REQUIRE(x.flexible_simulation.has_value());
    REQUIRE(x.biaxial.has_value());
    REQUIRE(x.biaxial->ran);
    const double flex_slide_m = x.flexible_simulation->sim.governing(x.flexible_simulation->sim.slide_m);
    const double biaxial_m = x.flexible_simulation->sim.governing(x.biaxial->slide_m);
    CHECK(x.verdict.decided_by == (biaxial_m > flex_slide_m ? Model::simulation_biaxial_slide
                                                            : Model::simulation_flexible));
    CHECK(*x.verdict.margin == Approx(0.05 / std::max(flex_slide_m, biaxial_m)));
    CHECK(x.model_reason.find("biaxial sliding of the rigid block ran too") != std::string::npos);
    // The level says which dynamic model ran and why, and the trail repeats it.
    CHECK(x.model == flexible_model_name);
    CHECK(x.model_reason.find("the flexible-body flag is raised") != std::string::npos);
    CHECK(std::count_if(x.trail.begin(), x.trail.end(), [](const std::string& t) {
              return t.rfind("model: flexible body", 0) == 0;
          }) == 1);
    CHECK(r.histories_generated == 1);
    // Simulated levels also show the (informational) energy estimate; its DeltaD is the
    // histories' displacement after the zero-phase 0.5 Hz high-pass (docs/methods.md s.4).
    CHECK(x.sliding.delta_d_m > 0.0);
    CHECK(*x.sliding.highpass_hz == 0.5);
    CHECK(x.sliding.delta_d_source.find("zero-phase 0.5 Hz high-pass") != std::string::npos);
    CHECK(x.sliding.slide_energy_m.has_value());
    // The flexible-body flag is raised beside the slide mode (band 1.7-4.9 Hz given).
    CHECK(x.flexible.raised);
}

TEST_CASE("PGA override is validated", "[assess][pipeline]") {
    Case c = read_case(fs::path(freestand::test::source_dir()) / "cases" / "glovebox-single.toml");
    try {
        with_pga_levels(c, {0.0});
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(std::string(e.what()) == "pga_levels: value 0 is out of range; expected [0.001, 3]");
    }
    CHECK_THROWS_AS(with_pga_levels(c, {}), InputError);
}

TEST_CASE("seed records must come in threes per history", "[assess][pipeline]") {
    Case c = glovebox({0.2}, 1);
    c.options.seed_records = {fs::path(freestand::test::data_dir()) / "RSN175_IMPVALL.H_H-E12140.AT2"};
    try {
        assess::assess(c);
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(std::string(e.what()).find(
                  "options.seed_records: expected 3 records (h1, h2, v) per history, 3 in "
                  "all for histories_per_level = 1, got 1") != std::string::npos);
    }
}

TEST_CASE("a table displacement replaces the high-passed histories, at every sliding level",
          "[assess][pipeline][energy]") {
    Case c = glovebox({0.2}, 1);
    c.options.simulate = SimulatePolicy::never;  // no histories at all
    c.site.energy_table_displacement_m = std::vector<double>{0.040};
    const AssessmentResult r = assess::assess(c);
    const Sliding& s = r.levels.at(0).sliding;
    CHECK(r.histories_generated == 0);
    CHECK(s.delta_d_m == 0.040);
    CHECK_FALSE(s.highpass_hz.has_value());
    CHECK(s.delta_d_source == "case table (site.energy_table_displacement_m)");
    // docs/methods.md s.4: 0.5 w^2 d^2 + 4 mu_e g d - g DeltaD = 0 at the lower friction bound.
    const double w = 2.0 * 3.141592653589793 * *s.f_es_hz;
    const double a = 0.5 * w * w;
    const double b = 4.0 * s.mu_e * 9.81;
    const double q = 9.81 * 0.040;
    CHECK(*s.slide_energy_m == Approx((-b + std::sqrt(b * b + 4.0 * a * q)) / (2.0 * a)));
    // The estimate is informational: the level was decided by the screen (never simulate).
    CHECK(r.levels.at(0).verdict.decided_by == Model::asce4_sliding);
}

TEST_CASE("without histories and without a table the energy estimate says why it is absent",
          "[assess][pipeline][energy]") {
    Case c = glovebox({0.2}, 1);
    c.options.simulate = SimulatePolicy::never;
    const AssessmentResult r = assess::assess(c);
    const Sliding& s = r.levels.at(0).sliding;
    CHECK_FALSE(s.slide_energy_m.has_value());
    CHECK(s.reason.find("energy: not computed") != std::string::npos);
}

TEST_CASE("a --pga override cannot drop the per-level table", "[assess][pipeline][energy]") {
    Case c = read_case(fs::path(freestand::test::source_dir()) / "cases" / "glovebox-single.toml");
    c.site.energy_table_displacement_m = std::vector<double>{0.02, 0.04, 0.06, 0.08};
    try {
        with_pga_levels(c, {0.2});
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(std::string(e.what()).find("energy_table_displacement_m for 4 levels, the override 1") !=
              std::string::npos);
    }
}

TEST_CASE("documented values are assessed or refused at their key, never by an internal name",
          "[assess][pipeline][hardening]") {
    // A value the case file documents is either assessed or refused at its own key.
    Case c = glovebox({0.2}, 1);
    SECTION("mu_s = 0: ASCE 4 does not apply, the simulation decides") {
        // No flexible-body screen inputs: the planar simulation decides.
        c = rigid_glovebox({0.2}, 1);
        c.component.base.mu_s = 0.0;
        c.component.base.mu_k = 0.0;
        c.component.base.mu_s_range = {0.0, 0.0};
        const AssessmentResult r = assess::assess(c);
        const LevelResult& l = r.levels.at(0);
        CHECK_FALSE(l.screen.passed);
        CHECK(l.screen.slide.verdict.failure == Failure::screen_inconclusive);
        CHECK(l.sliding.reason.find("frictionless base") != std::string::npos);
        REQUIRE(l.simulation.has_value());
        CHECK(l.verdict.decided_by == Model::simulation_biaxial_slide);  // it only slides
    }
    // The rocking sections keep to the rigid models: what they check is the screen's text.
    SECTION("restitution 0.001: the equivalent-linear damping would pass 100%") {
        c = rigid_glovebox({0.6}, 1);
        c.component.base.mu_s_range = {0.6, 0.6};
        c.component.base.restitution_range = std::array<double, 2>{0.001, 0.001};
        const AssessmentResult r = assess::assess(c);
        const LevelResult& l = r.levels.at(0);
        REQUIRE(l.screen.rock.applies);
        CHECK(l.screen.rock.verdict.failure == Failure::screen_inconclusive);
        CHECK(l.screen.rock.text.find("damping -ln(r) / pi = 2.2") != std::string::npos);
        CHECK(l.simulation.has_value());
    }
    SECTION("restitution 0 (no rebound): was refused as \"restitution ... (0, 1]\"") {
        c = rigid_glovebox({1.2}, 1);
        c.component.base.mu_s_range = {1.0, 1.0};
        c.component.base.restitution_range = std::array<double, 2>{0.0, 0.0};
        const AssessmentResult r = assess::assess(c);
        const LevelResult& l = r.levels.at(0);
        REQUIRE(l.screen.rock.applies);
        CHECK(l.screen.rock.verdict.failure == Failure::screen_inconclusive);
        CHECK(l.screen.rock.text.find("does not rebound") != std::string::npos);
        REQUIRE(l.simulation.has_value());
        CHECK(l.bounds.rocking.restitution == 0.0);
    }
}

TEST_CASE("a level whose vertical PGA reaches 1 g is refused at pga_g", "[assess][pipeline]") {
    Case c = read_case(fs::path(freestand::test::source_dir()) / "cases" / "glovebox-single.toml");
    try {
        with_pga_levels(c, {0.5, 1.5});
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(std::string(e.what()).find("pga_levels: PGA 1.5 g with a vertical/horizontal ratio of "
                                         "0.6667 gives a vertical PGA of 1 g") != std::string::npos);
    }
    CHECK_NOTHROW(with_pga_levels(c, {1.4}));
}

TEST_CASE("an extreme footprint is assessed, not refused with an internal damping",
          "[assess][pipeline][hardening]") {
    // cg_to_edge_x_m = [100, 1e-9] must not end in an internal "damping 2.57 out of range".
    const Case c = parse_case(R"([component]
name = "Needle"
mass_kg = 100.0
cg_height_m = 1.0
cg_to_edge_x_m = [100, 1e-9]
cg_to_edge_y_m = [0.3, 0.3]
mu_s = 0.6
allowable_slide_m = 0.05
[site]
pga_g = [0.3]
[options]
histories_per_level = 1
max_histories_per_level = 1
)",
                              (fs::path(freestand::test::source_dir()) / "cases" / "needle.toml").string());
    const AssessmentResult r = assess::assess(c);
    const LevelResult& x = r.levels.at(0);
    CHECK(x.initiation.mode != Mode::rest);
    CHECK(x.simulation.has_value());
    CHECK_FALSE(passes(r.own.verdict));
}

TEST_CASE("histories that cannot meet the realism ranges are rejected, never used",
          "[assess][pipeline][realism]") {
    SECTION("synthetic: no attempt can reach D/A <= 0.01 m/g; the error names the history") {
        Case c = glovebox({0.2}, 1);
        c.site.realism.da_max_m_per_g = 0.01;
        try {
            assess::assess(c);
            FAIL("no error");
        } catch (const NumericalError& e) {
            const std::string what = e.what();
            CHECK(what.find("history 1: no synthetic record passed SRP 3.7.1 and the realism "
                            "checks") != std::string::npos);
            CHECK(what.find("h1: D/A") != std::string::npos);
            CHECK(what.find("> 0.01") != std::string::npos);
        }
    }
    SECTION("seed records: the error names options.seed_records and the reason") {
        Case c = glovebox({0.2}, 1);
        const fs::path data(freestand::test::data_dir());
        c.options.seed_records = {data / "RSN175_IMPVALL.H_H-E12140.AT2",
                                  data / "RSN175_IMPVALL.H_H-E12230.AT2",
                                  data / "RSN1546_CHICHI_TCU122-N.AT2"};
        c.site.realism.va_mps_per_g = motion::Range{0.1, 0.2};
        try {
            assess::assess(c);
            FAIL("no error");
        } catch (const InputError& e) {
            const std::string what = e.what();
            CHECK(what.find("options.seed_records: history 1") != std::string::npos);
            CHECK(what.find("V/A") != std::string::npos);
        }
    }
}

TEST_CASE("every history's measures and realism checks travel into the result",
          "[assess][pipeline][realism]") {
    const AssessmentResult r = assess::assess(glovebox({0.2}, 1));
    REQUIRE(r.history_checks.size() == 3);
    for (const HistoryCheck& h : r.history_checks) {
        INFO(h.component);
        CHECK(h.acceptance.passed);
        CHECK(h.acceptance.realism_passed);
        CHECK(h.acceptance.pga_over_zpa >= 1.0);
        CHECK(h.acceptance.pga_over_zpa <= 1.1);
        CHECK(h.acceptance.horizontal == (h.component != "v"));
        if (h.acceptance.horizontal) CHECK(h.acceptance.da_m_per_g <= 1.3);
    }
    CHECK(std::any_of(r.limits.begin(), r.limits.end(), [](const std::string& l) {
        return l.find("realism checks") != std::string::npos && l.find("D/A at most 1.3 m/g") != std::string::npos;
    }));
}

TEST_CASE("the reported extreme footprint (glove box, p_radps kept) is assessed",
          "[assess][pipeline][hardening]") {
    // glovebox-single.toml with cg_to_edge_x_m = [100, 1e-9] and its p_radps kept reaches the
    // equivalent-linear damping at 0.1 g, where an unguarded check throws "damping: value
    // 2.5733644010246386 is out of range; expected (0, 1)" (the case without p_radps above never
    // reaches that check).
    const fs::path file = fs::path(freestand::test::source_dir()) / "cases" / "glovebox-single.toml";
    std::string text = core::read_text_file(file);
    const std::string edges = "cg_to_edge_x_m = [0.526, 0.526]";
    REQUIRE(text.find(edges) != std::string::npos);
    text.replace(text.find(edges), edges.size(), "cg_to_edge_x_m = [100, 1e-9]");
    REQUIRE(text.find("p_radps = [1.97, 1.85]") != std::string::npos);
    Case c = parse_case(text, file.string());
    c.options.histories_per_level = 1;
    c.options.max_histories_per_level = c.options.histories_per_level;
    const AssessmentResult r = assess::assess(with_pga_levels(c, {0.1}));
    const LevelResult& x = r.levels.at(0);
    REQUIRE(x.direction == Direction::x);
    CHECK(x.initiation.mode == Mode::rock);
    REQUIRE(x.simulation.has_value());
    CHECK(x.simulation->overturned == 1);
    CHECK(r.own.verdict.kind == VerdictKind::anchor);
}

namespace {
Case steel_pads(const std::vector<double>& pga, int histories) {
    Case c = read_case(fs::path(freestand::test::source_dir()) / "cases" / "glovebox-steel-pads.toml");
    c.options.histories_per_level = histories;
    c.options.max_histories_per_level = c.options.histories_per_level;
    return with_pga_levels(c, pga);
}
}  // namespace

TEST_CASE("a raised flexible-body flag runs the flexible model, which decides the level",
          "[assess][pipeline][flexible]") {
    // The glove box on steel pads at 0.3 g rests as a rigid block (A below tan alpha and mu_s)
    // but its 7.5 Hz mode lies in the band: the screen passes, the flag is raised.
    const AssessmentResult r = assess::assess(steel_pads({0.3}, 1));
    const LevelResult& x = r.levels.at(0);
    REQUIRE(x.flexible.raised);
    CHECK(x.screen.passed);
    REQUIRE(x.flexible_simulation.has_value());
    REQUIRE(x.simulation.has_value());  // the rigid one, beside
    CHECK(x.verdict.decided_by == Model::simulation_flexible);
    CHECK(x.verdict.margin_basis.find("flexible body: ") != std::string::npos);
    // The flexible body lifted its base, so a pass must bound the overturn rate, which one set
    // cannot (docs/methods.md s.6 step 4).
    CHECK(x.verdict.failure == Failure::not_settled);
    CHECK(x.verdict.margin_basis.rfind("not settled: no overturn in N = 1 sets (cap) bounds the "
                                       "overturn rate only below 97.5%",
                                       0) == 0);
    CHECK(x.model == flexible_model_name);
    CHECK(x.simulation_reason.find("flexible-body flag is raised") != std::string::npos);
    // The flexible body uplifts where the rigid block does not move.
    CHECK(x.flexible_simulation->uplifted == 1);
    CHECK(x.simulation->rock_rad.max == 0.0);
    CHECK(x.flexible_simulation->sim.rock_rad.max > 0.0);
    CHECK(x.flexible_simulation->frequency_hz == 7.5);
    CHECK(x.flexible_simulation->mass_fraction == 0.613);  // cantilever default
    // Resolved by simulation: no open condition remains.
    CHECK(x.verdict.conditions.empty());
    CHECK(open_conditions(r.levels).empty());
    CHECK(std::any_of(x.trail.begin(), x.trail.end(), [](const std::string& t) {
        return t.rfind("the flexible-body model decides; the rigid planar simulation", 0) == 0;
    }));
    CHECK(r.simulations_run == 2 * (x.simulation->bounds_differ ? 2 : 1) * 2);
}

TEST_CASE("without a fixed-base frequency the flag stays an open condition",
          "[assess][pipeline][flexible]") {
    Case c = steel_pads({0.3}, 1);
    c.component.fixed_base_frequency_hz.reset();  // the free-rocking band alone raises the flag
    REQUIRE(flexible_model_blocker(c).has_value());
    const AssessmentResult r = assess::assess(c);
    const LevelResult& x = r.levels.at(0);
    REQUIRE(x.flexible.raised);
    CHECK_FALSE(x.flexible_simulation.has_value());
    CHECK(x.verdict.conditions.size() == 1);
    REQUIRE(open_conditions(r.levels).size() == 1);
    CHECK(open_conditions(r.levels)[0].find("the flexible-body model (docs/methods.md s.10) did "
                                            "not run there") != std::string::npos);
    Case never = steel_pads({0.3}, 1);
    never.options.simulate = SimulatePolicy::never;
    CHECK(*flexible_model_blocker(never) ==
          "options.simulate = \"never\" forbids the flexible-body simulation");
}

}  // namespace freestand_test_assess_test_pipeline
