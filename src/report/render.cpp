#include "report/render.hpp"

#include <fmt/format.h>

#include <mstch/mstch.hpp>

#include "assess/verdict.hpp"
#include "core/file_io.hpp"

namespace freestand::report {

// Defined in the generated templates_embedded.cpp (src/report/CMakeLists.txt).
extern const char* const template_report_md;
extern const char* const template_report_html;

namespace {

using namespace freestand::assess;

const std::string none = "n/a";

std::string fixed(double v, int precision) { return fmt::format("{:.{}f}", v, precision); }
std::string fixed(const std::optional<double>& v, int precision) {
    return v ? fixed(*v, precision) : none;
}
std::string mm(const std::optional<double>& v_m) { return v_m ? fixed(*v_m * 1000.0, 1) : none; }

mstch::map input(std::string name, std::string value, std::string unit, std::string note = "") {
    return mstch::map{{"name", std::move(name)},
                      {"value", std::move(value)},
                      {"unit", std::move(unit)},
                      {"note", std::move(note)}};
}

std::string pair(double a, double b, int precision) {
    return fixed(a, precision) + ", " + fixed(b, precision);
}

mstch::array inputs(const Case& c) {
    const Component& k = c.component;
    mstch::array out;
    out.push_back(input("mass", fixed(k.mass_kg, 1), "kg"));
    out.push_back(input("CG height above the contact plane", fixed(k.cg_height_m, 3), "m",
                        k.uniform_block ? "uniform block: half the height" : ""));
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
    out.push_back(input("free-rocking band",
                        k.free_rocking_band_hz
                            ? pair((*k.free_rocking_band_hz)[0], (*k.free_rocking_band_hz)[1], 2)
                            : none,
                        "Hz"));
    out.push_back(input("base material", k.base.material.empty() ? none : k.base.material, "",
                        k.base.source));
    out.push_back(input("static friction mu_s", fixed(k.base.mu_s, 3), "-"));
    out.push_back(input("kinetic friction mu_k", fixed(k.base.mu_k, 3), "-"));
    out.push_back(input("restitution r",
                        k.base.restitution ? fixed(*k.base.restitution, 3) : "Housner", "-"));
    out.push_back(
        input("allowable slide (clearance)", fixed(k.allowable_slide_m * 1000.0, 1), "mm"));
    out.push_back(
        input("required overturning factor of safety", fixed(k.required_overturn_fs, 2), "-"));
    out.push_back(
        input("design spectrum", c.site.design == "rg1.60" ? "US NRC RG 1.60" : c.site.design, ""));
    std::string levels;
    for (double p : c.site.pga_g) levels += (levels.empty() ? "" : ", ") + fixed(p, 3);
    out.push_back(input("PGA levels (horizontal)", levels, "g"));
    out.push_back(input("vertical / horizontal PGA", fixed(c.site.vertical_ratio, 4), "-"));
    out.push_back(
        input("damping of the sliding spectrum", fixed(c.site.sliding_damping * 100.0, 1), "%"));
    out.push_back(input("gravity", fixed(c.site.g_mps2, 3), "m/s^2"));
    out.push_back(input("histories per level", std::to_string(c.options.histories_per_level), ""));
    out.push_back(input("simulate", to_string(c.options.simulate), ""));
    return out;
}

std::string margin_text(const Verdict& v) { return v.margin ? fixed(*v.margin, 2) : "unbounded"; }

mstch::map level_row(const LevelResult& l) {
    const auto& sim = l.simulation;
    std::string amp = none;
    if (sim) {
        amp = fixed(sim->amplification_max, 2) + " (sim max)";
    } else if (l.rocking.amplification_estimate) {
        amp = "~" + fixed(*l.rocking.amplification_estimate, 2);
    } else {
        amp = "1.3-11 (rocking, measured range)";
    }
    std::string el_fs = none;
    if (l.initiation.mode != Mode::rock && l.initiation.mode != Mode::slide_rock) {
        el_fs = "not rocking";
    } else if (l.rocking.overturn_predicted) {
        el_fs = "overturns";
    } else if (l.rocking.overturn_fs) {
        el_fs = fixed(*l.rocking.overturn_fs, 2);
    } else if (!l.rocking.gate_passed) {
        el_fs = "no uplift";
    }
    return mstch::map{
        {"pga", fixed(l.pga_g, 3)},
        {"pga_v", fixed(l.pga_v_g, 3)},
        {"dir", std::string(to_string(l.direction))},
        {"mode", std::string(to_string(l.initiation.mode))},
        {"flex", std::string(l.flexible.raised ? "FLAG" : "")},
        {"a_ratio", fixed(l.initiation.a_ratio, 3)},
        {"slide_asce", mm(l.sliding.slide_asce_m)},
        {"slide_energy", mm(l.sliding.slide_energy_m)},
        {"sim_max", sim ? mm(sim->slide_max_max_m) : none},
        {"sim_residual", sim ? mm(sim->slide_residual_max_m) : none},
        {"rock_sim", sim ? fixed(sim->rock_max_over_alpha_max, 3) : none},
        {"el_fs", el_fs},
        {"overturned", sim ? fixed(sim->overturned_fraction * 100.0, 0) + "%" : none},
        {"amplification", amp},
        {"verdict", verdict_text(l.verdict)},
        {"margin", margin_text(l.verdict)},
        {"decided_by", std::string(to_string(l.verdict.decided_by))},
        {"simulation_reason", l.simulation_reason + "."},
        {"sliding_reason", l.sliding.reason},
    };
}

mstch::array text_list(const std::vector<std::string>& items) {
    mstch::array out;
    for (const std::string& s : items) out.push_back(mstch::map{{"text", s}});
    return out;
}

mstch::array flex_notes(const std::vector<LevelResult>& levels) {
    mstch::array out;
    for (const LevelResult& l : levels) {
        if (!l.flexible.raised) continue;
        out.push_back(mstch::map{
            {"text", fmt::format("PGA {:.3f} g, {}: mode stays {} ({}). Screen: {}. A flexible "
                                 "body may uplift below the "
                                 "static threshold (frequency-induced rocking, METHODS.md s.2).",
                                 l.pga_g, to_string(l.direction), to_string(l.initiation.mode),
                                 l.flexible.basis, l.flexible.reason)}});
    }
    return out;
}

std::string upgrade_summary(const Upgrade& up) {
    return up.recommended
               ? "the weakest material that passes every level is " + *up.recommended + "."
               : "no material of METHODS.md s.7 passes every level.";
}

mstch::map context(const AssessmentResult& r, const Stamp& stamp, const std::vector<Figure>& figs) {
    const LevelResult* gov = r.levels.empty() ? nullptr : &r.levels[r.governing_level];
    mstch::array trials;
    for (const MaterialTrial& t : r.upgrade.trials) {
        const std::string failing = t.verdict.kind == VerdictKind::anchor
                                        ? "does not pass: rocking / overturning"
                                        : "does not pass: slides beyond the allowable";
        trials.push_back(
            mstch::map{{"material", t.material},
                       {"mu_s", fixed(t.mu_s, 2)},
                       {"verdict", passes(t.verdict) ? verdict_text(t.verdict) : failing},
                       {"margin", margin_text(t.verdict)},
                       {"decided_by", std::string(to_string(t.verdict.decided_by))}});
    }
    mstch::array levels;
    for (const LevelResult& l : r.levels) levels.push_back(level_row(l));
    mstch::array checks;
    for (const HistoryCheck& h : r.history_checks) {
        checks.push_back(mstch::map{{"history", std::to_string(h.history)},
                                    {"component", h.component},
                                    {"method", h.method},
                                    {"passed", std::string(h.passed ? "yes" : "no: " + h.reason)},
                                    {"min_ratio", fixed(h.min_ratio, 3)},
                                    {"max_ratio", fixed(h.max_ratio, 3)}});
    }
    mstch::array figures;
    for (const Figure& f : figs)
        figures.push_back(mstch::map{{"file", f.file}, {"caption", f.caption}, {"svg", f.svg}});
    return mstch::map{
        {"component_name", r.input.component.name},
        {"description", r.input.component.description},
        {"verdict", verdict_text(r.overall)},
        {"verdict_kind", std::string(to_string(r.overall.kind))},
        {"verdict_margin", margin_text(r.overall) +
                               (r.overall.material.empty() ? "" : " with " + r.overall.material)},
        {"verdict_margin_basis", r.overall.margin_basis},
        {"verdict_decided_by", std::string(to_string(r.overall.decided_by))},
        {"governing",
         gov ? fmt::format("PGA {:.3f} g, direction {}", gov->pga_g, to_string(gov->direction))
             : none},
        {"upgrade_needed", r.upgrade.needed},
        {"upgrade_summary", upgrade_summary(r.upgrade)},
        {"trials", trials},
        {"inputs", inputs(r.input)},
        {"levels", levels},
        {"flex_notes", flex_notes(r.levels)},
        {"figures", figures},
        {"has_history_checks", !r.history_checks.empty()},
        {"history_checks", checks},
        {"assumptions", text_list(r.assumptions)},
        {"limits", text_list(r.limits)},
        {"stamp_version", stamp.tool_version},
        {"stamp_commit", stamp.commit},
        {"stamp_case_file", stamp.case_file},
        {"stamp_sha256", stamp.input_sha256},
        {"stamp_seed", std::to_string(stamp.seed)},
    };
}

// mstch's escape function is global: swap it for one render and restore it after.
class EscapeGuard {
  public:
    explicit EscapeGuard(std::function<std::string(const std::string&)> f)
        : saved_(mstch::config::escape) {
        mstch::config::escape = std::move(f);
    }
    ~EscapeGuard() { mstch::config::escape = saved_; }
    EscapeGuard(const EscapeGuard&) = delete;
    EscapeGuard& operator=(const EscapeGuard&) = delete;

  private:
    std::function<std::string(const std::string&)> saved_;
};

}  // namespace

std::string markdown_escape(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '\n':
            case '\r':
                out += ' ';
                break;
            case '\\':
            case '`':
            case '*':
            case '_':
            case '[':
            case ']':
            case '|':
            case '#':
            case '!':
                out += '\\';
                out += c;
                break;
            default:
                out += c;
        }
    }
    return out;
}

Rendered render(const AssessmentResult& r, const Stamp& stamp) {
    Rendered out;
    out.figures = figures(r);
    const mstch::map ctx = context(r, stamp, out.figures);
    {
        EscapeGuard guard(markdown_escape);
        out.markdown = mstch::render(template_report_md, ctx);
    }
    out.html = mstch::render(template_report_html, ctx);
    out.json = to_json(r, stamp).dump(2) + "\n";
    return out;
}

void write_report(const std::filesystem::path& dir, const Rendered& rendered) {
    for (const Figure& f : rendered.figures) core::write_file_atomic(dir / f.file, f.svg);
    core::write_file_atomic(dir / "report.md", rendered.markdown);
    core::write_file_atomic(dir / "report.html", rendered.html);
    core::write_file_atomic(dir / "result.json", rendered.json);
}

}  // namespace freestand::report
