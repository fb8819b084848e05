// The decision policy of docs/methods.md s.6 on hand-built inputs: the screen, when to simulate,
// the simulation's statistics, severity, headline text.
#include <catch2/catch.hpp>

#include "assess/verdict.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_assess_test_verdict {

using namespace freestand::assess;

namespace {

constexpr double allowable = 0.050;
constexpr double fs_required = 1.5;

LevelResult level(Mode upper, Mode lower, double a_ratio = 0.3) {
    LevelResult l;
    l.pga_g = 0.3;
    l.initiation.mode = upper;
    l.initiation.a_ratio = a_ratio;
    l.initiation.mu_s = 0.18;
    l.initiation.tan_alpha = 0.43;
    l.initiation_lower = l.initiation;
    l.initiation_lower.mode = lower;
    l.initiation_lower.mu_s = 0.12;
    return l;
}

LevelResult sliding(double asce_m, std::optional<double> energy_m = std::nullopt) {
    LevelResult l = level(Mode::slide, Mode::slide);
    l.sliding.mu_s = 0.12;
    l.sliding.c_s_mps2 = 2.2;
    l.sliding.f_es_hz = 1.2;
    l.sliding.slide_asce_m = asce_m;
    l.sliding.slide_energy_m = energy_m;
    return l;
}

LevelResult rocking(std::optional<double> el_fs, bool gate = true, bool overturn = false) {
    LevelResult l = level(Mode::rock, Mode::rock, 0.6);
    l.rocking.alpha_rad = 0.4;
    l.rocking.gate_passed = gate;
    l.rocking.overturn_predicted = overturn;
    l.rocking.overturn_fs = el_fs;
    if (el_fs) l.rocking.theta_rad = 0.4 / *el_fs;
    return l;
}

Stats same(double v) { return Stats{v, v, v}; }

Simulation sim(int n, Stats slide_m, Stats rock_over_alpha = {}, int overturned = 0) {
    Simulation s;
    s.histories = n;
    s.slide_m = slide_m;
    s.rock_over_alpha = rock_over_alpha;
    s.rock_rad = Stats{0.4 * rock_over_alpha.mean, 0.4 * rock_over_alpha.p84,
                       0.4 * rock_over_alpha.max};
    s.overturned = overturned;
    return s;
}

// The pipeline's order: screen, then (when the policy says so) the simulation, then decide.
LevelResult decided(LevelResult l, std::optional<Simulation> s = std::nullopt) {
    l.screen = screen_level(l, allowable, fs_required);
    l.simulation = s;
    l.verdict = decide_level(l, allowable, fs_required);
    return l;
}

}  // namespace

TEST_CASE("rest at the lower friction bound passes the screen on the static criterion",
          "[assess][verdict]") {
    const LevelResult l = decided(level(Mode::rest, Mode::rest, 0.1));
    CHECK(l.screen.passed);
    CHECK(l.screen.rest.applies);
    CHECK_FALSE(l.screen.slide.applies);
    CHECK(l.verdict.kind == VerdictKind::acceptable);
    CHECK(l.verdict.decided_by == Model::static_initiation);
    CHECK(*l.verdict.margin == Approx(0.12 / 0.1));  // min(mu_s lower, tan alpha) / A
    CHECK_FALSE(simulation_need(l.screen, SimulatePolicy::automatic).run);
}

TEST_CASE("sliding at the lower bound only: ASCE 4 screens it", "[assess][verdict]") {
    LevelResult l = sliding(0.030);
    l.initiation.mode = Mode::rest;  // at rest at the upper bound, slides at the lower
    l = decided(l);
    CHECK(l.screen.slide.applies);
    CHECK_FALSE(l.screen.rock.applies);
    CHECK(l.verdict.kind == VerdictKind::acceptable_with_clearance);
    CHECK(l.verdict.decided_by == Model::asce4_sliding);
    CHECK(l.verdict.clearance_m == 0.030);
    CHECK(*l.verdict.margin == Approx(0.050 / 0.030));
}

TEST_CASE("the energy estimate neither decides nor triggers a simulation", "[assess][verdict]") {
    const LevelResult l = decided(sliding(0.030, 0.600));  // energy 12x the allowable
    CHECK(l.screen.passed);
    CHECK(l.verdict.decided_by == Model::asce4_sliding);
    CHECK(l.verdict.clearance_m == 0.030);
    for (SimulatePolicy p : {SimulatePolicy::automatic, SimulatePolicy::never})
        CHECK_FALSE(simulation_need(l.screen, p).run);
}

TEST_CASE("a failed screen requires the simulation, which governs pass and fail",
          "[assess][verdict]") {
    LevelResult l = sliding(0.080);
    l.screen = screen_level(l, allowable, fs_required);
    CHECK_FALSE(l.screen.passed);
    CHECK(simulation_need(l.screen, SimulatePolicy::automatic).run);
    CHECK(simulation_need(l.screen, SimulatePolicy::always).run);
    // The 84th percentile governs (30 mm), not the mean (20 mm) nor the maximum (60 mm).
    l = decided(l, sim(30, Stats{0.020, 0.030, 0.060}));
    CHECK(l.verdict.kind == VerdictKind::acceptable_with_clearance);
    CHECK(l.verdict.decided_by == Model::simulation_slide);
    CHECK(l.verdict.clearance_m == 0.030);
    CHECK(*l.verdict.margin == Approx(0.050 / 0.030));
    // A mean within the allowable does not save a level whose 84th percentile is beyond it.
    l = decided(l, sim(30, Stats{0.040, 0.060, 0.080}));
    CHECK(l.verdict.kind == VerdictKind::anchor);
    CHECK(l.verdict.failure == Failure::slides_beyond_allowable);
    CHECK(*l.verdict.margin == Approx(0.050 / 0.060));
}

TEST_CASE("simulate = never lets the screen decide a failure and says so", "[assess][verdict]") {
    LevelResult l = sliding(0.080);
    l.screen = screen_level(l, allowable, fs_required);
    const SimulationNeed need = simulation_need(l.screen, SimulatePolicy::never);
    CHECK_FALSE(need.run);
    CHECK(need.reason.find("the screen decides the failure") != std::string::npos);
    l = decided(l);
    CHECK(l.verdict.kind == VerdictKind::anchor);
    CHECK(l.verdict.decided_by == Model::asce4_sliding);
    CHECK(*l.verdict.margin == Approx(0.050 / 0.080));
}

TEST_CASE("a passing screen decides even when a simulation is reported beside it",
          "[assess][verdict]") {
    LevelResult l = decided(sliding(0.030), sim(7, same(0.070)));
    CHECK(l.verdict.decided_by == Model::asce4_sliding);
    CHECK(l.verdict.kind == VerdictKind::acceptable_with_clearance);
    const auto trail = decision_trail(l, allowable, fs_required);
    REQUIRE(trail.size() == 5);
    CHECK(trail[3].find("a FAILURE") != std::string::npos);
    CHECK(trail[3].find("the screen is not conservative here") != std::string::npos);
}

TEST_CASE("rocking screen: equivalent-linear FS, overturning, disagreeing gate",
          "[assess][verdict]") {
    LevelResult ok = decided(rocking(3.0));
    CHECK(ok.screen.passed);
    CHECK(ok.verdict.decided_by == Model::equivalent_linear_rocking);
    CHECK(*ok.verdict.margin == Approx(2.0));
    LevelResult low = decided(rocking(1.2));
    CHECK_FALSE(low.screen.passed);
    CHECK(low.verdict.failure == Failure::rocking_fs_below_required);
    LevelResult over = decided(rocking(std::nullopt, true, true));
    CHECK(over.verdict.failure == Failure::overturns);
    CHECK(*over.verdict.margin == 0.0);
    // The static criterion predicts uplift, the gate does not: inconclusive, so simulate.
    LevelResult gate = decided(rocking(std::nullopt, false));
    CHECK_FALSE(gate.screen.passed);
    CHECK(gate.verdict.failure == Failure::screen_inconclusive);
    CHECK(simulation_need(gate.screen, SimulatePolicy::automatic).run);
}

TEST_CASE("simulated rocking: any overturn fails, theta/alpha against 1/FS, no motion",
          "[assess][verdict]") {
    LevelResult l = rocking(1.2);
    l = decided(l, sim(7, same(0.0), Stats{0.1, 0.2, 0.3}, 1));
    CHECK(l.verdict.failure == Failure::overturns);
    CHECK(*l.verdict.margin == 0.0);
    CHECK(l.verdict.margin_basis.find("1 of 7 histories overturned") != std::string::npos);
    // The 84th percentile governs, not the mean.
    l = decided(l, sim(30, same(0.0), Stats{0.4, 0.6, 0.9}));
    CHECK(l.verdict.decided_by == Model::simulation_rocking);
    CHECK(*l.verdict.margin == Approx(1.0 / (0.6 * 1.5)));
    CHECK(passes(l.verdict));
    l = decided(l, sim(30, same(0.0), Stats{0.4, 0.7, 0.9}));
    CHECK_FALSE(passes(l.verdict));
    // No motion still has a margin: the rotation's ratio.
    l = decided(l, sim(7, same(0.0), Stats{0.001, 0.002, 0.005}));
    CHECK(l.verdict.no_motion);
    CHECK(*l.verdict.margin == Approx(1.0 / (0.002 * 1.5)));
    CHECK(margin_text(l.verdict) == "333.33 (no motion)");
    // Nothing moved at all: the level's static margin, never an unlimited one.
    l.initiation_lower.a_ratio = 0.5;
    l.initiation_lower.mu_s = 0.3;
    l.initiation_lower.tan_alpha = 0.6;
    l = decided(l, sim(7, same(0.0), same(0.0)));
    CHECK(l.verdict.no_motion);
    CHECK(*l.verdict.margin == Approx(0.3 / 0.5));
    CHECK(l.verdict.margin_basis.find("static margin") != std::string::npos);
}

TEST_CASE("the flexible-body flag becomes an open condition of a passing level",
          "[assess][verdict]") {
    LevelResult l = level(Mode::rest, Mode::rest, 0.1);
    l.flexible.raised = true;
    l.flexible.basis = "fixed-base 7.50 Hz";
    l = decided(l);
    REQUIRE(l.verdict.conditions.size() == 1);
    const auto merged = open_conditions({l});
    REQUIRE(merged.size() == 1);
    CHECK(merged[0].find("PGA 0.300 g x") != std::string::npos);
    LevelResult failing = sliding(0.080);
    failing.flexible.raised = true;
    failing = decided(failing);
    CHECK(failing.verdict.conditions.empty());
}

TEST_CASE("a flexible-body simulation decides its level, pass or fail", "[assess][verdict][flexible]") {
    LevelResult l = level(Mode::rest, Mode::rest, 0.1);  // the screen passes
    l.flexible.raised = true;
    FlexibleSimulation f;
    f.sim = sim(7, same(0.2), Stats{});  // 200 mm of slip > the allowable
    l.flexible_simulation = f;
    l = decided(l);
    CHECK_FALSE(passes(l.verdict));
    CHECK(l.verdict.decided_by == Model::simulation_flexible);
    CHECK(l.verdict.failure == Failure::slides_beyond_allowable);
    CHECK(l.verdict.conditions.empty());
    f.sim = sim(7, same(0.0), Stats{0.01, 0.02, 0.03});
    l.flexible_simulation = f;
    l = decided(l);
    CHECK(passes(l.verdict));
    CHECK(l.verdict.decided_by == Model::simulation_flexible);
    CHECK(l.verdict.conditions.empty());
    CHECK(std::string(to_string(Model::simulation_flexible)).find("s.10") != std::string::npos);
}

TEST_CASE("severity: failures first, then the smaller margin, no motion is least severe",
          "[assess][verdict]") {
    Verdict pass_small;
    pass_small.margin = 1.1;
    Verdict pass_big;
    pass_big.margin = 3.0;
    Verdict quiet;
    quiet.no_motion = true;
    Verdict fail;
    fail.kind = VerdictKind::anchor;
    fail.margin = 0.9;
    CHECK(more_severe(pass_small, pass_big));
    CHECK(more_severe(pass_big, quiet));
    // A level that moves governs over one at rest even when the rest margin is smaller
    // (docs/methods.md s.6 step 8); among levels at rest the smaller margin.
    Verdict at_rest;
    at_rest.no_motion = true;
    at_rest.margin = 1.05;
    CHECK(more_severe(pass_big, at_rest));
    Verdict at_rest_more = at_rest;
    at_rest_more.margin = 4.0;
    CHECK(more_severe(at_rest, at_rest_more));
    CHECK(more_severe(at_rest_more, quiet));
    CHECK(more_severe(fail, pass_small));
    CHECK_FALSE(more_severe(pass_big, pass_small));
    std::vector<LevelResult> levels(3);
    levels[0].verdict = pass_big;
    levels[1].verdict = pass_small;
    levels[1].pga_g = 0.2;
    levels[2].verdict = quiet;
    const Governing g = governing_of(levels);
    CHECK(g.level == 1);
    CHECK(g.pga_g == 0.2);
    CHECK(*g.verdict.margin == 1.1);
}

TEST_CASE("verdict and margin text", "[assess][verdict]") {
    Verdict v;
    CHECK(verdict_text(v) == "free-standing acceptable");
    v.kind = VerdictKind::acceptable_with_clearance;
    v.clearance_m = 0.047000000001;
    CHECK(verdict_text(v) == "acceptable with clearance >= 47 mm");
    v.clearance_m = 0.0471;
    CHECK(verdict_text(v) == "acceptable with clearance >= 48 mm");
    v.kind = VerdictKind::change_material;
    v.material = "aluminium";
    v.mechanism = "lower friction: it slides instead of rocking over";
    CHECK(verdict_text(v) ==
          "change base material to aluminium (lower friction: it slides instead of rocking over)");
    v.kind = VerdictKind::anchor;
    CHECK(verdict_text(v) == "anchor");
    v.margin = 0.5;
    CHECK(margin_text(v) == "0.50");
}

}  // namespace freestand_test_assess_test_verdict
