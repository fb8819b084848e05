#include "assess/pipeline.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "assess/biaxial_level.hpp"
#include "assess/histories.hpp"
#include "assess/joined.hpp"
#include "assess/level.hpp"
#include "assess/materials.hpp"
#include "assess/plot_data.hpp"
#include "assess/settle.hpp"
#include "assess/verdict.hpp"
#include "core/errors.hpp"
#include "core/limits.hpp"

namespace freestand::assess {

namespace {

// Every PGA level, each settled on as many sets as its decision needs (assess/settle.hpp).
std::vector<LevelResult> evaluate_all(const Case& c, const std::vector<LevelDemand>& demands,
                                      HistoryBank& bank) {
    std::vector<LevelResult> out;
    for (std::size_t i = 0; i < demands.size(); ++i) {
        for (LevelResult& l : evaluate_settled(c, demands[i], i, bank))
            out.push_back(std::move(l));
    }
    return out;
}

bool any_failure(const std::vector<LevelResult>& levels, Failure a, Failure b) {
    return std::any_of(levels.begin(), levels.end(), [&](const LevelResult& l) {
        return l.verdict.failure == a || l.verdict.failure == b;
    });
}

std::string range_text(const std::array<double, 2>& r) {
    return fmt::format("mu_s {:.3g}-{:.3g}", r[0], r[1]);
}

// Why the recommended material helps, from how the own base failed and which way the
// friction moves (docs/methods.md s.6 step 7: a lower friction can be the answer).
std::string mechanism(const BaseContact& own, const std::vector<LevelResult>& own_levels,
                      const MaterialTrial& chosen) {
    const bool rocked =
        any_failure(own_levels, Failure::overturns, Failure::rocking_fs_below_required);
    const bool slid = any_failure(own_levels, Failure::slides_beyond_allowable,
                                  Failure::slides_beyond_allowable);
    const std::string change = fmt::format("{} instead of {}", range_text(chosen.mu_s_range),
                                           range_text(own.mu_s_range));
    const double mu_new = (chosen.mu_s_range[0] + chosen.mu_s_range[1]) / 2.0;
    const double mu_own = (own.mu_s_range[0] + own.mu_s_range[1]) / 2.0;
    if (mu_new < mu_own && rocked) {
        return "lower friction, " + change +
               ": it slides instead of rocking over, and the slide stays within the allowable";
    }
    if (mu_new > mu_own && slid) {
        return "higher friction, " + change + ": it slides less or stays at rest";
    }
    if (mu_new == mu_own) {
        return "same friction, restitution " +
               (chosen.restitution ? fmt::format("{:.2f}", *chosen.restitution)
                                   : std::string("Housner's")) +
               ": every level passes";
    }
    return change + ": every level passes";
}

// A passing headline: the governing level's verdict, with the largest clearance any level
// needs and every open condition.
Governing passing_headline(const std::vector<LevelResult>& levels) {
    Governing g = governing_of(levels);
    g.verdict.clearance_m = clearance_needed_m(levels);
    if (g.verdict.clearance_m >= no_motion_slide_m) {
        g.verdict.kind = VerdictKind::acceptable_with_clearance;
    }
    g.verdict.conditions = open_conditions(levels);
    return g;
}

// The verdict of a set of levels, as a case's own base and every material trial report it.
Governing headline(const std::vector<LevelResult>& levels) {
    const Governing g = governing_of(levels);
    return passes(g.verdict) ? passing_headline(levels) : g;
}

struct Search {
    Upgrade upgrade;
    double best_margin = 0.0;
    std::vector<LevelResult> recommended_levels;
};

// The governing margin of a trial (0 when it has none: a failure without a ratio).
double trial_margin(const MaterialTrial& t) { return t.governing.verdict.margin.value_or(0.0); }

// docs/methods.md s.6 step 7: each material is the case reassessed with that material's whole
// property set, through evaluate_all as for the case itself (with_base_material makes the case
// a file naming only that material would give); of those that pass, the one with the largest
// governing margin (the most robust, not the first that scrapes through; the first in table
// order on a tie).
Search search_materials(const Case& c, const std::vector<LevelDemand>& demands,
                        HistoryBank& bank) {
    Search out;
    out.upgrade.needed = true;
    for (const Material& m : materials()) {
        const Case trial_case = with_base_material(c, m.name);
        std::vector<LevelResult> levels = evaluate_all(trial_case, demands, bank);
        MaterialTrial t;
        t.material = m.name;
        t.mu_s_range = trial_case.component.base.mu_s_range;
        t.restitution = trial_case.component.base.restitution;
        t.governing = headline(levels);
        t.passes = passes(t.governing.verdict);
        const bool best = t.passes && (!out.upgrade.recommended ||
                                       trial_margin(t) > out.best_margin);
        out.upgrade.trials.push_back(t);
        if (best) {
            out.upgrade.recommended = m.name;
            out.best_margin = trial_margin(t);
            out.recommended_levels = std::move(levels);
        }
    }
    return out;
}

// Failing levels read "change base material to M" once M is known, else stay "anchor".
void apply_remedy(std::vector<LevelResult>& levels, const std::optional<std::string>& material) {
    for (LevelResult& l : levels) {
        if (passes(l.verdict) || !material) continue;
        l.verdict.kind = VerdictKind::change_material;
        l.verdict.material = *material;
    }
}

// Echo of the user target files (names, damping, scaling) and how the other dampings follow.
std::vector<std::string> target_file_assumptions(const Site& site) {
    const UserTargets& u = *site.targets;
    std::vector<std::string> out;
    if (u.y5) {
        out.push_back(fmt::format(
            "Target files instead of a design spectrum: direction x {} (damping {:.3g}), "
            "direction y {} (damping {:.3g}); every file is scaled at each level by pga_g / "
            "{:.6g} g (direction x's PSA at {:.6g} Hz, the rigid limit), so direction y's PGA is "
            "{:.6g} x pga_g; history h1 is matched to x's target and h2 to y's; each direction's "
            "initiation and flexible-body screens use its own target; the sliding and rocking "
            "demand is the vector SA_VH = sqrt(SA_H1^2 + 0.16 SA_H2^2), H1 the larger of the "
            "x and y targets (docs/methods.md s.4; ASCE 4-16).",
            u.h5.given, u.h5.spectrum.damping, u.y5->given, u.y5->spectrum.damping, u.zpa_h_g,
            u.h5.spectrum.frequency_hz.back(), u.y5->spectrum.psa_g.back() / u.zpa_h_g));
    } else {
        out.push_back(fmt::format(
            "Target files instead of a design spectrum: horizontal {} (damping {:.3g}), scaled "
            "at each level by pga_g / {:.6g} g (its PSA at {:.6g} Hz, the rigid limit); both "
            "horizontal directions receive it; the sliding and rocking demand is the vector "
            "SA_VH = sqrt(SA_H1^2 + 0.16 SA_H2^2) (docs/methods.md s.4; ASCE 4-16).",
            u.h5.given, u.h5.spectrum.damping, u.zpa_h_g, u.h5.spectrum.frequency_hz.back()));
    }
    if (u.h10 && u.y10) {
        out.push_back(fmt::format("10%-damped horizontal targets: direction x {} (damping "
                                  "{:.3g}), direction y {} (damping {:.3g}), same scale factor; "
                                  "other dampings interpolate on log damping between the 5% and "
                                  "10% files (EN 1998-1 eta scaling outside them).",
                                  u.h10->given, u.h10->spectrum.damping, u.y10->given,
                                  u.y10->spectrum.damping));
    } else if (u.h10) {
        out.push_back(fmt::format("10%-damped horizontal target: {} (damping {:.3g}), same scale "
                                  "factor; other dampings interpolate on log damping between the "
                                  "5% and 10% files (EN 1998-1 eta scaling outside them).",
                                  u.h10->given, u.h10->spectrum.damping));
    } else {
        out.push_back(
            "No 10%-damped target file: the demand at any other damping (the sliding method's "
            "and the equivalent-linear rocking's) is the 5% file scaled by the EN 1998-1 factor "
            "eta(xi) / eta(5%), eta = sqrt(10 / (5 + xi%)) >= 0.55 (meant for the amplified "
            "range; rocking::DampedSpectra).");
    }
    if (u.v) {
        out.push_back(fmt::format("Vertical target: {} (damping {:.3g}), same scale factor; "
                                  "vertical/horizontal PGA ratio {:.4f} from the files' rigid "
                                  "limits.",
                                  u.v->given, u.v->spectrum.damping, site.vertical_ratio));
    } else {
        out.push_back(fmt::format("No vertical target file: vertical target = {:.4f} x the "
                                  "horizontal target.",
                                  site.vertical_ratio));
    }
    return out;
}

std::vector<std::string> pipeline_assumptions(const Case& c) {
    std::vector<std::string> out = c.assumptions;
    if (c.site.targets) {
        for (const std::string& line : target_file_assumptions(c.site)) out.push_back(line);
    } else {
        out.push_back(
            "Both horizontal directions receive the same RG 1.60 target; the sliding and "
            "rocking demand is the vector SA_VH = sqrt(SA_H1^2 + 0.16 SA_H2^2) "
            "(docs/methods.md s.4; ASCE 4-16).");
    }
    out.push_back(
        fmt::format("Vertical PGA = {:.4f} x horizontal PGA, taken downward in the static "
                    "checks (the worst case, docs/methods.md s.5).",
                    c.site.vertical_ratio));
    out.push_back(
        "Decision (docs/methods.md s.6 step 4): the screen (static criteria; ASCE 4 sliding at the "
        "lower friction bound; the equivalent-linear rocking estimate at the upper bounds) "
        "decides a level it passes. A level that fails the screen is simulated and the "
        "simulation governs it, pass or fail; only simulate = \"never\" lets the screen decide a "
        "failure. The energy-conservation estimate is informational: it neither decides nor "
        "triggers a simulation.");
    out.push_back(fmt::format(
        "Statistics (docs/methods.md s.6 step 3): each simulated level runs {} three-component "
        "sets; per limit state the 84th percentile of the sets' peaks (the ceil(0.84 N)-th "
        "smallest) governs; the mean, the maximum and the count beyond the limit k/N with its "
        "exact 95% interval (Clopper & Pearson 1934) are reported beside it. Any overturned set "
        "fails the level.",
        c.options.histories_per_level));
    out.push_back(fmt::format(
        "Settled decisions (docs/methods.md s.6 step 4): the sets of a level decided by "
        "simulation are resampled with replacement {} times (a bootstrap from the case seed) and "
        "the decision redone on each; below {:.0f}% agreement the level gets {} more sets, up to "
        "{} (options.max_histories_per_level); a level still unsettled there fails.",
        bootstrap_resamples, 100.0 * settle_agreement, settle_batch_sets,
        c.options.max_histories_per_level));
    if (c.options.histories_per_level < 30) {
        out.push_back(fmt::format(
            "options.histories_per_level = {} is below the 30 sets of ASCE 4-16 and ASCE 43-05 "
            "practice for nonlinear response (docs/methods.md s.6 step 3): the 84th percentile "
            "of so few sets is coarse.",
            c.options.histories_per_level));
    }
    out.push_back(
        "Bounds (docs/methods.md s.6 step 6): sliding demands (ASCE 4 and the simulated slip) use the "
        "lower friction bound; rocking, overturning and the classification use the upper "
        "friction bound, with mu_k / mu_s kept at each bound; rocking is simulated at both "
        "restitution bounds and the worse governs.");
    out.push_back(
        "Base-material search (docs/methods.md s.6 step 7): each material of the table is assessed "
        "with its whole property set (the literature friction range as bounds, mu_k = mu_s, "
        "restitution from Housner's value of the component's own geometry to the value measured "
        "on steel specimens; the case's own bounds for its own material) exactly as a case "
        "naming it; of the materials that pass every level, the one with the largest governing "
        "margin is recommended.");
    if (c.component.allowable_relative_m) {
        out.push_back(fmt::format(
            "Joined units: the allowable relative displacement {:.1f} mm (slack of the "
            "connection between units) applies between units that move separately. This case "
            "is assessed as one rigid body (braced units), whose relative displacement is zero "
            "by that assumption; the absolute slide is checked against the clearance {:.1f} mm.",
            *c.component.allowable_relative_m * 1000.0, c.component.allowable_slide_m * 1000.0));
    }
    return out;
}

std::string realism_text(const motion::RealismLimits& lim) {
    std::string ratios;
    if (lim.va_mps_per_g)
        ratios += fmt::format(", V/A {}-{} m/s/g", lim.va_mps_per_g->min, lim.va_mps_per_g->max);
    if (lim.adv2) ratios += fmt::format(", AD/V^2 {}-{}", lim.adv2->min, lim.adv2->max);
    if (lim.da_max_m_per_g) ratios += fmt::format(", D/A at most {} m/g", *lim.da_max_m_per_g);
    return fmt::format(
        "Every history passed SRP 3.7.1 and the realism checks (docs/methods.md s.8): PGA "
        "{}-{} x the target's zero-period acceleration and D5-75 at least {} s on every "
        "component{}{}; a set that fails is rejected, never used.",
        lim.pga_over_zpa.min, lim.pga_over_zpa.max, lim.d5_75_min_s,
        ratios.empty() ? "" : "; on the horizontals", ratios.empty() ? "" : ratios.substr(1));
}

std::vector<std::string> limits(const AssessmentResult& r, HistoryBank& bank) {
    std::vector<std::string> out{
        "Each horizontal direction is a planar rigid block (docs/methods.md s.1), except the "
        "sliding demand of simulated levels whose block slides without rocking, simulated with "
        "both horizontal components at once (biaxial sliding, s.10); twisting and rocking "
        "under both components are not modelled.",
        "A flexible body may uplift below the static threshold (frequency-induced rocking, "
        "Saraswat 2017; docs/methods.md s.2); the rigid-body models cannot show it: where the "
        "flexible-body flag is raised the reduced-order flexible model (rigid base and one "
        "elastic mode, docs/methods.md s.10) runs and decides.",
        "The equivalent-linear rocking estimate is a screen following the ASCE 43-05 App. A "
        "approach, not the standard's text; a rocking block is not an oscillator (Makris & "
        "Konstantinidis 2003) and the simulation is the reference (docs/methods.md s.5a).",
        "Rocking impacts amplify accelerations at the top (1.3 to 11 measured on rigid "
        "specimens, Saraswat 2017; docs/methods.md s.5); equipment attached to a rocking body "
        "must be checked for it."};
    if (bank.generated()) {
        const auto& sets = bank.made();
        out.push_back(fmt::format(
            "{} three-component histories ({}) matched to {} at 1 g and scaled to each "
            "level; response spectra are linear, so each scaled record matches its scaled target "
            "with the same ratios (docs/methods.md s.8).",
            sets.size(), sets.front().method,
            r.input.site.targets ? "the target files" : "RG 1.60"));
        out.push_back(realism_text(r.input.site.realism));
    } else {
        out.push_back("No time histories were generated: the closed forms settled every level.");
    }
    return out;
}

// Runs behind a simulation: one per set and distinct bound.
int runs_of(const Simulation& sim) {
    return sim.histories * (1 + (sim.bounds_differ ? 1 : 0) + (sim.rocking_other ? 1 : 0));
}

}  // namespace

AssessmentResult assess(const Case& c, const RunSettings& run) {
    if (!c.units.empty()) return assess_joined(c, run);
    AssessmentResult res;
    res.input = c;
    HistoryBank bank(res.input, run);
    std::vector<LevelDemand> demands;
    for (double pga : c.site.pga_g) demands.push_back(level_demand(c.site, pga));
    res.levels = evaluate_all(res.input, demands, bank);
    res.own = headline(res.levels);
    if (passes(res.own.verdict) || !c.options.search_materials) {
        res.overall = res.own;
    } else {
        Search search = search_materials(res.input, demands, bank);
        res.upgrade = std::move(search.upgrade);
        // res.own stays the own base's failing verdict (kind anchor): on its own base the
        // component must be anchored; the levels then name the remedy.
        apply_remedy(res.levels, res.upgrade.recommended);
        if (res.upgrade.recommended) {
            res.overall = passing_headline(search.recommended_levels);
            res.overall.verdict.kind = VerdictKind::change_material;
            res.overall.verdict.material = *res.upgrade.recommended;
            const auto chosen =
                std::find_if(res.upgrade.trials.begin(), res.upgrade.trials.end(),
                             [&](const MaterialTrial& t) { return t.material == *res.upgrade.recommended; });
            res.overall.verdict.mechanism =
                mechanism(c.component.base, res.levels, *chosen);
            res.overall_from_trial = true;
        } else {
            res.overall = res.own;
        }
    }
    res.plots = plot_data(res, demands, bank);
    res.assumptions = pipeline_assumptions(c);
    res.limits = limits(res, bank);
    if (bank.generated()) {
        res.histories_generated = static_cast<int>(bank.made().size());
        const std::array<const char*, 3> names{"h1", "h2", "v"};
        for (std::size_t k = 0; k < bank.made().size(); ++k) {
            const HistorySet& set = bank.made()[k];
            for (std::size_t j = 0; j < set.acceptance.size() && j < names.size(); ++j) {
                res.history_checks.push_back(HistoryCheck{static_cast<int>(k + 1), names[j],
                                                          set.method, set.acceptance[j]});
            }
        }
    }
    std::optional<double> counted_3d_pga_g;
    for (const LevelResult& l : res.levels) {
        if (l.simulation) res.simulations_run += runs_of(*l.simulation);
        if (l.flexible_simulation) res.simulations_run += runs_of(l.flexible_simulation->sim);
        // The 3D runs of a PGA serve its x and y rows: counted once, with the step check's run.
        if (l.body3d && l.body3d->ran && counted_3d_pga_g != l.pga_g) {
            res.simulations_run += runs_of(l.body3d->sim) + (l.body3d->step_checked ? 1 : 0);
            counted_3d_pga_g = l.pga_g;
        }
    }
    return res;
}

Upgrade search_materials(const Case& c, const RunSettings& run) {
    HistoryBank bank(c, run);
    std::vector<LevelDemand> demands;
    for (double pga : c.site.pga_g) demands.push_back(level_demand(c.site, pga));
    return search_materials(c, demands, bank).upgrade;
}

Case with_pga_levels(Case c, const std::vector<double>& pga_g) {
    const SourceLocation where{"", 0, "pga_levels"};
    core::limits::require_pga_levels(pga_g, where);
    if (c.site.energy_table_displacement_m && c.site.energy_table_displacement_m->size() != pga_g.size()) {
        throw InputError(where, fmt::format("the case gives site.energy_table_displacement_m for "
                                            "{} levels, the override {}: the table cannot follow",
                                            c.site.energy_table_displacement_m->size(),
                                            pga_g.size()));
    }
    if (const auto bad = weightless_level(pga_g, c.site.vertical_ratio))
        throw InputError(where, *bad);
    c.site.pga_g = pga_g;
    return c;
}

}  // namespace freestand::assess
