#include "report/fragility_report.hpp"

#include "report/fragility_json.hpp"

#include <nlohmann/json.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/printable.hpp"
#include "core/publish.hpp"
#include "fragility/fit.hpp"
#include "report/references.hpp"
#include "report/render.hpp"
#include "report/svg.hpp"
#include "report/template_render.hpp"

namespace freestand::report {

extern const char* const template_fragility_md;
extern const char* const template_fragility_html;
extern const char* const template_fragility_section_md;
extern const char* const template_fragility_section_html;

namespace {

using nlohmann::ordered_json;
using fragility::all_events;

const std::array<const char*, 4> kColors{"#d62728", "#1f77b4", "#ff7f0e", "#555555"};

std::string g3(double v) { return fmt::format("{:.3g}", v); }

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
    std::string out = "\"";
    for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string count_text(const fragility::Count& c) {
    return fmt::format("{} / {} [{:.3f}, {:.3f}]", c.k, c.n, c.ci[0], c.ci[1]);
}

// The fitted curve on a log grid over [lo, hi].
Line fitted_line(const fragility::Fit& f, double lo, double hi, const std::string& label,
                 const std::string& color) {
    Line l{label, {}, {}, color, 1.6, false, false};
    for (const fragility::CurvePoint& c : fragility::fitted_curve(f, lo, hi, 120)) {
        l.x.push_back(c.pga_g);
        l.y.push_back(c.p);
    }
    return l;
}

std::string method_text(const fragility::Meta& m) {
    return fmt::format(
        "Probability of each failure given the PGA (docs/methods.md s.9; FEMA P-58 practice): "
        "at each level, {} samples each draw a ground motion and the uncertain friction and "
        "restitution from their own random stream (seed, level, sample), simulate {} and count "
        "the failures; k / n with its exact "
        "95% interval (Clopper & Pearson 1934); a lognormal P(a) = Phi(ln(a / theta_m) / beta) "
        "fitted by maximum likelihood over the levels (Baker 2015), with Pearson's chi2 as the "
        "goodness of fit. A fit is omitted, with the reason, where no curve can be fitted.",
        m.config.samples, m.models);
}

std::string levels_text(const std::vector<double>& pga) {
    std::string out;
    for (double a : pga) out += (out.empty() ? "" : ", ") + fmt::format("{:g}", a);
    return out;
}

}  // namespace

std::string samples_csv(const fragility::Result& r) {
    std::string out =
        "level,sample,pga_g,motion,mu_s,restitution_x,restitution_y,slide_max_m,"
        "rock_max_over_alpha,overturned\n";
    for (const fragility::SampleResult& s : r.samples) {
        out += fmt::format("{},{},{},{},{},{},{},{},{},{}\n", s.level + 1, s.sample + 1,
                           round10(r.meta.config.pga_g[static_cast<std::size_t>(s.level)]),
                           csv_field(s.motion), round10(s.mu_s), round10(s.restitution_x),
                           round10(s.restitution_y), round10(s.slide_max_m),
                           round10(s.rock_max_over_alpha), s.overturned ? "true" : "false");
    }
    return out;
}

Figure fragility_figure(const fragility::Result& r) {
    const std::vector<double>& pga = r.meta.config.pga_g;
    const double lo = pga.front() / (pga.size() > 1 ? 1.25 : 2.0);
    const double hi = pga.back() * 1.25;
    Plot p;
    p.title = fmt::format("Fragility: {}", core::printable_name(r.meta.case_name));
    p.x = Axis{"PGA (g)", false, 0.0, hi};
    p.y = Axis{"P(failure | PGA)", false, 0.0, 1.0};
    for (std::size_t e = 0; e < all_events.size(); ++e) {
        const std::string name = fragility::event_name(all_events[e]);
        const std::string color = kColors[e];
        Line points{name + ": k / n with 95% interval", {}, {}, color, 0.0, false, true};
        for (const fragility::Level& l : r.levels) {
            points.x.push_back(l.pga_g);
            points.y.push_back(l.events[e].p);
            p.lines.push_back(Line{"", {l.pga_g, l.pga_g}, {l.events[e].ci[0], l.events[e].ci[1]},
                                   color, 1.0, false, false});
        }
        p.lines.push_back(points);
        if (r.fits[e].fit)
            p.lines.push_back(fitted_line(*r.fits[e].fit, lo, hi,
                                          fmt::format("{}: lognormal theta_m {:.3g} g, beta {:.3g}",
                                                      name, r.fits[e].fit->theta_m_g,
                                                      r.fits[e].fit->beta),
                                          color));
    }
    return Figure{"fragility.svg",
                  "Fragility curves: observed failure fraction k / n at each level with its 95% "
                  "Clopper-Pearson interval (bars) and the lognormal fitted by maximum likelihood, "
                  "per failure event (docs/methods.md s.9).",
                  render_svg(p)};
}

mstch::map fragility_section_context(const fragility::Result& r, const Figure& figure) {
    const fragility::Meta& m = r.meta;
    mstch::array fits;
    for (std::size_t e = 0; e < all_events.size(); ++e) {
        const fragility::EventFit& f = r.fits[e];
        const std::string name = fragility::event_name(all_events[e]);
        if (!f.fit) {
            fits.push_back(mstch::map{{"event", name}, {"theta", std::string("no fit")},
                                      {"beta", std::string("")}, {"p1", std::string("")},
                                      {"p5", std::string("")}, {"p50", std::string("")},
                                      {"gof", f.note}});
            continue;
        }
        const fragility::Fit& x = *f.fit;
        fits.push_back(mstch::map{
            {"event", name},
            {"theta", g3(x.theta_m_g)},
            {"beta", g3(x.beta)},
            {"p1", g3(x.pga_1pct_g)},
            {"p5", g3(x.pga_5pct_g)},
            {"p50", g3(x.pga_50pct_g)},
            {"gof", x.p_value ? fmt::format("{:.3g} ({}, p = {:.3g})", x.chi2, x.dof, *x.p_value)
                              : fmt::format("{:.3g} (dof {}: no test)", x.chi2, x.dof)}});
    }
    mstch::array rows;
    double widest = 0.0;
    for (const fragility::Level& l : r.levels) {
        for (const fragility::Count& c : l.events) widest = std::max(widest, c.ci[1] - c.ci[0]);
        rows.push_back(mstch::map{{"pga", fmt::format("{:.3f}", l.pga_g)},
                                  {"n", std::to_string(l.n)},
                                  {"overturn", count_text(l.events[0])},
                                  {"slide", count_text(l.events[1])},
                                  {"rock", count_text(l.events[2])},
                                  {"any", count_text(l.events[3])}});
    }
    std::string events;
    for (const fragility::Event e : all_events)
        events += (events.empty() ? "" : "; ") + std::string(fragility::event_name(e)) + ": " +
                  event_meaning(e, m);
    return mstch::map{{"frag_method", method_text(m)},
                      {"frag_levels", levels_text(m.config.pga_g)},
                      {"frag_samples", std::to_string(m.config.samples)},
                      {"frag_seed", std::to_string(m.config.seed)},
                      {"frag_motion", m.motion_source},
                      {"frag_models", m.models},
                      {"frag_mu_law", m.mu_s_law},
                      {"frag_r_law", m.restitution_law},
                      {"frag_events", events},
                      {"frag_fits", fits},
                      {"frag_rows", rows},
                      {"frag_halfwidth", fmt::format("{:.3f}", widest)},
                      {"frag_figure_file", figure.file},
                      {"frag_caption", figure.caption},
                      {"frag_svg", figure.svg}};
}

RenderedFragility render_fragility(const fragility::Result& r, const Stamp& stamp) {
    RenderedFragility out;
    out.figure = fragility_figure(r);
    mstch::map ctx = fragility_section_context(r, out.figure);
    ctx.emplace("frag_case", core::printable_name(r.meta.case_name));  // a title: one line
    ctx.emplace("references", reference_items(fragility_references()));
    ctx.emplace("stamp_version", stamp.tool_version);
    ctx.emplace("stamp_commit", stamp.commit);
    ctx.emplace("stamp_case_file", stamp.case_file);
    ctx.emplace("stamp_sha256", stamp.input_sha256);
    ctx.emplace("stamp_seed", std::to_string(stamp.seed));
    ctx.emplace("stamp_inputs", stamp_input_items(stamp));
    out.markdown = render_markdown(template_fragility_md, ctx,
                                   {{"section", template_fragility_section_md}});
    out.html = render_html(template_fragility_html, ctx,
                           {{"section", template_fragility_section_html}});
    out.json = fragility_json(r, stamp).dump(2) + "\n";
    out.csv = samples_csv(r);
    return out;
}

void write_fragility(const std::filesystem::path& dir, const RenderedFragility& rendered,
                     const std::vector<core::OutputFile>& extra) {
    std::vector<core::OutputFile> files{{rendered.figure.file, rendered.figure.svg},
                                        {"report.md", rendered.markdown},
                                        {"report.html", rendered.html},
                                        {"fragility.json", rendered.json},
                                        {"samples.csv", rendered.csv}};
    files.insert(files.end(), extra.begin(), extra.end());
    core::publish_folder(dir, files);
}

}  // namespace freestand::report
