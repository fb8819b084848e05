// Verdict logic of METHODS.md s.6 on hand-built inputs: every branch of decide_level,
// simulation_need, overall_verdict and verdict_text.
#include <catch2/catch.hpp>

#include "assess/verdict.hpp"

using namespace freestand::assess;

namespace {

constexpr double allowable = 0.050;
constexpr double fs_required = 1.5;

LevelResult level(Mode mode, double a_ratio = 0.3) {
    LevelResult l;
    l.pga_g = 0.3;
    l.initiation.mode = mode;
    l.initiation.a_ratio = a_ratio;
    l.initiation.mu_s = 0.15;
    l.initiation.tan_alpha = 0.43;
    return l;
}

LevelResult sliding(double asce_m, double energy_m) {
    LevelResult l = level(Mode::slide);
    l.sliding.f_es_hz = 1.2;
    l.sliding.slide_asce_m = asce_m;
    l.sliding.slide_energy_m = energy_m;
    return l;
}

Simulation sim(double slide_max_m, double residual_m, double rock_over_alpha = 0.0,
               double overturned = 0.0) {
    Simulation s;
    s.histories = 5;
    s.slide_max_max_m = slide_max_m;
    s.slide_residual_max_m = residual_m;
    s.rock_max_over_alpha_max = rock_over_alpha;
    s.overturned_fraction = overturned;
    return s;
}

}  // namespace

TEST_CASE("rest: free-standing acceptable by the static criterion", "[assess][verdict]") {
    const Verdict v = decide_level(level(Mode::rest, 0.1), allowable, fs_required);
    CHECK(v.kind == VerdictKind::acceptable);
    CHECK(v.decided_by == Model::static_initiation);
    CHECK(*v.margin == Approx(0.15 / 0.1));  // min(mu_s, tan alpha) / A
    CHECK(verdict_text(v) == "free-standing acceptable");
}

TEST_CASE("slide: closed forms within the allowable, the larger governs", "[assess][verdict]") {
    const Verdict v = decide_level(sliding(0.020, 0.030), allowable, fs_required);
    CHECK(v.kind == VerdictKind::acceptable_with_clearance);
    CHECK(v.decided_by == Model::energy_sliding);
    CHECK(v.clearance_m == 0.030);
    CHECK(*v.margin == Approx(0.050 / 0.030));
    CHECK(verdict_text(v) == "acceptable with clearance >= 30 mm");
}

TEST_CASE("slide: both closed forms beyond the allowable, the smaller decides the failure",
          "[assess][verdict]") {
    const Verdict v = decide_level(sliding(0.080, 0.300), allowable, fs_required);
    CHECK(v.kind == VerdictKind::upgrade_material);
    CHECK(v.decided_by == Model::asce4_sliding);
    CHECK(*v.margin == Approx(0.050 / 0.080));
}

TEST_CASE("slide: a simulation governs when run (peak or residual)", "[assess][verdict]") {
    LevelResult l = sliding(0.040, 0.300);
    l.simulation = sim(0.012, 0.009);
    Verdict v = decide_level(l, allowable, fs_required);
    CHECK(v.kind == VerdictKind::acceptable_with_clearance);
    CHECK(v.decided_by == Model::simulation_slide);
    CHECK(verdict_text(v) == "acceptable with clearance >= 12 mm");
    l.simulation =
        sim(0.060, 0.061);  // residual larger than the peak cannot happen, but it governs
    v = decide_level(l, allowable, fs_required);
    CHECK(v.kind == VerdictKind::upgrade_material);
    CHECK(v.decided_by == Model::simulation_residual);
}

TEST_CASE("slide below 1 mm is no motion, and no closed form means no slide", "[assess][verdict]") {
    LevelResult l = sliding(0.0004, 0.0008);
    CHECK(decide_level(l, allowable, fs_required).kind == VerdictKind::acceptable);
    LevelResult none = level(Mode::slide);
    const Verdict v = decide_level(none, allowable, fs_required);
    CHECK(v.kind == VerdictKind::acceptable);
    CHECK(v.decided_by == Model::asce4_sliding);
    CHECK_FALSE(v.margin.has_value());
}

TEST_CASE("rock without simulation: the equivalent-linear factor of safety decides",
          "[assess][verdict]") {
    LevelResult l = level(Mode::rock, 0.6);
    l.rocking.overturn_fs = 2.0;
    Verdict v = decide_level(l, allowable, fs_required);
    CHECK(v.kind == VerdictKind::acceptable);
    CHECK(v.decided_by == Model::equivalent_linear_rocking);
    CHECK(*v.margin == Approx(2.0 / 1.5));
    l.rocking.overturn_fs = 1.2;
    CHECK(decide_level(l, allowable, fs_required).kind == VerdictKind::anchor);
    l.rocking.overturn_fs.reset();
    l.rocking.overturn_predicted = true;
    v = decide_level(l, allowable, fs_required);
    CHECK(v.kind == VerdictKind::anchor);
    CHECK(*v.margin == 0.0);
    CHECK(verdict_text(v) == "anchor");
}

TEST_CASE("rock with simulation: any overturned history anchors", "[assess][verdict]") {
    LevelResult l = level(Mode::rock, 0.6);
    l.rocking.overturn_fs = 5.0;  // the screen says fine; the reference decides
    l.simulation = sim(0.0, 0.0, 0.5, 0.2);
    Verdict v = decide_level(l, allowable, fs_required);
    CHECK(v.kind == VerdictKind::anchor);
    CHECK(v.decided_by == Model::simulation_rocking);
    l.simulation = sim(0.0, 0.0, 0.5, 0.0);
    v = decide_level(l, allowable, fs_required);
    CHECK(v.kind == VerdictKind::acceptable);
    CHECK(*v.margin == Approx((1.0 / 0.5) / 1.5));
    l.simulation = sim(0.0, 0.0, 0.8, 0.0);  // FS 1.25 < 1.5
    CHECK(decide_level(l, allowable, fs_required).kind == VerdictKind::anchor);
}

TEST_CASE("slide-rock: the worse of the sliding and rocking verdicts", "[assess][verdict]") {
    LevelResult l = level(Mode::slide_rock, 0.6);
    l.simulation = sim(0.020, 0.010, 0.3, 0.0);
    Verdict v = decide_level(l, allowable, fs_required);
    CHECK(v.kind == VerdictKind::acceptable_with_clearance);
    CHECK(v.decided_by == Model::simulation_slide);
    l.simulation = sim(0.020, 0.010, 0.9, 0.0);
    v = decide_level(l, allowable, fs_required);
    CHECK(v.kind == VerdictKind::anchor);
    CHECK(v.decided_by == Model::simulation_rocking);
}

TEST_CASE("rest with a simulation that shows slip is judged on the slip", "[assess][verdict]") {
    LevelResult l = level(Mode::rest, 0.1);
    l.simulation = sim(0.0, 0.0);
    CHECK(decide_level(l, allowable, fs_required).decided_by == Model::no_motion);
    l.simulation = sim(0.004, 0.002);
    const Verdict v = decide_level(l, allowable, fs_required);
    CHECK(v.kind == VerdictKind::acceptable_with_clearance);
    CHECK(v.decided_by == Model::simulation_slide);
}

TEST_CASE("when to simulate", "[assess][verdict]") {
    CHECK_FALSE(simulation_need(level(Mode::rest), allowable, SimulatePolicy::automatic).run);
    CHECK(simulation_need(level(Mode::rest), allowable, SimulatePolicy::always).run);
    CHECK_FALSE(simulation_need(level(Mode::rock), allowable, SimulatePolicy::never).run);
    CHECK(simulation_need(level(Mode::rock), allowable, SimulatePolicy::automatic).run);
    CHECK(simulation_need(level(Mode::slide_rock), allowable, SimulatePolicy::automatic).run);
    CHECK_FALSE(simulation_need(sliding(0.02, 0.04), allowable, SimulatePolicy::automatic).run);
    CHECK_FALSE(simulation_need(sliding(0.06, 0.40), allowable, SimulatePolicy::automatic).run);
    const SimulationNeed open =
        simulation_need(sliding(0.04, 0.40), allowable, SimulatePolicy::automatic);
    CHECK(open.run);
    CHECK(open.reason == "the closed-form slides straddle the allowable: the simulation decides");
    // Exactly at the allowable counts as within it.
    CHECK_FALSE(simulation_need(sliding(0.05, 0.05), allowable, SimulatePolicy::automatic).run);
    CHECK(simulation_need(level(Mode::slide), allowable, SimulatePolicy::automatic).run);
}

TEST_CASE("overall verdict: worst level, upgrade, or anchor", "[assess][verdict]") {
    std::vector<LevelResult> levels{level(Mode::rest, 0.1), sliding(0.02, 0.03)};
    for (auto& l : levels) l.verdict = decide_level(l, allowable, fs_required);
    Upgrade up;
    Verdict v = overall_verdict(levels, up);
    CHECK(v.kind == VerdictKind::acceptable_with_clearance);
    CHECK(governing_index(levels) == 1);

    levels.push_back(sliding(0.08, 0.30));
    levels.back().verdict = decide_level(levels.back(), allowable, fs_required);
    up.needed = true;
    Verdict pass;
    pass.kind = VerdictKind::acceptable;
    pass.margin = 1.2;
    Verdict fail;
    fail.kind = VerdictKind::upgrade_material;
    up.trials = {{"plywood", 0.15, fail}, {"HDPE", 0.32, pass}, {"steel", 0.72, pass}};
    up.recommended = "HDPE";
    v = overall_verdict(levels, up);
    CHECK(v.kind == VerdictKind::upgrade_material);
    CHECK(verdict_text(v) == "upgrade base material to HDPE");
    CHECK(*v.margin == 1.2);
    apply_upgrade(levels, up);
    CHECK(verdict_text(levels.back().verdict) == "upgrade base material to HDPE");

    up.recommended.reset();
    levels.back().verdict = decide_level(levels.back(), allowable, fs_required);
    v = overall_verdict(levels, up);
    CHECK(v.kind == VerdictKind::anchor);
    CHECK(v.decided_by == Model::asce4_sliding);
    apply_upgrade(levels, up);
    CHECK(levels.back().verdict.kind == VerdictKind::anchor);
}

TEST_CASE("clearance is rounded up to whole millimetres", "[assess][verdict]") {
    Verdict v;
    v.kind = VerdictKind::acceptable_with_clearance;
    v.clearance_m = 0.047;
    CHECK(verdict_text(v) == "acceptable with clearance >= 47 mm");
    v.clearance_m = 0.0471;
    CHECK(verdict_text(v) == "acceptable with clearance >= 48 mm");
}
