#include "assess/pipeline.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "assess/histories.hpp"
#include "assess/level.hpp"
#include "assess/materials.hpp"
#include "assess/plot_data.hpp"
#include "assess/verdict.hpp"
#include "core/errors.hpp"

namespace freestand::assess {

namespace {

constexpr std::array<Direction, 2> directions{Direction::x, Direction::y};

std::vector<LevelResult> evaluate_all(const Case& c, const BaseContact& base,
                                      const std::vector<LevelDemand>& demands, HistoryBank& bank) {
    std::vector<LevelResult> out;
    for (const LevelDemand& dem : demands) {
        for (Direction d : directions) out.push_back(evaluate_level(c, base, d, dem, bank));
    }
    return out;
}

Verdict worst_of(const std::vector<LevelResult>& levels) {
    return levels.empty() ? Verdict{} : levels[governing_index(levels)].verdict;
}

// METHODS.md s.6 step 5: the same pipeline for each material; the weakest that passes.
// Only the friction changes: mu_k keeps the case's mu_k / mu_s ratio and the restitution stays
// the case's (the table's r was measured on steel specimens, not on this component).
Upgrade search_materials(const Case& c, const std::vector<LevelDemand>& demands,
                         HistoryBank& bank) {
    Upgrade up;
    up.needed = true;
    const BaseContact& own = c.component.base;
    const double kinetic_ratio = own.mu_s > 0.0 ? own.mu_k / own.mu_s : 1.0;
    for (const Material& m : materials()) {
        BaseContact trial = own;
        trial.material = m.name;
        trial.mu_s = m.mu_s;
        trial.mu_k = m.mu_s * kinetic_ratio;
        trial.source = "upgrade trial";
        const std::vector<LevelResult> levels = evaluate_all(c, trial, demands, bank);
        up.trials.push_back(MaterialTrial{m.name, m.mu_s, worst_of(levels)});
        if (!up.recommended && passes(up.trials.back().verdict)) up.recommended = m.name;
    }
    return up;
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
            "x and y targets (METHODS.md s.4).",
            u.h5.given, u.h5.spectrum.damping, u.y5->given, u.y5->spectrum.damping, u.zpa_h_g,
            u.h5.spectrum.frequency_hz.back(), u.y5->spectrum.psa_g.back() / u.zpa_h_g));
    } else {
        out.push_back(fmt::format(
            "Target files instead of a design spectrum: horizontal {} (damping {:.3g}), scaled "
            "at each level by pga_g / {:.6g} g (its PSA at {:.6g} Hz, the rigid limit); both "
            "horizontal directions receive it; the sliding and rocking demand is the vector "
            "SA_VH = sqrt(SA_H1^2 + 0.16 SA_H2^2) (METHODS.md s.4).",
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
            "rocking demand is the vector SA_VH = sqrt(SA_H1^2 + 0.16 SA_H2^2) (METHODS.md "
            "s.4).");
    }
    out.push_back(
        fmt::format("Vertical PGA = {:.4f} x horizontal PGA, taken downward in the static "
                    "checks (the worst case, METHODS.md s.5).",
                    c.site.vertical_ratio));
    out.push_back(
        "Sliding: the simulation (peak and residual slip, max over the histories) governs when "
        "it was run; it is run when the ASCE 4 and energy estimates straddle the allowable. "
        "Otherwise the larger closed form governs, or the smaller when both exceed the "
        "allowable.");
    out.push_back(
        "Rocking is decided by the time-history simulation when it was run, else by the "
        "equivalent-linear screen (METHODS.md s.5a).");
    out.push_back(
        "Upgrade trials change only the static friction (mu_k keeps the case's mu_k/mu_s); "
        "the restitution stays the case's.");
    return out;
}

std::vector<std::string> limits(const AssessmentResult& r, HistoryBank& bank) {
    std::vector<std::string> out{
        "Each horizontal direction is a planar rigid block (METHODS.md s.1); bidirectional "
        "effects (twisting, walking) are not modelled.",
        "A flexible body may uplift below the static threshold (frequency-induced rocking, "
        "METHODS.md s.2); the rigid-body models cannot show it: see the flexible-body flag.",
        "The equivalent-linear rocking estimate is a screen, not the ASCE 43-05 text; the "
        "simulation is the reference (METHODS.md s.5a).",
        "Rocking impacts amplify accelerations at the top (1.3 to 11 measured on rigid specimens, "
        "METHODS.md s.5); equipment attached to a rocking body must be checked for it."};
    if (bank.generated()) {
        const auto& sets = bank.sets();
        out.push_back(fmt::format(
            "{} three-component histories ({}) matched to {} at 1 g and scaled to each "
            "level; response spectra are linear, so each scaled record matches its scaled target "
            "with the same ratios.",
            sets.size(), sets.front().method,
            r.input.site.targets ? "the target files" : "RG 1.60"));
        for (std::size_t k = 0; k < sets.size(); ++k) {
            if (!sets[k].passed) {
                out.push_back(
                    fmt::format("History {} did not pass every SRP 3.7.1 acceptance "
                                "criterion; it is used all the same.",
                                k + 1));
            }
        }
    } else {
        out.push_back("No time histories were generated: the closed forms settled every level.");
    }
    return out;
}

}  // namespace

AssessmentResult assess(const Case& c) {
    AssessmentResult res;
    res.input = c;
    HistoryBank bank(res.input);
    std::vector<LevelDemand> demands;
    for (double pga : c.site.pga_g) demands.push_back(level_demand(c.site, pga));
    res.levels = evaluate_all(res.input, c.component.base, demands, bank);
    const bool own_fails = std::any_of(res.levels.begin(), res.levels.end(),
                                       [](const LevelResult& l) { return !passes(l.verdict); });
    if (own_fails) res.upgrade = search_materials(res.input, demands, bank);
    apply_upgrade(res.levels, res.upgrade);
    res.overall = overall_verdict(res.levels, res.upgrade);
    res.governing_level = governing_index(res.levels);
    res.plots = plot_data(res, demands, bank);
    res.assumptions = pipeline_assumptions(c);
    res.limits = limits(res, bank);
    if (bank.generated()) {
        res.histories_generated = static_cast<int>(bank.sets().size());
        const std::array<const char*, 3> names{"h1", "h2", "v"};
        for (std::size_t k = 0; k < bank.sets().size(); ++k) {
            const HistorySet& set = bank.sets()[k];
            for (std::size_t j = 0; j < set.acceptance.size() && j < names.size(); ++j) {
                const auto& a = set.acceptance[j];
                res.history_checks.push_back(HistoryCheck{static_cast<int>(k + 1), names[j],
                                                          set.method, a.passed, a.min_ratio,
                                                          a.max_ratio, a.reason});
            }
        }
    }
    for (const LevelResult& l : res.levels)
        res.simulations_run += l.simulation ? l.simulation->histories : 0;
    return res;
}

Case with_pga_levels(Case c, const std::vector<double>& pga_g) {
    const SourceLocation where{"", 0, "--pga"};
    if (pga_g.empty()) throw InputError(where, "expected at least one PGA level");
    for (std::size_t i = 0; i < pga_g.size(); ++i) {
        require_in_range(pga_g[i], 0.0, 3.0, where, false, true);
        if (i > 0 && pga_g[i] <= pga_g[i - 1]) {
            throw InputError(where, fmt::format("levels must be strictly increasing; {} follows {}",
                                                pga_g[i], pga_g[i - 1]));
        }
    }
    c.site.pga_g = pga_g;
    return c;
}

}  // namespace freestand::assess
