#include "assess/verdict.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace freestand::assess {

const char* to_string(Mode m) {
    switch (m) {
        case Mode::rest:
            return "rest";
        case Mode::slide:
            return "slide";
        case Mode::rock:
            return "rock";
        case Mode::slide_rock:
            return "slide-rock";
    }
    return "rest";
}

const char* to_string(Model m) {
    switch (m) {
        case Model::static_initiation:
            return "static initiation criterion (METHODS.md s.2)";
        case Model::asce4_sliding:
            return "ASCE 4 equivalent-linear sliding (METHODS.md s.4)";
        case Model::energy_sliding:
            return "energy-conservation sliding (METHODS.md s.4)";
        case Model::simulation_slide:
            return "time-history simulation, peak slip (METHODS.md s.3)";
        case Model::simulation_residual:
            return "time-history simulation, residual slip (METHODS.md s.3)";
        case Model::equivalent_linear_rocking:
            return "equivalent-linear rocking estimate (METHODS.md s.5a)";
        case Model::simulation_rocking:
            return "time-history simulation, rocking and overturning (METHODS.md s.3)";
        case Model::no_motion:
            return "low-motion threshold: peak slip < 1 mm (METHODS.md s.2)";
    }
    return "";
}

const char* to_string(VerdictKind k) {
    switch (k) {
        case VerdictKind::acceptable:
            return "acceptable";
        case VerdictKind::acceptable_with_clearance:
            return "acceptable_with_clearance";
        case VerdictKind::upgrade_material:
            return "upgrade_material";
        case VerdictKind::anchor:
            return "anchor";
    }
    return "";
}

namespace {

double larger_closed_form_slide(const Sliding& s) {
    return std::max(s.slide_asce_m.value_or(0.0), s.slide_energy_m.value_or(0.0));
}

bool closed_form_slide_available(const Sliding& s) {
    return s.slide_asce_m.has_value() || s.slide_energy_m.has_value();
}

bool slides(const LevelResult& level) {
    if (level.initiation.mode == Mode::slide || level.initiation.mode == Mode::slide_rock)
        return true;
    return level.simulation && level.simulation->slide_max_max_m >= no_motion_slide_m;
}

bool rocks(const LevelResult& level) {
    return level.initiation.mode == Mode::rock || level.initiation.mode == Mode::slide_rock;
}

Verdict slide_verdict(const LevelResult& level, double allowable_m) {
    struct Estimate {
        Model model;
        double value_m;
    };
    std::vector<Estimate> chosen;
    const Sliding& s = level.sliding;
    if (level.simulation) {
        // The simulation is the reference (METHODS.md s.4): peak and residual over the histories.
        chosen.push_back({Model::simulation_slide, level.simulation->slide_max_max_m});
        chosen.push_back({Model::simulation_residual, level.simulation->slide_residual_max_m});
    } else if (level.initiation.mode != Mode::rock) {
        if (s.slide_asce_m) chosen.push_back({Model::asce4_sliding, *s.slide_asce_m});
        if (s.slide_energy_m) chosen.push_back({Model::energy_sliding, *s.slide_energy_m});
    }
    Verdict v;
    if (chosen.empty()) {
        // The spectrum never reaches C_s: ASCE 4 says the body does not slide.
        v.decided_by = Model::asce4_sliding;
        v.margin_basis = "ASCE 4: the sliding spectrum never reaches C_s";
        return v;
    }
    auto by_value = [](const Estimate& a, const Estimate& b) { return a.value_m < b.value_m; };
    const Estimate hi = *std::max_element(chosen.begin(), chosen.end(), by_value);
    const Estimate lo = *std::min_element(chosen.begin(), chosen.end(), by_value);
    // Without a simulation the closed forms agree (or the case forbids simulating): when even
    // the smaller exceeds the allowable it decides the failure; otherwise the larger governs.
    const Estimate gov = (!level.simulation && lo.value_m > allowable_m) ? lo : hi;
    v.decided_by = gov.model;
    v.margin_basis = "allowable slide / governing slide";
    if (gov.value_m > 0.0) v.margin = allowable_m / gov.value_m;
    if (gov.value_m < no_motion_slide_m) {
        v.kind = VerdictKind::acceptable;
    } else if (gov.value_m <= allowable_m) {
        v.kind = VerdictKind::acceptable_with_clearance;
        v.clearance_m = gov.value_m;
    } else {
        v.kind = VerdictKind::upgrade_material;
        v.clearance_m = gov.value_m;
    }
    return v;
}

Verdict rock_verdict(const LevelResult& level, double required_fs) {
    Verdict v;
    v.margin_basis =
        fmt::format("factor of safety alpha / theta_max over required {}", required_fs);
    if (level.simulation) {
        const Simulation& sim = *level.simulation;
        v.decided_by = Model::simulation_rocking;
        if (sim.overturned_fraction > 0.0) {
            v.margin = 0.0;
        } else if (sim.rock_max_over_alpha_max > 0.0) {
            v.margin = 1.0 / sim.rock_max_over_alpha_max / required_fs;
        }
    } else {
        const Rocking& r = level.rocking;
        v.decided_by = Model::equivalent_linear_rocking;
        if (r.overturn_predicted) {
            v.margin = 0.0;
        } else if (r.overturn_fs) {
            v.margin = *r.overturn_fs / required_fs;
        }
    }
    v.kind = (!v.margin || *v.margin >= 1.0) ? VerdictKind::acceptable : VerdictKind::anchor;
    return v;
}

}  // namespace

SimulationNeed simulation_need(const LevelResult& closed, double allowable_slide_m,
                               SimulatePolicy policy) {
    if (policy == SimulatePolicy::never) return {false, "options.simulate = \"never\""};
    if (policy == SimulatePolicy::always) return {true, "options.simulate = \"always\""};
    switch (closed.initiation.mode) {
        case Mode::rest:
            return {false, "at rest by the static criteria (METHODS.md s.2)"};
        case Mode::rock:
        case Mode::slide_rock:
            return {true,
                    "rocking: the equivalent-linear estimate is a screen, the simulation is "
                    "the reference (METHODS.md s.5a)"};
        case Mode::slide:
            break;
    }
    if (!closed_form_slide_available(closed.sliding)) {
        return {true, "the block slides by the static criterion but no closed form applies"};
    }
    const Sliding& s = closed.sliding;
    const double hi = larger_closed_form_slide(s);
    const double lo = std::min(s.slide_asce_m.value_or(hi), s.slide_energy_m.value_or(hi));
    if (hi <= allowable_slide_m) return {false, "both closed-form slides are within the allowable"};
    if (lo > allowable_slide_m) return {false, "both closed-form slides exceed the allowable"};
    return {true, "the closed-form slides straddle the allowable: the simulation decides"};
}

Verdict decide_level(const LevelResult& level, double allowable_slide_m, double required_fs) {
    if (level.initiation.mode == Mode::rest && !slides(level)) {
        Verdict v;
        v.decided_by = level.simulation ? Model::no_motion : Model::static_initiation;
        v.margin_basis = "static threshold min(mu_s, tan alpha) / A";
        const double threshold = std::min(level.initiation.mu_s, level.initiation.tan_alpha);
        if (level.initiation.a_ratio > 0.0) v.margin = threshold / level.initiation.a_ratio;
        return v;
    }
    std::optional<Verdict> result;
    if (slides(level)) result = slide_verdict(level, allowable_slide_m);
    if (rocks(level)) {
        const Verdict r = rock_verdict(level, required_fs);
        result = result ? more_severe(*result, r) : r;
    }
    return *result;
}

bool passes(const Verdict& v) {
    return v.kind == VerdictKind::acceptable || v.kind == VerdictKind::acceptable_with_clearance;
}

const Verdict& more_severe(const Verdict& a, const Verdict& b) {
    if (a.kind != b.kind) return a.kind > b.kind ? a : b;
    if (a.clearance_m != b.clearance_m) return a.clearance_m > b.clearance_m ? a : b;
    if (a.margin.has_value() != b.margin.has_value()) return a.margin ? a : b;
    if (a.margin && *b.margin < *a.margin) return b;
    return a;
}

std::size_t governing_index(const std::vector<LevelResult>& levels) {
    std::size_t gov = 0;
    for (std::size_t i = 1; i < levels.size(); ++i) {
        if (&more_severe(levels[gov].verdict, levels[i].verdict) != &levels[gov].verdict) gov = i;
    }
    return gov;
}

Verdict overall_verdict(const std::vector<LevelResult>& levels, const Upgrade& upgrade) {
    if (levels.empty()) return Verdict{};
    const Verdict& worst = levels[governing_index(levels)].verdict;
    if (passes(worst)) return worst;
    if (upgrade.recommended) {
        for (const MaterialTrial& t : upgrade.trials) {
            if (t.material != *upgrade.recommended) continue;
            Verdict v = t.verdict;
            v.kind = VerdictKind::upgrade_material;
            v.material = t.material;
            return v;
        }
    }
    Verdict v = worst;
    v.kind = VerdictKind::anchor;
    v.material.clear();
    return v;
}

void apply_upgrade(std::vector<LevelResult>& levels, const Upgrade& upgrade) {
    for (LevelResult& level : levels) {
        if (level.verdict.kind != VerdictKind::upgrade_material) continue;
        if (upgrade.recommended) {
            level.verdict.material = *upgrade.recommended;
        } else {
            level.verdict.kind = VerdictKind::anchor;
        }
    }
}

std::string verdict_text(const Verdict& v) {
    switch (v.kind) {
        case VerdictKind::acceptable:
            return "free-standing acceptable";
        case VerdictKind::acceptable_with_clearance: {
            // Whole mm, rounded up; the 1e-9 guards against 0.047000000001 -> 48.
            const double mm = std::ceil(v.clearance_m * 1000.0 - 1e-9);
            return fmt::format("acceptable with clearance >= {:.0f} mm", mm);
        }
        case VerdictKind::upgrade_material:
            return v.material.empty() ? "upgrade base material"
                                      : "upgrade base material to " + v.material;
        case VerdictKind::anchor:
            return "anchor";
    }
    return "";
}

}  // namespace freestand::assess
