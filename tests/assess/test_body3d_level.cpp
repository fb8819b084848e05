// The rigid body in three dimensions in assess (docs/methods.md s.11): a simulated level where
// the body can uplift in some direction is decided by the 3D body, its runs shared by x and y,
// the planar runs beside with the ratio; a level that cannot uplift keeps its model and says why.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>

#include "support/shipped_case.hpp"
#include "assess/body3d_level.hpp"
#include "assess/level.hpp"
#include "assess/pipeline.hpp"
#include "assess/verdict.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_assess_test_body3d_level {

using namespace freestand;
using namespace freestand::assess;
using freestand::test::shipped_case;
using freestand::test::trail_has;

namespace {



}  // namespace

TEST_CASE("the 3D body of a component: its planar geometries' rectangle and inertias",
          "[assess][3d]") {
    const Case c = shipped_case("glovebox-single.toml", {0.2}, 1);
    const dynamics::Body3d b = component_body3d(c.component);
    const block::Block bx = c.component.block(Direction::x);
    const block::Block by = c.component.block(Direction::y);
    REQUIRE(b.footprint_m.size() == 4);
    CHECK(b.h_m == c.component.cg_height_m);
    CHECK(b.mass_kg == c.component.mass_kg);
    // Leaning along +x it tips over direction x's right edge, along -y over y's left edge.
    CHECK(b.reach_m(0.0) == Approx(bx.b_right_m));
    CHECK(b.reach_m(units::pi) == Approx(bx.b_left_m));
    CHECK(b.reach_m(-units::pi / 2.0) == Approx(by.b_left_m));
    CHECK(b.critical_tilt_rad(0.0) == Approx(std::atan(bx.b_right_m / bx.h_m)));
    CHECK(b.inertia_cg_kgm2(0, 0) == by.inertia_cg_kgm2);
    CHECK(b.inertia_cg_kgm2(1, 1) == bx.inertia_cg_kgm2);
}

TEST_CASE("a level that can uplift is decided by the 3D body, the planar runs beside it",
          "[assess][3d]") {
    // The slender TS1 block rocks at 0.3 g at both friction bounds.
    Case c = shipped_case("block-ts1.toml", {0.3}, 2);
    c.options.search_materials = false;  // the own base's levels are what is checked
    const AssessmentResult r = assess::assess(c);
    const LevelResult& x = r.levels.at(0);
    const LevelResult& y = r.levels.at(1);
    for (const LevelResult* l : {&x, &y}) {
        INFO(to_string(l->direction));
        REQUIRE(l->simulation.has_value());
        REQUIRE(l->body3d.has_value());
        REQUIRE(l->body3d->ran);
        CHECK(l->model == body3d_model_name);
        CHECK(l->model_reason.find("the body can uplift at the upper bounds (x rock, y rock)") !=
              std::string::npos);
        CHECK(l->verdict.decided_by == Model::simulation_3d);
        CHECK(l->verdict.margin_basis.find("3D body: ") != std::string::npos);
        CHECK(trail_has(*l, "3D body (h1 along x, h2 along y, the vertical; dt 0.001 s)"));
        CHECK(trail_has(*l, "the 3D body decides; the planar simulation of direction"));
        CHECK(l->body3d->sim.histories == 2);
        CHECK(l->body3d->sim.bounds_differ);
    }
    // One set of runs per PGA, shared by x and y; the ratio is to the larger planar statistic.
    const Body3dLevel& b = *x.body3d;
    CHECK(b.sim.overturned_sets == y.body3d->sim.overturned_sets);
    CHECK(b.sim.rock_over_alpha.p84 == y.body3d->sim.rock_over_alpha.p84);
    CHECK(b.twist_rad.values == y.body3d->twist_rad.values);
    const double planar = std::max(x.simulation->governing(x.simulation->rock_over_alpha),
                                   y.simulation->governing(y.simulation->rock_over_alpha));
    CHECK(b.planar_rock_over_alpha == planar);
    CHECK(b.rock_ratio.has_value() == (planar > 0.0));
    if (b.rock_ratio) {
        CHECK(*b.rock_ratio ==
              Approx(b.sim.governing(b.sim.rock_over_alpha) / planar).epsilon(1e-12));
    }
    // The 3D statistics decide by the planar rules: the same verdict from them directly.
    const Verdict direct = simulation_verdict(b.sim, r.input.component.allowable_slide_m,
                                              r.input.component.required_overturn_fs);
    CHECK(passes(direct) == passes(x.verdict));
    CHECK(direct.margin == x.verdict.margin);
    // The planar runs' restitution bounds: the steel's measured r and Housner's beside it.
    const DirectionBounds& bounds = x.bounds;
    REQUIRE(bounds.rocking_lower.has_value());
    REQUIRE(b.sim.rocking_other.has_value());
    CHECK(b.sim.rocking_bound.restitution + b.sim.rocking_other->bound.restitution ==
          Approx(bounds.rocking.restitution + bounds.rocking_lower->restitution));
    CHECK(b.sim.rocking_bound.restitution != b.sim.rocking_other->bound.restitution);
    // The step check reruns the governing history at a sixteenth of the step, beside its own run.
    CHECK(b.step_checked);
    CHECK(b.check_dt_s == Approx(b.dt_s / 16.0));
    const auto k = static_cast<std::size_t>(b.sim.governing_history);
    if (b.sim.overturned_sets.at(k) == 0)
        CHECK(b.run_tilt_over_critical == b.sim.rock_over_alpha.values.at(k));
    if (b.run_overturned) CHECK(b.sim.overturned_sets.at(k) == 1);
    CHECK(b.check_tilt_over_critical > 0.0);
    // It checks the slide of that run too: with one friction bound the run is the slide's.
    if (!b.sim.bounds_differ && b.sim.overturned_sets.at(k) == 0)
        CHECK(b.run_slide_m == b.sim.slide_m.values.at(k));
    CHECK(b.run_slide_m > 0.0);
    CHECK(b.check_slide_m > 0.0);
    CHECK(x.trail.end() != std::find_if(x.trail.begin(), x.trail.end(), [&b](const std::string& t) {
              return t.find("step check on the governing history") != std::string::npos &&
                     t.find(fmt::format("and {:.1f} mm at {:g} s", 1e3 * b.check_slide_m,
                                        b.check_dt_s)) != std::string::npos;
          }));
    // simulations_run counts the planar runs of both rows and the shared 3D runs once, with the
    // step check's.
    const auto runs = [](const Simulation& sim) {
        return sim.histories * (1 + (sim.bounds_differ ? 1 : 0) + (sim.rocking_other ? 1 : 0));
    };
    CHECK(r.simulations_run == runs(*x.simulation) + runs(*y.simulation) + runs(b.sim) + 1);
    // Without the step check (no case key; the policy tests skip it) the decision is the same
    // and the trail says the check did not run.
    Case unchecked = c;
    unchecked.options.step_check = false;
    const AssessmentResult u = assess::assess(unchecked);
    const LevelResult& ux = u.levels.at(0);
    REQUIRE(ux.body3d.has_value());
    CHECK_FALSE(ux.body3d->step_checked);
    CHECK(ux.verdict.margin == x.verdict.margin);
    CHECK(ux.body3d->sim.overturned_sets == b.sim.overturned_sets);
    CHECK(std::any_of(ux.trail.begin(), ux.trail.end(), [](const std::string& t) {
        return t.rfind("3D body (", 0) == 0 && t.find("; step check not run") != std::string::npos;
    }));
    CHECK(u.simulations_run == r.simulations_run - 1);
    double time_s = 0.0;
    for (double t : b.time_in_state_s) time_s += t;
    CHECK(time_s > 1.0);
    CHECK(b.time_in_state_s[2] + b.time_in_state_s[3] > 0.0);  // on an edge or a vertex
}

TEST_CASE("a flagged body that can uplift runs the 3D body carrying its mode",
          "[assess][3d][flexible]") {
    // The glove box on steel pads: its 7.5 Hz mode lifts the base at 0.3 g, where the rigid
    // block rests, and the planar flexible runs decide; at 0.4 g the rigid block can rock, and
    // the 3D body runs with the mode along x and y.
    Case c = shipped_case("glovebox-steel-pads.toml", {0.3, 0.4}, 2);
    c.site.dbe_pga_g.reset();  // the goal is not what this checks
    const AssessmentResult r = assess::assess(c);
    const LevelResult& low = r.levels.at(0);
    REQUIRE(low.flexible_simulation.has_value());
    CHECK(low.flexible_simulation->uplifted > 0);
    REQUIRE(low.body3d.has_value());
    CHECK_FALSE(low.body3d->ran);
    CHECK(low.body3d->reason.find("; the flexible body lifted its base (x in ") !=
          std::string::npos);
    const LevelResult& x = r.levels.at(2);
    REQUIRE(x.pga_g == 0.4);
    REQUIRE(x.body3d.has_value());
    CHECK(x.body3d->ran);
    CHECK(x.body3d->flexible);
    CHECK(x.body3d->mode_text.rfind("mode 7.5 Hz along x and y, damping 0.02", 0) == 0);
    CHECK(x.body3d->modal_m.max > 0.0);
    CHECK(x.body3d->reason.find(", carrying the flexible body's mode 7.5 Hz") !=
          std::string::npos);
    CHECK(trail_has(x, "3D body (h1 along x"));
    // Carrying the mode, the 3D body decides; the planar flexible runs stay beside it.
    CHECK(x.model == assess::body3d_flexible_model_name);
    CHECK(x.verdict.decided_by == Model::simulation_3d_flexible);
    // The 3D body carrying the mode resolves the flag: its passing decision (on these two sets,
    // before the settling's overturn bound asks for more) carries no open flexible-body
    // condition.
    const Verdict decided = decide_level(x, c.component.allowable_slide_m,
                                         c.component.required_overturn_fs);
    REQUIRE(passes(decided));
    CHECK(decided.conditions.empty());
    CHECK(trail_has(x, "the 3D body carrying the mode decides; beside it the planar flexible "
                       "body of direction x gives "));
    REQUIRE(x.flexible_simulation.has_value());
}

TEST_CASE("a level that cannot uplift keeps its model and says why the 3D body does not run",
          "[assess][3d]") {
    // The glove box slides at 0.2 g at both friction bounds (tan(alpha) well above mu_s).
    const AssessmentResult r = assess::assess(shipped_case("glovebox-single.toml", {0.2}, 1));
    const LevelResult& x = r.levels.at(0);
    REQUIRE(x.simulation.has_value());
    REQUIRE(x.body3d.has_value());
    CHECK_FALSE(x.body3d->ran);
    CHECK(x.body3d->reason ==
          "at the upper friction bound direction x is slide and y is slide: no component reaches "
          "its axis's g tan(alpha), so no plan direction uplifts");
    CHECK(x.model != body3d_model_name);
    CHECK(x.verdict.decided_by != Model::simulation_3d);
    CHECK(trail_has(x, "3D body not run: at the upper friction bound"));
}

}  // namespace freestand_test_assess_test_body3d_level
