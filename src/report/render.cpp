#include "report/render.hpp"

#include "report/result_document.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <mstch/mstch.hpp>

#include "assess/settle.hpp"
#include "assess/verdict.hpp"
#include "core/file_io.hpp"
#include "core/printable.hpp"
#include "core/publish.hpp"
#include "report/fragility_report.hpp"
#include "report/goal_report.hpp"
#include "report/joined.hpp"
#include "report/references.hpp"
#include "report/template_render.hpp"

namespace freestand::report {

// Defined in the generated templates_embedded.cpp (src/report/CMakeLists.txt).
extern const char* const template_report_md;
extern const char* const template_report_html;
extern const char* const template_fragility_section_md;
extern const char* const template_fragility_section_html;

namespace {

using namespace freestand::assess;

const std::string none = "n/a";

std::string fixed(double v, int precision) { return fmt::format("{:.{}f}", v, precision); }
std::string fixed(const std::optional<double>& v, int precision) {
    return v ? fixed(*v, precision) : none;
}
std::string mm(const std::optional<double>& v_m) { return v_m ? fixed(*v_m * 1000.0, 1) : none; }
std::string yes_no(bool b) { return b ? "yes" : "no"; }

mstch::map input(std::string name, std::string value, std::string unit, std::string note = "") {
    return mstch::map{{"name", std::move(name)},
                      {"value", std::move(value)},
                      {"unit", std::move(unit)},
                      {"note", std::move(note)}};
}

std::string pair(double a, double b, int precision) {
    return fixed(a, precision) + ", " + fixed(b, precision);
}
std::string bounds_text(double lower, double upper, int precision) {
    return fmt::format("[{}]", pair(lower, upper, precision));
}

// The first level of a direction carries that direction's bounds (they do not vary with PGA).
const LevelResult* first_level(const std::vector<LevelResult>& levels, Direction d) {
    for (const LevelResult& l : levels) {
        if (l.direction == d) return &l;
    }
    return nullptr;
}

std::string restitution_note(const BaseContact& b, const DirectionBounds& bounds) {
    if (b.restitution_range) return "restitution_range (case file)";
    if (b.restitution) {
        return fmt::format(
            "from Housner's value of the critical edge (Housner 1963) to the measured "
            "r = {:.3f} (docs/methods.md s.7)",
            *b.restitution);
    }
    return bounds.rocking.housner
               ? "Housner's value of the critical edge, no measured r (Housner 1963; "
                 "docs/methods.md s.1)"
               : "";
}

std::string statistic_rule(const Options& o) {
    return fmt::format(
        "the 84th percentile of the sets' peaks governs, with k/N beyond each limit beside it; a "
        "decision the bootstrap does not settle, or a pass of a level that can uplift whose sets "
        "bound the overturn rate only above {:.0f}% (95%), gets {} more sets, up to {} "
        "(docs/methods.md s.6 steps 3-4)",
        100.0 * assess::settle_overturn_rate, assess::settle_batch_sets,
        o.max_histories_per_level);
}

std::string energy_delta_d_text(const Site& site) {
    if (site.energy_table_displacement_m) {
        std::vector<std::string> mm_values;
        for (double v : *site.energy_table_displacement_m) mm_values.push_back(fixed(v * 1000.0, 1));
        return fmt::format("case table per level: {} mm", fmt::join(mm_values, ", "));
    }
    return fmt::format(
        "mean of the histories' peak displacements after a zero-phase {:.3g} Hz high-pass",
        site.energy_highpass_hz);
}

mstch::array inputs(const Case& c, const std::vector<LevelResult>& levels) {
    const Component& k = c.component;
    mstch::array out;
    out.push_back(input("mass", fixed(k.mass_kg, 1), "kg"));
    out.push_back(input("CG height above the contact plane", fixed(k.cg_height_m, 3), "m",
                        k.uniform_block ? "uniform block: half the height" : ""));
    if (k.height_m && !k.uniform_block) {
        out.push_back(input("height of the top above the contact plane", fixed(*k.height_m, 3), "m",
                            "top point of the top acceleration; default inertia and modal height"));
    }
    out.push_back(
        input("CG to rocking edges, x (left, right)", pair(k.x.b_left_m, k.x.b_right_m, 3), "m"));
    out.push_back(
        input("CG to rocking edges, y (left, right)", pair(k.y.b_left_m, k.y.b_right_m, 3), "m"));
    out.push_back(input("I_c about the CG, x plane", fixed(k.x.inertia_cg_kgm2, 2), "kg m^2",
                        k.x.inertia_source));
    out.push_back(input("I_c about the CG, y plane", fixed(k.y.inertia_cg_kgm2, 2), "kg m^2",
                        k.y.inertia_source));
    out.push_back(input("footprint", k.footprint.empty() ? none : k.footprint, ""));
    out.push_back(input("fixed-base natural frequency", fixed(k.fixed_base_frequency_hz, 2), "Hz"));
    // One row when both directions share a band (or have none), else one per direction.
    const auto band_text = [&](Direction d) {
        const auto& band = k.plane(d).free_rocking_band_hz;
        return band ? pair((*band)[0], (*band)[1], 2) : none;
    };
    if (k.x.free_rocking_band_hz == k.y.free_rocking_band_hz) {
        out.push_back(input("free-rocking band", band_text(Direction::x), "Hz"));
    } else {
        for (const Direction d : {Direction::x, Direction::y})
            out.push_back(input(fmt::format("free-rocking band, {} plane", to_string(d)),
                                band_text(d), "Hz"));
    }
    out.push_back(input("base material", k.base.material.empty() ? none : k.base.material, "",
                        k.base.source));
    out.push_back(input("static friction mu_s (nominal)", fixed(k.base.mu_s, 3), "-"));
    out.push_back(input("static friction bounds [lower, upper]",
                        bounds_text(k.base.mu_s_range[0], k.base.mu_s_range[1], 3), "-",
                        k.base.mu_s_range_source));
    out.push_back(input("kinetic friction mu_k (nominal)", fixed(k.base.mu_k, 3), "-",
                        "mu_k / mu_s applied to both friction bounds"));
    out.push_back(input("restitution r (nominal)",
                        k.base.restitution ? fixed(*k.base.restitution, 3) : "Housner", "-"));
    for (Direction d : {Direction::x, Direction::y}) {
        const LevelResult* l = first_level(levels, d);
        if (!l) continue;
        out.push_back(
            input(fmt::format("restitution bounds, {} [lower, upper]", to_string(d)),
                  bounds_text(l->bounds.restitution_lower, l->bounds.rocking.restitution, 3), "-",
                  restitution_note(k.base, l->bounds)));
    }
    out.push_back(input("energy method's DeltaD", energy_delta_d_text(c.site), "",
                        "informational estimate only: the energy method of Saraswat 2017 "
                        "(docs/methods.md s.4)"));
    out.push_back(input("allowable slide (absolute: clearance)",
                        fixed(k.allowable_slide_m * 1000.0, 1), "mm"));
    if (k.allowable_relative_m) {
        out.push_back(input("allowable relative displacement (joined units)",
                            fixed(*k.allowable_relative_m * 1000.0, 1), "mm",
                            "a braced pair is one rigid body: the relative displacement is zero "
                            "in this model"));
    }
    out.push_back(
        input("required overturning factor of safety", fixed(k.required_overturn_fs, 2), "-"));
    out.push_back(input("design spectrum",
                        c.site.design == "rg1.60" ? "US NRC RG 1.60" : c.site.design, "",
                        c.site.design == "rg1.60" ? "RG 1.60 (docs/methods.md s.8)"
                                                  : "docs/methods.md s.8"));
    std::string pga_levels;
    for (double p : c.site.pga_g) pga_levels += (pga_levels.empty() ? "" : ", ") + fixed(p, 3);
    out.push_back(input("PGA levels (horizontal)", pga_levels, "g"));
    out.push_back(input("vertical / horizontal PGA", fixed(c.site.vertical_ratio, 4), "-"));
    out.push_back(
        input("damping of the sliding spectrum", fixed(c.site.sliding_damping * 100.0, 1), "%"));
    out.push_back(input("gravity", fixed(c.site.g_mps2, 3), "m/s^2"));
    out.push_back(input("histories per level", std::to_string(c.options.histories_per_level), "",
                        statistic_rule(c.options)));
    out.push_back(input("simulate", to_string(c.options.simulate), "",
                        "screen, then simulate (docs/methods.md s.6 step 4)"));
    return out;
}

std::string mode_text(const LevelResult& l) {
    std::string out = to_string(l.initiation.mode);
    if (l.initiation_lower.mode != l.initiation.mode)
        out += fmt::format(" (lower mu: {})", to_string(l.initiation_lower.mode));
    return out;
}

std::string el_fs_text(const LevelResult& l) {
    if (l.initiation.mode != Mode::rock && l.initiation.mode != Mode::slide_rock)
        return "not rocking";
    if (l.rocking.overturn_predicted) return "overturns";
    if (l.rocking.overturn_fs) return fixed(*l.rocking.overturn_fs, 2);
    if (!l.rocking.gate_passed) return "no uplift";
    return none;
}

std::string amplification_estimate(const LevelResult& l) {
    if (l.rocking.amplification_estimate)
        return fmt::format("~{:.2f}", *l.rocking.amplification_estimate);
    return "1.3-11 (rocking, measured range)";
}

std::string stats_text(const Stats& s, double scale, int precision) {
    return fmt::format("{:.{}f} / {:.{}f} / {:.{}f}", s.mean * scale, precision, s.p84 * scale,
                       precision, s.max * scale, precision);
}

std::string overturned_text(const Simulation& sim) {
    return fmt::format("{}/{} [{:.0f}%, {:.0f}%]", sim.overturned, sim.histories,
                       100.0 * sim.overturn_ci[0], 100.0 * sim.overturn_ci[1]);
}

// Biaxial peak |u| statistics (mm) and their ratio to the larger planar peak slip.
std::string biaxial_text(const LevelResult& l) {
    if (!l.biaxial || !l.biaxial->ran) return none;
    const BiaxialSlide& b = *l.biaxial;
    return fmt::format("{} ({} x {})", stats_text(b.slide_m, 1000.0, 1),
                       b.ratio ? fixed(*b.ratio, 2) : none, to_string(b.planar_direction));
}

// The 3D body's governing demands and their ratios to the planar ones.
std::string body3d_text(const LevelResult& l) {
    if (!l.body3d || !l.body3d->ran) return none;
    const Body3dLevel& b = *l.body3d;
    const auto ratio = [](const std::optional<double>& r) {
        return r ? fixed(*r, 2) + " x" : none;
    };
    return fmt::format("tilt/critical {} ({}); slide {} mm ({}); {} overturned{}",
                       b.sim.overturned < b.sim.histories
                           ? stats_text(b.sim.rock_over_alpha, 1.0, 3)
                           : none,
                       ratio(b.rock_ratio), stats_text(b.sim.slide_m, 1000.0, 1),
                       ratio(b.slide_ratio), overturned_text(b.sim),
                       b.flexible ? "; with the flexible mode, |q| " +
                                        stats_text(b.modal_m, 1000.0, 1) + " mm"
                                  : std::string());
}

std::string level_verdict_text(const Verdict& v) {
    return passes(v) ? verdict_text(v)
                     : fmt::format("{} ({})", verdict_text(v), to_string(v.failure));
}

// Which contact bound the deciding model ran at (docs/methods.md s.6 step 6).
std::string governing_bound(const LevelResult& l) {
    switch (l.verdict.decided_by) {
        case Model::static_initiation:
        case Model::asce4_sliding:
        case Model::simulation_slide:
        case Model::simulation_biaxial_slide:
            return l.bounds.sliding.name.empty() ? "lower friction bound" : l.bounds.sliding.name;
        case Model::equivalent_linear_rocking:
        case Model::simulation_rocking:
            return l.bounds.rocking.name.empty() ? "upper friction and restitution bounds"
                                                 : l.bounds.rocking.name;
        case Model::simulation_flexible:
        case Model::simulation_3d:
        case Model::simulation_3d_flexible:
            return "slip at the lower friction bound, rocking at the upper bounds";
        case Model::fragility_goal:
            return "friction and restitution drawn between their bounds";
    }
    return none;
}

// What the time-history table checks and against which target, with the sources.
std::string history_basis(const Site& site) {
    const std::string target =
        site.targets ? "the case's target files" : "RG 1.60 (vertical = ratio x horizontal)";
    const std::string psd = site.targets ? ""
                                         : ", the horizontals' power spectral density against "
                                           "the RG 1.60 target PSD of SRP 3.7.1 App. A";
    return fmt::format(
        "Each component of each history is checked against its 5%-damped target, {}, by the "
        "SRP 3.7.1 Option 1 Approach 2 criteria{} (docs/methods.md s.8). Response spectra by "
        "the Nigam & Jennings 1969 recurrence; histories matched by time-domain wavelet "
        "adjustment (Al Atik & Abrahamson 2010) from a random-phase synthetic record or a seed "
        "record (the method column). Every history also meets the realism ranges of "
        "docs/methods.md s.8 (PGA / ZPA, D5-75, and on horizontals V/A, AD/V^2, D/A where a "
        "range is set; \"(n/c)\" marks a ratio reported, not checked). The histories were "
        "matched at 1 g: PGV, PGD and Arias intensity scale with the level (Arias as its "
        "square), the ratios do not.",
        target, psd);
}

mstch::map level_row(const LevelResult& l) {
    const auto& sim = l.simulation;
    // Rotation statistics cover the standing histories: none when every history overturned.
    const bool standing = sim && sim->overturned < sim->histories;
    return mstch::map{
        {"pga", fixed(l.pga_g, 3)},
        {"pga_v", fixed(l.pga_v_g, 3)},
        {"dir", std::string(to_string(l.direction))},
        {"mode", mode_text(l)},
        {"flex", std::string(l.flexible.raised ? "FLAG" : "")},
        {"a_ratio", fixed(l.initiation.a_ratio, 3)},
        {"screen", yes_no(l.screen.passed)},
        {"slide_asce", mm(l.sliding.slide_asce_m)},
        {"delta_d", l.sliding.slide_energy_m ? mm(l.sliding.delta_d_m) : none},
        {"slide_energy", mm(l.sliding.slide_energy_m)},
        {"el_fs", el_fs_text(l)},
        {"amplification_estimate", amplification_estimate(l)},
        {"histories",
         sim ? fmt::format("{} (84th percentile{})", sim->histories,
                           l.settling ? fmt::format(", {:.0f}% settled",
                                                    100.0 * l.settling->settled_fraction)
                                      : std::string())
             : none},
        {"sim_slide", sim ? stats_text(sim->slide_m, 1000.0, 1) : none},
        {"sim_biaxial", biaxial_text(l)},
        {"sim_3d", body3d_text(l)},
        {"sim_residual", sim ? mm(sim->slide_residual_m.max) : none},
        {"rock_sim", standing ? stats_text(sim->rock_over_alpha, 1.0, 3) : none},
        {"overturned", sim ? overturned_text(*sim) : none},
        {"amplification", sim ? fixed(sim->amplification.max, 2) : none},
        {"verdict", level_verdict_text(l.verdict)},
        {"margin", margin_text(l.verdict)},
        {"decided_by", std::string(to_string(l.verdict.decided_by))},
        {"bound", governing_bound(l)},
        {"trail", text_list(l.trail)},
        {"sliding_reason", l.sliding.reason},
    };
}

mstch::array flex_notes(const std::vector<LevelResult>& levels) {
    mstch::array out;
    for (const LevelResult& l : levels) {
        if (!l.flexible.raised) continue;
        out.push_back(mstch::map{
            {"text", fmt::format("PGA {:.3f} g, {}: mode stays {} ({}). Screen: {}. A flexible "
                                 "body may uplift below the "
                                 "static threshold (frequency-induced rocking, Saraswat 2017; "
                                 "docs/methods.md s.2).",
                                 l.pga_g, to_string(l.direction), to_string(l.initiation.mode),
                                 l.flexible.basis, l.flexible.reason)}});
    }
    return out;
}

// Rigid and flexible side by side at each level the flexible-body model ran (docs/methods.md
// s.10): one row per model over the same histories and bounds.
// "How sure is this verdict" (docs/methods.md s.6 steps 3-4): per level decided by its sets,
// N, the share of bootstrap resamples that agree, and the counts beyond each limit.
// The sets beyond the allowable slide by the demand that decided: the biaxial |u| where it ran
// (beside the flexible body's slip, the larger of the two per set), else the model's own slip.
Exceedance slide_beyond(const LevelResult& l, const Simulation& sim, double allowable_m) {
    if (!l.biaxial || !l.biaxial->ran) return sim.slide_exceed;
    std::vector<double> demand_m = l.biaxial->slide_m.values;
    if (l.flexible_simulation)
        for (std::size_t k = 0; k < demand_m.size() && k < sim.slide_m.values.size(); ++k)
            demand_m[k] = std::max(demand_m[k], sim.slide_m.values[k]);
    return exceedance(demand_m, allowable_m);
}

mstch::array how_sure_rows(const std::vector<LevelResult>& levels, double allowable_m) {
    mstch::array out;
    for (const LevelResult& l : levels) {
        if (!l.settling) continue;
        const Simulation& sim =
            l.flexible_simulation ? l.flexible_simulation->sim : *l.simulation;
        out.push_back(mstch::map{
            {"pga", fixed(l.pga_g, 3)},
            {"dir", std::string(to_string(l.direction))},
            {"n_sets", std::to_string(l.settling->n_sets)},
            {"settled", fmt::format("{:.1f}%{}", 100.0 * l.settling->settled_fraction,
                                    l.settling->settled ? "" : " (not settled)")},
            {"slide_beyond", exceedance_text(slide_beyond(l, sim, allowable_m))},
            {"rock_beyond", exceedance_text(sim.rock_exceed)},
            {"overturned",
             exceedance_text(Exceedance{sim.overturned, sim.histories, sim.overturn_ci})},
            {"verdict", std::string(passes(l.verdict) ? "passes" : "fails")}});
    }
    return out;
}

mstch::array flex_compare(const std::vector<LevelResult>& levels) {
    mstch::array out;
    const auto row = [](const LevelResult& l, const Simulation& sim, const std::string& model,
                        const std::string& uplifted, const std::string& modal) {
        const bool standing = sim.overturned < sim.histories;
        return mstch::map{{"pga", fixed(l.pga_g, 3)},
                          {"dir", std::string(to_string(l.direction))},
                          {"model", model},
                          {"sim_slide", stats_text(sim.slide_m, 1000.0, 1)},
                          {"rock_sim", standing ? stats_text(sim.rock_over_alpha, 1.0, 3) : none},
                          {"overturned", overturned_text(sim)},
                          {"uplifted", uplifted},
                          {"modal", modal}};
    };
    for (const LevelResult& l : levels) {
        if (!l.flexible_simulation) continue;
        const FlexibleSimulation& f = *l.flexible_simulation;
        if (l.simulation) {
            out.push_back(row(l, *l.simulation, "rigid planar block (beside)", none, none));
        }
        const bool by_3d = body3d_decides(l);
        out.push_back(row(l, f.sim,
                          fmt::format("flexible body, {:.3g} Hz ({})", f.frequency_hz,
                                      by_3d ? "beside" : "decides"),
                          fmt::format("{} / {}", f.uplifted, f.sim.histories),
                          stats_text(f.modal_m, 1000.0, 2)));
        if (by_3d)  // beside a flexible run, the 3D body decides only carrying the mode
            out.push_back(row(l, l.body3d->sim, "3D body carrying the mode (decides)", none,
                              stats_text(l.body3d->modal_m, 1000.0, 2)));
    }
    return out;
}

std::string level_name(double pga_g, Direction d) {
    return fmt::format("PGA {:.3f} g, direction {}", pga_g, to_string(d));
}

std::string base_name(const BaseContact& b) {
    return b.material.empty() ? fmt::format("mu_s {:.3f}", b.mu_s) : b.material;
}

// The case's own base beside a headline that is not its own pass: one level, as the headline.
std::string own_base_line(const AssessmentResult& r) {
    const Verdict& v = r.own.verdict;
    return fmt::format("Case's own base ({}): {} at {}: {}, decided by {}, margin {}",
                       base_name(r.input.component.base), passes(v) ? "governed" : "fails",
                       level_name(r.own.pga_g, r.own.direction),
                       passes(v) ? verdict_text(v) : std::string(to_string(v.failure)),
                       to_string(v.decided_by), margin_text(v));
}

bool shows_own_base(const AssessmentResult& r) {
    const VerdictKind k = r.overall.verdict.kind;
    return k == VerdictKind::change_material || k == VerdictKind::anchor;
}

std::string upgrade_summary(const AssessmentResult& r) {
    if (!r.upgrade.recommended) return "no material of docs/methods.md s.7 passes every level: anchor.";
    const std::string& why = r.overall.verdict.mechanism;
    return fmt::format(
        "{} is recommended, the first material in docs/methods.md s.7 order that "
        "passes every level{}.",
        *r.upgrade.recommended, why.empty() ? "" : ": " + why);
}

mstch::array trial_rows(const Upgrade& up) {
    mstch::array out;
    for (const MaterialTrial& t : up.trials) {
        const Governing& g = t.governing;
        const Verdict& v = g.verdict;
        out.push_back(
            mstch::map{{"material", t.material},
                       {"mu_s_range", bounds_text(t.mu_s_range[0], t.mu_s_range[1], 3)},
                       {"restitution", t.restitution ? fixed(*t.restitution, 3) : "Housner"},
                       {"passes", yes_no(t.passes)},
                       {"governing", fmt::format("{:.3f} g, {}", g.pga_g, to_string(g.direction))},
                       {"verdict", verdict_text(v)},
                       {"failure", passes(v) ? "" : std::string(to_string(v.failure))},
                       {"decided_by", std::string(to_string(v.decided_by))},
                       {"margin", margin_text(v)}});
    }
    return out;
}

std::string margin_with_basis(const Verdict& v) {
    return v.margin_basis.empty() ? margin_text(v)
                                  : fmt::format("{} ({})", margin_text(v), v.margin_basis);
}

// One history at the 1 g it was matched at: the SRP ratios and the realism measures (ratios
// checked on horizontals only, "(n/c)" where no range is set).
mstch::map history_row(const HistoryCheck& h) {
    const motion::Acceptance& a = h.acceptance;
    const auto ratio = [&](double v, bool checked) {
        return fixed(v, 2) + (h.acceptance.horizontal && checked ? "" : " (n/c)");
    };
    return mstch::map{
        {"history", std::to_string(h.history)},
        {"component", h.component},
        {"method", h.method},
        {"passed", std::string(a.passed ? "yes" : "no: " + a.reason)},
        {"min_ratio", fixed(a.min_ratio, 3)},
        {"max_ratio", fixed(a.max_ratio, 3)},
        {"pga_over_zpa", fixed(a.pga_over_zpa, 3)},
        {"pgv_mps", fixed(a.pgv_mps, 3)},
        {"pgd_m", fixed(a.pgd_m, 3)},
        {"va", ratio(a.va_mps_per_g, a.realism.va_mps_per_g.has_value())},
        {"adv2", ratio(a.adv2, a.realism.adv2.has_value())},
        {"da", ratio(a.da_m_per_g, a.realism.da_max_m_per_g.has_value())},
        {"arias_mps", fixed(a.arias_mps, 3)},
        {"d5_75_s", fixed(a.d5_75_s, 2)},
        {"d5_95_s", fixed(a.d5_95_s, 2)}};
}

mstch::map context(const AssessmentResult& r, const Stamp& stamp, const std::vector<Figure>& figs) {
    const Verdict& v = r.overall.verdict;
    mstch::array levels;
    for (const LevelResult& l : r.levels) levels.push_back(level_row(l));
    mstch::array checks;
    for (const HistoryCheck& h : r.history_checks) checks.push_back(history_row(h));
    mstch::array figures;
    for (const Figure& f : figs)
        figures.push_back(mstch::map{{"file", f.file}, {"caption", f.caption}, {"svg", f.svg}});
    return mstch::map{
        // A title and a heading are one line: a name's line breaks are shown, not obeyed.
        {"component_name", core::printable_name(r.input.component.name)},
        {"description", r.input.component.description},
        {"verdict", verdict_text(v)},
        {"verdict_kind", std::string(to_string(v.kind))},
        {"verdict_margin", margin_with_basis(v)},
        {"verdict_decided_by", std::string(to_string(v.decided_by))},
        {"governing", headline_level(r)},
        {"conditions", text_list(v.conditions)},
        {"has_own_base", shows_own_base(r)},
        {"own_base", own_base_line(r)},
        {"upgrade_needed", r.upgrade.needed},
        {"upgrade_summary", upgrade_summary(r)},
        {"trials", trial_rows(r.upgrade)},
        {"inputs", inputs(r.input, r.levels)},
        {"levels", levels},
        {"how_sure", how_sure_rows(r.levels, r.input.component.allowable_slide_m)},
        {"has_how_sure", std::any_of(r.levels.begin(), r.levels.end(),
                                     [](const LevelResult& l) { return l.settling.has_value(); })},
        {"flex_notes", flex_notes(r.levels)},
        {"flex_compare", flex_compare(r.levels)},
        {"has_flex_compare", std::any_of(r.levels.begin(), r.levels.end(), [](const LevelResult& l) {
             return l.flexible_simulation.has_value();
         })},
        {"figures", figures},
        {"has_history_checks", !r.history_checks.empty()},
        {"history_basis", history_basis(r.input.site)},
        {"history_checks", checks},
        {"assumptions", text_list(r.assumptions)},
        {"limits", text_list(r.limits)},
        {"references", reference_items(references())},
        {"stamp_version", stamp.tool_version},
        {"stamp_commit", stamp.commit},
        {"stamp_case_file", stamp.case_file},
        {"stamp_sha256", stamp.input_sha256},
        {"stamp_seed", std::to_string(stamp.seed)},
        {"stamp_inputs", stamp_input_items(stamp)},
    };
}


}  // namespace

std::string headline_level(const AssessmentResult& r) {
    // The goal speaks for a PGA over both directions, not for one level.
    std::string out = r.overall.verdict.failure == Failure::performance_goal
                          ? fmt::format("performance goal at PGA {:.3f} g", r.overall.pga_g)
                          : level_name(r.overall.pga_g, r.overall.direction);
    if (r.overall_from_trial) {
        const std::string& m = r.overall.verdict.material;
        out += " with " + (m.empty() ? r.upgrade.recommended.value_or("the recommended base") : m);
    }
    return out;
}

Rendered render(const AssessmentResult& r, const Stamp& stamp, const fragility::Result* fragility,
                const goal::PerformanceGoal* goal) {
    if (r.joined) return render_joined(r, stamp);
    Rendered out;
    out.figures = figures(r);
    mstch::map ctx = context(r, stamp, out.figures);
    ctx.emplace("has_fragility", fragility != nullptr);
    if (fragility) {
        // The section's figure is written beside the others for the Markdown report and
        // inlined by the HTML section itself (frag_svg), so it is not in the figure gallery.
        const Figure fig = fragility_figure(*fragility);
        for (auto& [key, value] : fragility_section_context(*fragility, fig))
            ctx.emplace(key, value);
        out.extra_files.push_back({fig.file, fig.svg});
    }
    ctx.emplace("has_goal", goal != nullptr);
    if (goal)
        for (auto& [key, value] : goal_section_context(*goal)) ctx.emplace(key, value);
    out.markdown = render_markdown(template_report_md, ctx,
                                   {{"fragility_section", template_fragility_section_md}});
    out.html = render_html(template_report_html, ctx,
                           {{"fragility_section", template_fragility_section_html}});
    out.json = result_json_text(r, stamp, fragility, goal);
    return out;
}

std::vector<core::OutputFile> report_files(const Rendered& rendered) {
    std::vector<core::OutputFile> files;
    for (const Figure& f : rendered.figures) files.push_back({f.file, f.svg});
    for (const core::OutputFile& f : rendered.extra_files) files.push_back(f);
    files.push_back({"report.md", rendered.markdown});
    files.push_back({"report.html", rendered.html});
    files.push_back({"result.json", rendered.json});
    return files;
}

void write_report(const std::filesystem::path& dir, const Rendered& rendered) {
    core::publish_folder(dir, report_files(rendered));
}

}  // namespace freestand::report
