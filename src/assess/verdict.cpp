#include "assess/verdict.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/steps.hpp"

namespace freestand::assess {

const char* to_string(Model m) {
    switch (m) {
        case Model::static_initiation:
            return "static initiation criterion (docs/methods.md s.2; Shenton 1996)";
        case Model::asce4_sliding:
            return "ASCE 4 equivalent-linear sliding (docs/methods.md s.4; ASCE 4-16)";
        case Model::equivalent_linear_rocking:
            return "equivalent-linear rocking estimate (docs/methods.md s.5a; ASCE 43-05 App. A "
                   "approach)";
        case Model::simulation_slide:
            return "time-history simulation, peak slip (docs/methods.md s.3)";
        case Model::simulation_rocking:
            return "time-history simulation, rocking and overturning (docs/methods.md s.3)";
        case Model::simulation_biaxial_slide:
            return "biaxial sliding simulation, peak |u| of both horizontal components at once "
                   "(docs/methods.md s.10)";
        case Model::simulation_flexible:
            return "time-history simulation of the flexible body, rigid base and one elastic mode "
                   "(docs/methods.md s.10)";
        case Model::simulation_3d:
            return "time-history simulation of the rigid body in three dimensions, every "
                   "component at once (docs/methods.md s.11)";
        case Model::simulation_3d_flexible:
            return "time-history simulation of the body in three dimensions carrying the "
                   "flexible body's mode along x and y, every component at once "
                   "(docs/methods.md s.11)";
        case Model::fragility_goal:
            return "performance goal: fragility engine at multiples of the DBE, lognormal fit "
                   "(docs/methods.md s.6 step 5, s.9; ASCE 43-05 s.1.3)";
    }
    return "";
}

const char* to_string(VerdictKind k) {
    switch (k) {
        case VerdictKind::acceptable:
            return "acceptable";
        case VerdictKind::acceptable_with_clearance:
            return "acceptable_with_clearance";
        case VerdictKind::change_material:
            return "change_material";
        case VerdictKind::anchor:
            return "anchor";
    }
    return "";
}

const char* to_string(Failure f) {
    switch (f) {
        case Failure::none:
            return "none";
        case Failure::slides_beyond_allowable:
            return "slides beyond the allowable";
        case Failure::rocking_fs_below_required:
            return "rocking factor of safety below the required";
        case Failure::overturns:
            return "overturns";
        case Failure::screen_inconclusive:
            return "screen inconclusive (no simulation)";
        case Failure::not_settled:
            return "decision not settled by the sets at the cap";
        case Failure::performance_goal:
            return "performance goal not met (ASCE 43-05 s.1.3)";
    }
    return "";
}

namespace {

double mm(double m) { return m * 1000.0; }

Verdict no_motion(Model model, std::string basis) {
    Verdict v;
    v.no_motion = true;
    v.decided_by = model;
    v.margin_basis = std::move(basis);
    return v;
}

// Sliding demand against the allowable (absolute clearance).
Verdict slide_demand_verdict(double slide_m, double allowable_m, Model model,
                             const std::string& what) {
    if (slide_m < no_motion_slide_m) {
        Verdict v =
            no_motion(model, fmt::format("{} {:.2f} mm < 1 mm (no motion)", what, mm(slide_m)));
        if (slide_m > 0.0) {
            v.margin = allowable_m / slide_m;
            v.margin_basis += fmt::format("; allowable slide {:.1f} mm / {:.2f} mm",
                                          mm(allowable_m), mm(slide_m));
        }
        return v;
    }
    Verdict v;
    v.decided_by = model;
    v.margin = allowable_m / slide_m;
    v.margin_basis = fmt::format("allowable slide {:.1f} mm / {} {:.1f} mm", mm(allowable_m),
                                 what, mm(slide_m));
    v.clearance_m = slide_m;
    if (slide_m <= allowable_m) {
        v.kind = VerdictKind::acceptable_with_clearance;
    } else {
        v.kind = VerdictKind::anchor;
        v.failure = Failure::slides_beyond_allowable;
    }
    return v;
}

Verdict fs_verdict(double fs, double required_fs, Model model, const std::string& what) {
    Verdict v;
    v.decided_by = model;
    v.margin = fs / required_fs;
    v.margin_basis =
        fmt::format("factor of safety alpha / theta_max = {:.2f} ({}) over required {:.2f}", fs,
                    what, required_fs);
    if (*v.margin < 1.0) {
        v.kind = VerdictKind::anchor;
        v.failure = Failure::rocking_fs_below_required;
    }
    return v;
}

Verdict overturn_verdict(Model model, std::string basis) {
    Verdict v;
    v.kind = VerdictKind::anchor;
    v.failure = Failure::overturns;
    v.decided_by = model;
    v.margin = 0.0;
    v.margin_basis = std::move(basis);
    return v;
}

// The more severe of two partial verdicts; a passing result keeps the larger clearance need.
Verdict combine(const Verdict& a, const Verdict& b) {
    Verdict out = more_severe(b, a) ? b : a;
    if (passes(out)) {
        out.clearance_m = std::max(a.clearance_m, b.clearance_m);
        if (out.clearance_m >= no_motion_slide_m) out.kind = VerdictKind::acceptable_with_clearance;
        if (out.no_motion && out.clearance_m >= no_motion_slide_m) out.no_motion = false;
    }
    return out;
}

Verdict inconclusive(Model model, std::string basis) {
    Verdict v;
    v.kind = VerdictKind::anchor;
    v.failure = Failure::screen_inconclusive;
    v.decided_by = model;
    v.margin_basis = std::move(basis);
    return v;
}

ScreenCheck check(Verdict v, std::string text) {
    ScreenCheck c;
    c.applies = true;
    c.passed = passes(v);
    c.verdict = std::move(v);
    c.text = std::move(text);
    return c;
}

ScreenCheck rest_check(const Initiation& lower) {
    const double threshold = std::min(lower.mu_s, lower.tan_alpha);
    Verdict v;
    v.decided_by = Model::static_initiation;
    std::string text = fmt::format("A = {:.3f} <= min(mu_s {:.3f}, tan alpha {:.3f}): at rest",
                                   lower.a_ratio, lower.mu_s, lower.tan_alpha);
    if (lower.a_ratio > 0.0) {
        v.no_motion = true;  // at rest: the static margin is its margin (s.6 step 8)
        v.margin = threshold / lower.a_ratio;
        v.margin_basis = "static threshold min(mu_s lower bound, tan alpha) / A";
    } else {
        v = no_motion(Model::static_initiation, "no horizontal acceleration");
    }
    return check(std::move(v), std::move(text));
}

ScreenCheck slide_check(const Sliding& s, double allowable_m) {
    if (s.slide_asce_m) {
        Verdict v =
            slide_demand_verdict(*s.slide_asce_m, allowable_m, Model::asce4_sliding, "ASCE 4 slide");
        const bool ok = passes(v);
        return check(std::move(v),
                     fmt::format("ASCE 4 slide at mu_s {:.3f}: {:.1f} mm {} allowable {:.1f} mm",
                                 s.mu_s, mm(*s.slide_asce_m), ok ? "<=" : ">", mm(allowable_m)));
    }
    if (s.c_s_mps2 > 0.0 && !s.f_es_hz) {
        // ASCE 4: the body does not slide when SA_VH never reaches C_s; the margin is how far
        // the spectrum could scale before it does.
        Verdict v = no_motion(Model::asce4_sliding, "ASCE 4: SA_VH never reaches C_s");
        if (s.sa_vh_peak_g > 0.0) {
            v.margin = s.c_s_g / s.sa_vh_peak_g;
            v.margin_basis = fmt::format("ASCE 4: C_s {:.3f} g / peak SA_VH {:.3f} g (no sliding)",
                                         s.c_s_g, s.sa_vh_peak_g);
        }
        return check(std::move(v),
                     fmt::format("ASCE 4 at mu_s {:.3f}: SA_VH never reaches C_s = {:.3f} m/s^2, "
                                 "no sliding",
                                 s.mu_s, s.c_s_mps2));
    }
    return check(inconclusive(Model::asce4_sliding, "no closed-form sliding demand: " + s.reason),
                 "the block slides but no closed form applies (" + s.reason + ")");
}

ScreenCheck rock_check(const Rocking& r, double required_fs) {
    const Model m = Model::equivalent_linear_rocking;
    if (r.overturn_predicted) {
        return check(overturn_verdict(m, "equivalent-linear estimate finds no theta below alpha"),
                     "equivalent-linear estimate: overturning predicted");
    }
    if (!r.gate_passed) {
        // The static criterion (vertical taken fully downward) predicts uplift; the gate's
        // 0.4 A_v reduction does not. A screen must not pass on the less conservative of two.
        return check(inconclusive(m, "static criterion predicts uplift, the equivalent-linear "
                                     "gate (1 - 0.4 A_v) tan(alpha) does not"),
                     fmt::format("static uplift (A > tan alpha) but PGA below the "
                                 "equivalent-linear gate {:.3f} g: the screens disagree",
                                 r.gate_g));
    }
    if (!r.theta_rad) {
        return check(inconclusive(m, r.el_reason), r.el_reason);
    }
    if (!r.overturn_fs || *r.theta_rad < no_motion_rock_rad) {
        return check(no_motion(m, "equivalent-linear theta below 0.003 rad (no motion)"),
                     "equivalent-linear theta below 0.003 rad: no motion");
    }
    Verdict v = fs_verdict(*r.overturn_fs, required_fs, m, "equivalent-linear");
    const bool ok = passes(v);
    return check(std::move(v), fmt::format("equivalent-linear FS {:.2f} {} required {:.2f}",
                                           *r.overturn_fs, ok ? ">=" : "<", required_fs));
}

bool rocking_mode(Mode m) { return m == Mode::rock || m == Mode::slide_rock; }
bool sliding_mode(Mode m) { return m == Mode::slide || m == Mode::slide_rock; }

Verdict screen_verdict(const Screen& s) {
    std::optional<Verdict> out;
    for (const ScreenCheck* c : {&s.rest, &s.slide, &s.rock}) {
        if (!c->applies) continue;
        out = out ? combine(*out, c->verdict) : c->verdict;
    }
    return out.value_or(Verdict{});
}

std::string flexible_condition(const LevelResult& l) {
    return fmt::format(
        "flexible-body flag at PGA {:.3f} g, {} ({}): a flexible body may uplift below the "
        "static threshold (frequency-induced rocking), which the rigid-block models accepting "
        "this level cannot show",
        l.pga_g, to_string(l.direction), l.flexible.basis);
}

std::string stat_name(const Simulation& sim) {
    return fmt::format("84th percentile of {} sets", sim.histories);
}

// "k/N (95% a-b%)" of an exceedance count.
std::string simulation_trail_line(const Simulation& sim) {
    std::string line = fmt::format(
        "{} sets (the 84th percentile governs): peak slip mean/84th/max {:.1f}/{:.1f}/{:.1f} mm "
        "at mu_s {:.3f}, beyond the allowable {}; theta/alpha {:.3f}/{:.3f}/{:.3f} at mu_s "
        "{:.3f}, r {:.3f}, beyond 1/FS {}; overturned {}",
        sim.histories, mm(sim.slide_m.mean), mm(sim.slide_m.p84), mm(sim.slide_m.max),
        sim.sliding_bound.mu_s, exceedance_text(sim.slide_exceed), sim.rock_over_alpha.mean,
        sim.rock_over_alpha.p84, sim.rock_over_alpha.max, sim.rocking_bound.mu_s,
        sim.rocking_bound.restitution, exceedance_text(sim.rock_exceed),
        exceedance_text(Exceedance{sim.overturned, sim.histories, sim.overturn_ci}));
    if (sim.rocking_other) {
        const RockingRuns& o = *sim.rocking_other;
        line += fmt::format("; at the other restitution bound r {:.3f}: theta/alpha "
                            "{:.3f}/{:.3f}/{:.3f}, overturned {}/{} (the worse governs)",
                            o.bound.restitution, o.over_alpha.mean, o.over_alpha.p84,
                            o.over_alpha.max, o.overturned, sim.histories);
    }
    return line;
}

std::string flexible_trail_line(const FlexibleSimulation& f) {
    const Simulation& sim = f.sim;
    return fmt::format(
        "flexible body ({:.3g} Hz, damping {:.3g}, modal mass {:.3g} M at {:.3g} m), {} "
        "histories: base uplifted in {}; peak modal displacement mean/max {:.1f}/{:.1f} mm; peak "
        "slip mean/84th/max {:.1f}/{:.1f}/{:.1f} mm; theta/alpha {:.3f}/{:.3f}/{:.3f}; "
        "overturned {}/{}",
        f.frequency_hz, f.damping, f.mass_fraction, f.height_m, sim.histories, f.uplifted,
        mm(f.modal_m.mean), mm(f.modal_m.max), mm(sim.slide_m.mean), mm(sim.slide_m.p84),
        mm(sim.slide_m.max), sim.rock_over_alpha.mean, sim.rock_over_alpha.p84,
        sim.rock_over_alpha.max, sim.overturned, sim.histories);
}

// A verdict of no motion without a demand ratio (nothing moved at all) takes the level's
// static margin, the threshold acceleration over the demand: never "infinite", so a level at
// rest cannot govern over one that moves (docs/methods.md s.6 step 8).
Verdict with_static_margin(Verdict v, const LevelResult& level) {
    if (v.margin || !v.no_motion) return v;
    const Initiation& i = level.initiation_lower;
    if (i.a_ratio <= 0.0) return v;
    v.margin = std::min(i.mu_s, i.tan_alpha) / i.a_ratio;
    v.margin_basis += fmt::format("; static margin min(mu_s {:.3f}, tan alpha {:.3f}) / A {:.3f}",
                                  i.mu_s, i.tan_alpha, i.a_ratio);
    return v;
}

}  // namespace

Screen screen_level(const LevelResult& closed, double allowable_slide_m, double required_fs) {
    Screen s;
    if (closed.initiation_lower.mode == Mode::rest) {
        // At rest at the lower friction bound means at rest at the upper one too.
        s.rest = rest_check(closed.initiation_lower);
    }
    if (sliding_mode(closed.initiation_lower.mode)) {
        s.slide = slide_check(closed.sliding, allowable_slide_m);
    }
    if (rocking_mode(closed.initiation.mode)) s.rock = rock_check(closed.rocking, required_fs);
    s.passed = s.rest.passed && s.slide.passed && s.rock.passed;
    return s;
}

SimulationNeed simulation_need(const Screen& screen, SimulatePolicy policy) {
    switch (policy) {
        case SimulatePolicy::never:
            return {false, screen.passed
                               ? "not simulated: the screen passed (options.simulate = \"never\")"
                               : "not simulated although the screen failed: options.simulate = "
                                 "\"never\", so the screen decides the failure"};
        case SimulatePolicy::always:
            return {true, screen.passed
                              ? "simulated because options.simulate = \"always\"; the screen "
                                "passed and decides, the simulation is reported beside it"
                              : "simulated: the screen failed, so the simulation is required and "
                                "governs (docs/methods.md s.6 step 4)"};
        case SimulatePolicy::automatic:
            break;
    }
    if (screen.passed) return {false, "not simulated: the screen passed"};
    return {true,
            "simulated: the screen failed, so the simulation is required and governs "
            "(docs/methods.md s.6 step 4)"};
}

Verdict simulation_verdict(const Simulation& sim, double allowable_slide_m, double required_fs,
                           const BiaxialSlide* biaxial) {
    const std::string stat = stat_name(sim);
    if (sim.overturned > 0) {
        return overturn_verdict(
            Model::simulation_rocking,
            fmt::format("{} of {} histories overturned (95% interval {:.0f}-{:.0f}%); any "
                        "overturn fails the level",
                        sim.overturned, sim.histories, 100.0 * sim.overturn_ci[0],
                        100.0 * sim.overturn_ci[1]));
    }
    // The biaxial peak |u|, when it ran, is the sliding demand (docs/methods.md s.10).
    const bool bi = biaxial && biaxial->ran;
    const double slide_m = sim.governing(bi ? biaxial->slide_m : sim.slide_m);
    const Verdict slide = slide_demand_verdict(
        slide_m, allowable_slide_m, bi ? Model::simulation_biaxial_slide : Model::simulation_slide,
        fmt::format("simulated {} ({})", bi ? "biaxial peak |u|" : "peak slip", stat));
    Verdict rock;
    const double theta_rad = sim.governing(sim.rock_rad);
    const double theta_over_alpha = sim.governing(sim.rock_over_alpha);
    if (theta_rad < no_motion_rock_rad) {
        rock = no_motion(Model::simulation_rocking,
                         fmt::format("simulated peak rotation ({}) {:.4f} rad < 0.003 rad (no "
                                     "motion)",
                                     stat, theta_rad));
        if (theta_over_alpha > 0.0) rock.margin = 1.0 / (theta_over_alpha * required_fs);
    } else {
        rock = fs_verdict(1.0 / theta_over_alpha, required_fs, Model::simulation_rocking,
                          fmt::format("simulated, {}", stat));
    }
    if (slide.no_motion && rock.no_motion) {
        Verdict v = no_motion(Model::simulation_rocking,
                              fmt::format("simulated ({}) peak slip {:.2f} mm < 1 mm and peak "
                                          "rotation {:.4f} rad < 0.003 rad (no motion)",
                                          stat, mm(slide_m), theta_rad));
        // The smaller of the two demand ratios that exist (none when nothing moved at all).
        for (const Verdict* part : std::array<const Verdict*, 2>{&slide, &rock})
            if (part->margin && (!v.margin || *part->margin < *v.margin)) v.margin = part->margin;
        return v;
    }
    return combine(slide, rock);
}

namespace {
std::string body3d_trail_line(const Body3dLevel& b) {
    if (!b.ran) return "3D body not run: " + b.reason;
    const Simulation& sim = b.sim;
    const auto ratio = [](const std::optional<double>& r) {
        return r ? fmt::format("{:.2f} x the planar", *r) : std::string("the planar is nil");
    };
    const std::string step_check =
        b.step_checked
            ? fmt::format("step check on the governing history {}: peak tilt over critical "
                          "{:.4f}{} and peak |u| {:.1f} mm at dt {:g} s, {:.4f}{} and {:.1f} mm "
                          "at {:g} s",
                          sim.governing_history + 1, b.run_tilt_over_critical,
                          b.run_overturned ? " (overturned)" : "", mm(b.run_slide_m), b.dt_s,
                          b.check_tilt_over_critical, b.check_overturned ? " (overturned)" : "",
                          mm(b.check_slide_m), b.check_dt_s)
            : std::string("step check not run");
    return fmt::format(
        "3D body (h1 along x, h2 along y, the vertical; dt {:g} s): {} of {} overturned; peak tilt "
        "over critical 84th {:.3f} ({}, {:.3f}); peak |u| 84th {:.1f} mm at mu_s {:.3f} ({}, "
        "{:.1f} mm); peak twist 84th {:.4f} rad; {}",
        b.dt_s, sim.overturned, sim.histories, sim.governing(sim.rock_over_alpha),
        ratio(b.rock_ratio), b.planar_rock_over_alpha, mm(sim.governing(sim.slide_m)),
        sim.sliding_bound.mu_s, ratio(b.slide_ratio), mm(b.planar_slide_m),
        sim.governing(b.twist_rad), step_check) +
           (b.flexible ? fmt::format("; carrying the flexible body's {}: peak |q| 84th {:.1f} mm",
                                     b.mode_text, mm(b.modal_m.p84))
                       : std::string());
}

std::string biaxial_trail_line(const Simulation& sim, const BiaxialSlide& b) {
    if (!b.ran) return "biaxial sliding not run: " + b.reason;
    const std::string vs =
        b.ratio ? fmt::format("{:.2f} x the larger planar peak slip, {:.1f} mm ({})", *b.ratio,
                              mm(b.planar_governing_m), to_string(b.planar_direction))
                : "the planar peak slips are nil";
    return fmt::format("biaxial sliding (h1 along x, h2 along y, with the vertical): peak |u| "
                       "mean/84th/max {:.1f}/{:.1f}/{:.1f} mm at mu_s {:.3f}; {} {:.1f} mm is {}",
                       mm(b.slide_m.mean), mm(b.slide_m.p84), mm(b.slide_m.max),
                       sim.sliding_bound.mu_s, "the 84th percentile", mm(sim.governing(b.slide_m)),
                       vs);
}
}  // namespace

// The 3D body's verdict: its runs under the planar rules, with its name.
Verdict body3d_verdict(const Body3dLevel& b, double allowable_slide_m, double required_fs) {
    Verdict v = simulation_verdict(b.sim, allowable_slide_m, required_fs);
    v.decided_by = b.flexible ? Model::simulation_3d_flexible : Model::simulation_3d;
    v.margin_basis = "3D body: " + v.margin_basis;
    return v;
}

bool body3d_decides(const LevelResult& level) {
    return level.body3d && level.body3d->ran &&
           (!level.flexible_simulation || level.body3d->flexible);
}

Verdict decide_level(const LevelResult& level, double allowable_slide_m, double required_fs) {
    const Body3dLevel* body3d = level.body3d && level.body3d->ran ? &*level.body3d : nullptr;
    if (body3d_decides(level)) {
        // The body can uplift: the 3D body decides (docs/methods.md s.11), carrying the mode
        // where the flag is raised; the planar runs, flexible ones included, stay beside.
        Verdict v = body3d_verdict(*body3d, allowable_slide_m, required_fs);
        // Carrying the mode, the 3D body resolves the flag, as the flexible model does.
        if (level.flexible.raised && !body3d->flexible && passes(v))
            v.conditions.push_back(flexible_condition(level));
        return with_static_margin(v, level);
    }
    if (level.flexible_simulation) {
        // A raised flag resolved by the flexible model: its result decides (s.10).
        Verdict v = simulation_verdict(level.flexible_simulation->sim, allowable_slide_m, required_fs);
        v.decided_by = Model::simulation_flexible;
        v.margin_basis = "flexible body: " + v.margin_basis;
        // Neither model has both effects, so where biaxial sliding ran too the sliding demand is
        // the larger of the flexible body's planar slip and the rigid block's biaxial |u| (s.10).
        if (level.biaxial && level.biaxial->ran) {
            const Simulation& sim = level.flexible_simulation->sim;
            v = combine(v, slide_demand_verdict(
                               sim.governing(level.biaxial->slide_m), allowable_slide_m,
                               Model::simulation_biaxial_slide,
                               fmt::format("simulated biaxial peak |u| of the rigid block ({})",
                                           stat_name(sim))));
        }
        // A rigid 3D body beside the flexible one: neither has both the mode and the third
        // dimension, and the worse of the two governs.
        if (body3d) v = combine(v, body3d_verdict(*body3d, allowable_slide_m, required_fs));
        return with_static_margin(v, level);
    }
    Verdict v = screen_verdict(level.screen);
    if (!level.screen.passed && level.simulation) {
        v = simulation_verdict(*level.simulation, allowable_slide_m, required_fs,
                               level.biaxial ? &*level.biaxial : nullptr);
    }
    if (level.flexible.raised && passes(v)) v.conditions.push_back(flexible_condition(level));
    return with_static_margin(v, level);
}

std::vector<std::string> decision_trail(const LevelResult& level, double allowable_slide_m,
                                        double required_fs) {
    std::vector<std::string> out;
    const Screen& s = level.screen;
    std::vector<std::string> checks;
    for (const auto& [name, c] : {std::pair{"static", &s.rest}, std::pair{"sliding", &s.slide},
                                  std::pair{"rocking", &s.rock}}) {
        if (c->applies) checks.push_back(fmt::format("{}: {} ({})", name, c->text,
                                                     c->passed ? "passes" : "fails"));
    }
    out.push_back(fmt::format("screen {}: {}", s.passed ? "passed" : "failed",
                              fmt::join(checks, "; ")));
    out.push_back(level.simulation_reason);
    if (!level.model.empty()) {
        out.push_back(fmt::format("model: {}; why: {}", level.model, level.model_reason));
    }
    if (level.simulation) {
        const Simulation& sim = *level.simulation;
        out.push_back(simulation_trail_line(sim));
        if (level.biaxial) out.push_back(biaxial_trail_line(sim, *level.biaxial));
        if (level.body3d) out.push_back(body3d_trail_line(*level.body3d));
        const bool by_3d = body3d_decides(level);
        if (level.flexible_simulation) {
            out.push_back(flexible_trail_line(*level.flexible_simulation));
            const Verdict beside = simulation_verdict(sim, allowable_slide_m, required_fs);
            if (by_3d) {
                const Verdict flexible = simulation_verdict(level.flexible_simulation->sim,
                                                            allowable_slide_m, required_fs);
                out.push_back(fmt::format(
                    "the 3D body carrying the mode decides; beside it the planar flexible body "
                    "of direction {} gives {}, margin {}, and the rigid planar simulation {}, "
                    "margin {}",
                    to_string(level.direction), passes(flexible) ? "a pass" : "a FAILURE",
                    margin_text(flexible), passes(beside) ? "a pass" : "a FAILURE",
                    margin_text(beside)));
            } else {
                out.push_back(fmt::format(
                    "the flexible-body model decides; the rigid planar simulation beside it "
                    "gives {}, margin {}",
                    passes(beside) ? "a pass" : "a FAILURE", margin_text(beside)));
            }
        } else if (by_3d) {
            const Verdict beside = simulation_verdict(sim, allowable_slide_m, required_fs,
                                                      level.biaxial ? &*level.biaxial : nullptr);
            out.push_back(fmt::format(
                "the 3D body decides; the planar simulation of direction {} beside it gives {}, "
                "margin {}",
                to_string(level.direction), passes(beside) ? "a pass" : "a FAILURE",
                margin_text(beside)));
        } else if (s.passed) {
            // Reported beside the screen, which decides: say so when the two disagree.
            const Verdict beside = simulation_verdict(sim, allowable_slide_m, required_fs,
                                                      level.biaxial ? &*level.biaxial : nullptr);
            out.push_back(fmt::format(
                "the screen decides; the simulation beside it gives {}, margin {}{}",
                passes(beside) ? "a pass" : "a FAILURE", margin_text(beside),
                passes(beside) ? "" : ": the screen is not conservative here"));
        }
    }
    const Verdict& v = level.verdict;
    out.push_back(fmt::format("governed by {}: {}, margin {} ({})", to_string(v.decided_by),
                              passes(v) ? std::string("passes")
                                        : fmt::format("fails ({})", to_string(v.failure)),
                              margin_text(v), v.margin_basis));
    return out;
}

void redecide_level(LevelResult& level, const Component& component) {
    level.verdict =
        decide_level(level, component.allowable_slide_m, component.required_overturn_fs);
    level.trail =
        decision_trail(level, component.allowable_slide_m, component.required_overturn_fs);
}

bool passes(const Verdict& v) {
    return v.kind == VerdictKind::acceptable || v.kind == VerdictKind::acceptable_with_clearance;
}

bool more_severe(const Verdict& a, const Verdict& b) {
    if (passes(a) != passes(b)) return !passes(a);
    // A passing level that moves governs over one at rest, whatever their margins: a low level
    // at rest cannot hide a higher one that moves (docs/methods.md s.6 step 8).
    if (passes(a) && a.no_motion != b.no_motion) return !a.no_motion;
    constexpr double inf = std::numeric_limits<double>::infinity();
    const double ma = a.margin.value_or(inf);
    const double mb = b.margin.value_or(inf);
    if (ma != mb) return ma < mb;
    return a.clearance_m > b.clearance_m;
}

Governing governing_of(const std::vector<LevelResult>& levels) {
    std::size_t gov = 0;
    for (std::size_t i = 1; i < levels.size(); ++i) {
        if (more_severe(levels[i].verdict, levels[gov].verdict)) gov = i;
    }
    const LevelResult& l = levels.at(gov);
    return Governing{gov, l.pga_g, l.direction, l.verdict};
}

double clearance_needed_m(const std::vector<LevelResult>& levels) {
    double out = 0.0;
    for (const LevelResult& l : levels) {
        if (passes(l.verdict)) out = std::max(out, l.verdict.clearance_m);
    }
    return out;
}

std::vector<std::string> open_conditions(const std::vector<LevelResult>& levels) {
    std::vector<std::string> where;
    std::string basis;
    for (const LevelResult& l : levels) {
        if (l.verdict.conditions.empty()) continue;
        where.push_back(fmt::format("{:.3f} g {}", l.pga_g, to_string(l.direction)));
        basis = l.flexible.basis;
    }
    if (where.empty()) return {};
    return {fmt::format(
        "flexible-body flag raised at levels the rigid model accepts (PGA {}; {}): a flexible "
        "body may uplift below the static threshold (frequency-induced rocking, Saraswat 2017; "
        "docs/methods.md s.2), "
        "which the rigid-block models cannot show. The verdict holds at these levels only if the "
        "component is shown to respond as a rigid body (fixed-base frequency well above the "
        "band) or by test; the flexible-body model (docs/methods.md s.10) did not run there "
        "(it needs the fixed-base frequency and a simulation the case allows).",
        fmt::join(where, ", "), basis)};
}

std::string verdict_text(const Verdict& v) {
    switch (v.kind) {
        case VerdictKind::acceptable:
            return "free-standing acceptable";
        case VerdictKind::acceptable_with_clearance: {
            // Whole mm, rounded up, guarded: 0.047000000001 m is 47 mm, not 48.
            const double clear_mm = core::steps_covering(v.clearance_m * 1000.0);
            return fmt::format("acceptable with clearance >= {:.0f} mm", clear_mm);
        }
        case VerdictKind::change_material: {
            std::string out = v.material.empty() ? "change base material"
                                                 : "change base material to " + v.material;
            if (!v.mechanism.empty()) out += " (" + v.mechanism + ")";
            return out;
        }
        case VerdictKind::anchor:
            return "anchor";
    }
    return "";
}

bool verdict_text_fits(VerdictKind kind, std::string_view text) {
    Verdict v;
    v.kind = kind;
    switch (kind) {
        case VerdictKind::acceptable:
        case VerdictKind::anchor:
            return text == verdict_text(v);
        case VerdictKind::acceptable_with_clearance: {
            constexpr std::string_view head = "acceptable with clearance >= ";
            constexpr std::string_view tail = " mm";
            if (text.size() <= head.size() + tail.size() || text.substr(0, head.size()) != head ||
                text.substr(text.size() - tail.size()) != tail)
                return false;
            const std::string_view mm = text.substr(head.size(), text.size() - head.size() - tail.size());
            return std::all_of(mm.begin(), mm.end(), [](char c) { return c >= '0' && c <= '9'; });
        }
        case VerdictKind::change_material: {
            const std::string head = verdict_text(v);  // "change base material", no material
            return text.substr(0, head.size()) == head;
        }
    }
    return false;
}

std::string margin_text(const Verdict& v) {
    if (v.no_motion) return v.margin ? fmt::format("{:.2f} (no motion)", *v.margin) : "no motion";
    return v.margin ? fmt::format("{:.2f}", *v.margin) : "n/a";
}

}  // namespace freestand::assess
