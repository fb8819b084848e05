#include "assess/body3d_level.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "assess/flexible_level.hpp"
#include "assess/level_runs.hpp"
#include "assess/run_cache.hpp"
#include "assess/settle.hpp"
#include "assess/verdict.hpp"
#include "core/parallel.hpp"
#include "core/statistics.hpp"

namespace freestand::assess {

bool uplifts(Mode m) { return m == Mode::rock || m == Mode::slide_rock || m == Mode::flight; }

namespace {

// The 3D runs of every set in use at one friction bound (slot 0 sliding, 1 rocking), kept from
// batch to batch of the settling like the planar runs.
std::vector<dynamics::Body3dSummary> runs_at(const dynamics::Body3dModel& model,
                                             const std::vector<dynamics::BiaxialExcitation>& ex,
                                             double pga_g, const dynamics::Body3dOptions& options,
                                             int slot, HistoryBank& bank) {
    std::vector<dynamics::Body3dSummary> out(ex.size());
    RunTable<dynamics::Body3dSummary>* kept =
        bank.level_runs() ? &bank.level_runs()->body3d(slot, ex.size()) : nullptr;
    core::parallel_for(ex.size(), bank.run().threads, [&](std::size_t k) {
        out[k] = remembered(kept, k, [&] {
            return body3d_run(bank.run().run_cache, model, ex[k],
                              bank.excitation_key(k, 2, pga_g, ex[k]), options);
        });
    });
    return out;
}

// The bound's friction and restitution: a measured r scales every impact's loss (Body3dModel::
// angular_restitution); a bound at Housner's value is the plastic impact (his rule generalised).
dynamics::Body3dModel model_at(const Component& c, const ContactBound& bound,
                              const std::optional<dynamics::Body3dMode>& mode) {
    const std::optional<double> r =
        bound.housner ? std::nullopt : std::optional<double>(bound.restitution);
    const auto rigid =
        dynamics::make_body3d_model(component_body3d(c), bound.mu_s, bound.mu_k, 0.0, r);
    return mode ? dynamics::with_mode(rigid, *mode) : rigid;
}

// One restitution bound's rocking, as the planar runs report it.
RockingRuns rocking_of(const ContactBound& bound, const std::vector<dynamics::Body3dSummary>& runs) {
    RockingRuns out;
    out.bound = bound;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> over, rad;
    for (const dynamics::Body3dSummary& s : runs) {
        out.overturned += s.overturned ? 1 : 0;
        over.push_back(s.overturned ? nan : s.tilt_max_over_critical);
        rad.push_back(s.overturned ? nan : s.tilt_max_rad);
    }
    out.over_alpha = stats_of(over);
    out.rad = stats_of(rad);
    return out;
}

// The 3D runs at each bound slot (0 sliding, 1 rocking, 2 rocking at the lower restitution;
// 1 and 2 empty when they would repeat 0 or do not exist).
struct SlotRuns {
    std::array<std::vector<dynamics::Body3dSummary>, 3> slot;
    const std::vector<dynamics::Body3dSummary>& rocking() const {
        return slot[1].empty() ? slot[0] : slot[1];
    }
};

// The runs as the planar statistics: slide at the sliding bound, tilt at the worse restitution
// bound (more overturned sets, then the larger 84th percentile, as the planar runs), any
// overturn counting.
Simulation as_simulation(const SlotRuns& runs, const DirectionBounds& bounds, bool bounds_differ,
                         const Component& c, std::size_t& rock_slot) {
    const auto& slide = runs.slot[0];
    Simulation sim;
    sim.histories = static_cast<int>(slide.size());
    sim.sliding_bound = bounds.sliding;
    sim.bounds_differ = bounds_differ;
    RockingRuns upper = rocking_of(bounds.rocking, runs.rocking());
    rock_slot = runs.slot[1].empty() ? 0 : 1;
    if (bounds.rocking_lower) {
        RockingRuns lower = rocking_of(*bounds.rocking_lower, runs.slot[2]);
        if (worse(lower, upper)) {
            std::swap(lower, upper);
            rock_slot = 2;
        }
        sim.rocking_other = std::move(lower);
    }
    const auto& rock = runs.slot[rock_slot];
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> slide_m;
    double worst = -1.0;
    for (std::size_t k = 0; k < slide.size(); ++k) {
        bool overturned = false;
        for (const auto& r : runs.slot) overturned = overturned || (!r.empty() && r[k].overturned);
        sim.overturned_sets.push_back(overturned ? 1 : 0);
        sim.overturned += overturned ? 1 : 0;
        // A body that tips over carries its footprint centre with it: no slide to report.
        slide_m.push_back(slide[k].overturned ? nan : slide[k].slide_max_m);
        const double score = overturned ? 1e9 : rock[k].tilt_max_over_critical;
        if (score > worst) {
            worst = score;
            sim.governing_history = static_cast<int>(k);
        }
    }
    sim.rocking_bound = upper.bound;
    sim.rock_over_alpha = std::move(upper.over_alpha);
    sim.rock_rad = std::move(upper.rad);
    sim.slide_m = stats_of(slide_m);
    sim.overturn_ci = core::clopper_pearson(sim.overturned, sim.histories);
    count_exceedances(sim, c.allowable_slide_m, c.required_overturn_fs);
    return sim;
}

std::optional<double> ratio(double body3d, double planar) {
    if (planar > 0.0) return body3d / planar;
    return std::nullopt;
}

// Every history with the 3D body at both bounds, with the planar governing demands beside.
Body3dLevel run_body3d(const Case& c, const LevelDemand& demand, const LevelResult& x,
                       const LevelResult& y, const std::optional<dynamics::Body3dMode>& mode,
                       HistoryBank& bank) {
    std::vector<dynamics::BiaxialExcitation> ex;
    for (const HistorySet& set : bank.sets())
        ex.push_back(dynamics::biaxial_excitation_from_records(set.h1, set.h2, demand.pga_g,
                                                               &set.v));
    const dynamics::Body3dOptions options = body3d_options(c.site.g_mps2);
    const DirectionBounds& bounds = x.bounds;
    const bool differ = bounds.sliding.mu_s != bounds.rocking.mu_s ||
                        bounds.sliding.mu_k != bounds.rocking.mu_k;
    const std::array<dynamics::Body3dModel, 3> models{
        model_at(c.component, bounds.sliding, mode), model_at(c.component, bounds.rocking, mode),
        model_at(c.component, bounds.rocking_lower.value_or(bounds.rocking), mode)};
    SlotRuns runs;
    runs.slot[0] = runs_at(models[0], ex, demand.pga_g, options, 0, bank);
    if (differ) runs.slot[1] = runs_at(models[1], ex, demand.pga_g, options, 1, bank);
    if (bounds.rocking_lower)
        runs.slot[2] = runs_at(models[2], ex, demand.pga_g, options, 2, bank);
    Body3dLevel b;
    b.ran = true;
    b.dt_s = options.dt_s;
    std::size_t rock_slot = 1;
    b.sim = as_simulation(runs, bounds, differ, c.component, rock_slot);
    const auto& rock = runs.slot[rock_slot];
    const dynamics::Body3dModel& rocking_model = models[rock_slot];
    std::vector<double> twist, modal;
    for (const auto& s : rock) {
        twist.push_back(s.twist_max_rad);
        modal.push_back(s.modal_max_m);
        for (std::size_t i = 0; i < b.time_in_state_s.size(); ++i)
            b.time_in_state_s[i] += s.time_in_state_s[i] / static_cast<double>(rock.size());
    }
    for (const auto& r : runs.slot)
        for (const auto& s : r) b.unconverged_steps += static_cast<int>(s.unconverged_steps);
    b.twist_rad = stats_of(twist);
    if (mode) {
        b.flexible = true;
        b.modal_m = stats_of(modal);
        b.mode_text = fmt::format("mode {:.3g} Hz along x and y, damping {:.3g}, modal mass "
                                  "{:.3g} M at {:.3g} m",
                                  mode->frequency_x_hz, mode->damping, mode->mass_fraction,
                                  mode->height_m);
    }
    // The step's error on the governing history: the same run at a sixteenth of the step, where
    // the overturn counts of docs/methods.md s.11's step study have converged.
    const auto k = static_cast<std::size_t>(b.sim.governing_history);
    if (c.options.step_check) {
        dynamics::Body3dOptions fine = options;
        fine.dt_s = options.dt_s / 16.0;
        const dynamics::Body3dSummary check =
            body3d_run(bank.run().run_cache, rocking_model, ex[k],
                       bank.excitation_key(k, 2, demand.pga_g, ex[k]), fine);
        b.step_checked = true;
        b.check_dt_s = fine.dt_s;
        b.check_tilt_over_critical = check.tilt_max_over_critical;
        b.check_overturned = check.overturned;
        b.check_slide_m = check.slide_max_m;
    }
    b.run_tilt_over_critical = rock[k].tilt_max_over_critical;
    b.run_overturned = rock[k].overturned;
    b.run_slide_m = rock[k].slide_max_m;
    // The like-for-like planar model: the flexible body's runs where the 3D body carries the
    // mode, else the rigid block's.
    for (const LevelResult* l : {&x, &y}) {
        const Simulation* planar = mode && l->flexible_simulation ? &l->flexible_simulation->sim
                                   : l->simulation                 ? &*l->simulation
                                                                   : nullptr;
        if (!planar) continue;
        const Simulation& p = *planar;
        b.planar_rock_over_alpha = std::max(b.planar_rock_over_alpha, p.governing(p.rock_over_alpha));
        b.planar_slide_m = std::max(b.planar_slide_m, p.governing(p.slide_m));
    }
    b.rock_ratio = ratio(b.sim.governing(b.sim.rock_over_alpha), b.planar_rock_over_alpha);
    b.slide_ratio = ratio(b.sim.governing(b.sim.slide_m), b.planar_slide_m);
    return b;
}

}  // namespace

dynamics::Body3dOptions body3d_options(double g_mps2) {
    dynamics::Body3dOptions o;
    o.dt_s = 1e-3;
    o.solver_tol = 1e-8;
    o.max_sweeps = 100;
    o.record_series = false;
    o.g_mps2 = g_mps2;
    return o;
}

dynamics::Body3d component_body3d(const Component& c) {
    return body3d_of_blocks(c.block(Direction::x), c.block(Direction::y), c.mass_kg,
                            c.cg_height_m);
}

dynamics::Body3d body3d_of_blocks(const block::Block& bx, const block::Block& by, double mass_kg,
                                  double cg_height_m) {
    dynamics::Body3d body;
    body.mass_kg = mass_kg;
    body.h_m = cg_height_m;
    // Counter-clockwise from the corner at the left edges of both planar geometries.
    body.footprint_m = {{-bx.b_left_m, -by.b_left_m},
                        {bx.b_right_m, -by.b_left_m},
                        {bx.b_right_m, by.b_right_m},
                        {-bx.b_left_m, by.b_right_m}};
    const double wx = bx.b_left_m + bx.b_right_m;
    const double wy = by.b_left_m + by.b_right_m;
    body.inertia_cg_kgm2 = Eigen::Vector3d(by.inertia_cg_kgm2, bx.inertia_cg_kgm2,
                                           mass_kg * (wx * wx + wy * wy) / 12.0)
                               .asDiagonal();
    return body;
}

std::optional<std::string> no_uplift_reason(const LevelResult& x, const LevelResult& y) {
    if (uplifts(x.initiation.mode) || uplifts(y.initiation.mode)) return std::nullopt;
    return fmt::format("at the upper friction bound direction x is {} and y is {}: no component "
                       "reaches its axis's g tan(alpha), so no plan direction uplifts",
                       to_string(x.initiation.mode), to_string(y.initiation.mode));
}

namespace {

int flexible_uplifts(const LevelResult& l) {
    return l.flexible_simulation ? l.flexible_simulation->uplifted : 0;
}

// Why the 3D body does not run at this PGA, or nullopt: the rigid body cannot uplift in any
// direction. Where only the flexible body lifts its base, its planar runs decide: the 3D body
// carrying the mode with the rigid classification at rest or sliding costs 10 to 20 times the
// rigid 3D runs (every step solved; docs/methods.md s.11).
std::optional<std::string> body3d_not_needed(const LevelResult& x, const LevelResult& y) {
    auto why = no_uplift_reason(x, y);
    if (why && (flexible_uplifts(x) > 0 || flexible_uplifts(y) > 0))
        *why += fmt::format("; the flexible body lifted its base (x in {} sets, y in {}), and "
                            "its planar runs decide",
                            flexible_uplifts(x), flexible_uplifts(y));
    return why;
}

std::string body3d_reason(const LevelResult& x, const LevelResult& y, const Body3dLevel& b) {
    const std::string carrying =
        b.flexible ? fmt::format(", carrying the flexible body's {}", b.mode_text) : "";
    return fmt::format(
        "the body can uplift at the upper bounds (x {}, y {}): rocking about edges and "
        "corners, sliding and twisting at once, the 3D body decides (docs/methods.md "
        "s.11), at the planar runs' friction and restitution bounds{}",
        to_string(x.initiation.mode), to_string(y.initiation.mode), carrying);
}

}  // namespace

dynamics::Body3dMode body3d_mode(const Component& c, const ContactBound& bound) {
    // The planar flexible model resolves the modal mass and height (a uniform cantilever's
    // when the case gives none); the one fixed-base frequency acts along both axes.
    const dynamics::FlexibleModel planar = flexible_model(c, bound, Direction::x);
    return dynamics::Body3dMode{planar.frequency_hz, planar.frequency_hz, planar.damping,
                                planar.mass_fraction, planar.height_m};
}

std::optional<dynamics::Body3dMode> flexible_mode(const Case& c, const LevelResult& x,
                                                  const LevelResult& y) {
    if (!x.flexible_simulation && !y.flexible_simulation) return std::nullopt;
    return body3d_mode(c.component, x.bounds.rocking);
}

void apply_body3d(const Case& c, const LevelDemand& demand, std::vector<LevelResult*> levels,
                  HistoryBank& bank) {
    if (levels.size() != 2 || (!levels[0]->simulation && !levels[1]->simulation)) return;
    const std::optional<dynamics::Body3dMode> mode = flexible_mode(c, *levels[0], *levels[1]);
    const auto why_not = body3d_not_needed(*levels[0], *levels[1]);
    std::optional<Body3dLevel> runs;
    for (LevelResult* l : levels) {
        if (!l->simulation) continue;
        Body3dLevel b;
        if (why_not) {
            b.reason = *why_not;
        } else if (!decided_by_sets(*l)) {
            b.reason = "the screen passed and decides this direction";
        } else {
            if (!runs) runs = run_body3d(c, demand, *levels[0], *levels[1], mode, bank);
            b = *runs;
            b.reason = body3d_reason(*levels[0], *levels[1], b);
            if (b.flexible) {
                l->model = body3d_flexible_model_name;
                l->model_reason = b.reason + "; the planar runs of each direction, the flexible "
                                             "body's and the rigid block's, stay beside it";
            } else if (l->flexible_simulation) {
                l->model_reason += "; the 3D rigid body ran too (" + b.reason +
                                   "): the worse of the two verdicts governs";
            } else {
                l->model = body3d_model_name;
                l->model_reason = b.reason + "; the planar runs of each direction stay beside it";
            }
        }
        l->body3d = std::move(b);
        redecide_level(*l, c.component);
    }
}

}  // namespace freestand::assess
