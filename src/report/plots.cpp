#include "report/plots.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "assess/verdict.hpp"
#include "report/svg.hpp"

namespace freestand::report {

namespace {

const std::vector<std::string> palette{"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                       "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};

Line to_line(const assess::Series& s, std::string color, double width = 1.2) {
    return Line{s.label, s.x, s.y, std::move(color), width, false};
}

Figure initiation_figure(const assess::AssessmentResult& r, const assess::InitiationDiagram& d) {
    const char* dir = assess::to_string(d.direction);
    const double ta = d.tan_alpha;
    const double x_max = d.a_g.empty() ? 2.0 * ta : d.a_g.back();
    double y_max = std::max(1.0, 1.2 * r.input.component.base.mu_s);
    for (const auto& p : d.points) y_max = std::max(y_max, 1.2 * p[1]);
    Plot p;
    p.title = fmt::format("Motion initiation, direction {} (tan alpha = {:.3f})", dir, ta);
    p.x = Axis{"A = PGA_h / (1 - PGA_v)", false, 0.0, x_max};
    p.y = Axis{"static friction mu_s", false, 0.0, y_max};
    p.regions.push_back(Region{"rest", {{0, 0}, {ta, ta}, {ta, y_max}, {0, y_max}}, "#e8f4e8"});
    p.regions.push_back(Region{"slide", {{0, 0}, {x_max, 0}, {x_max, ta}, {ta, ta}}, "#e3eefa"});
    Region rock{"rock", {{ta, ta}}, "#fbe9d7"};
    Region slide_rock{"slide-rock", {{ta, ta}, {x_max, ta}}, "#f6dcef"};
    for (std::size_t i = 0; i < d.a_g.size(); ++i)
        rock.polygon.push_back({d.a_g[i], std::min(d.mu_crit[i], y_max)});
    rock.polygon.push_back({x_max, y_max});
    rock.polygon.push_back({ta, y_max});
    for (std::size_t i = d.a_g.size(); i-- > 0;)
        slide_rock.polygon.push_back({d.a_g[i], std::min(d.mu_crit[i], y_max)});
    p.regions.push_back(rock);
    p.regions.push_back(slide_rock);
    p.lines.push_back(Line{"mu_crit(A) (Shenton 1996)", d.a_g, d.mu_crit, "#555555", 1.2, true});
    std::size_t k = 0;
    for (const assess::LevelResult& l : r.levels) {
        if (l.direction != d.direction || k >= d.points.size()) continue;
        p.markers.push_back(
            Marker{fmt::format("{:.2f} g", l.pga_g), d.points[k][0], d.points[k][1], "#000000"});
        ++k;
    }
    return Figure{
        fmt::format("initiation-{}.svg", dir),
        fmt::format("Motion-initiation diagram, direction {}: regions of docs/methods.md s.2 for "
                    "this block, and the case's point at each PGA level.",
                    dir),
        render_svg(p)};
}

Figure spectra_figure(const assess::AssessmentResult& r) {
    Plot p;
    p.title = "Response spectra, 5% damping: target and matched histories";
    p.x = Axis{"frequency (Hz)", true, 0.1, 100.0};
    p.y = Axis{"pseudo-spectral acceleration (g)", true, {}, {}};
    const auto& s = r.plots.spectra;
    for (std::size_t i = 1; i < s.size(); ++i)
        p.lines.push_back(to_line(s[i], palette[(i - 1) % palette.size()], 0.8));
    if (!s.empty()) p.lines.push_back(Line{s[0].label, s[0].x, s[0].y, "#000000", 2.0, false});
    return Figure{"spectra.svg",
                  s.size() > 1
                      ? "Target (black) and the matched horizontal histories at the shown level."
                      : "Target spectrum (no histories were generated).",
                  render_svg(p)};
}

Figure history_figure(const std::string& file, const std::string& title, const std::string& y_label,
                      const std::vector<assess::Series>& series, const std::string& caption) {
    Plot p;
    p.title = title;
    p.x = Axis{"time (s)", false, 0.0, {}};
    p.y = Axis{y_label, false, {}, {}};
    for (std::size_t i = 0; i < series.size(); ++i)
        p.lines.push_back(to_line(series[i], palette[i % palette.size()]));
    return Figure{file, caption, render_svg(p)};
}

// Points (PGA, value) of one curve; a level without the value adds nothing.
struct Curve {
    std::vector<double> pga_g;
    std::vector<double> value;
    void add(double pga, double v) {
        pga_g.push_back(pga);
        value.push_back(v);
    }
    bool empty() const { return pga_g.empty(); }
};

// Adds a curve drawn with a dot at each level (simulated curves may have a single point).
void add_curve(Plot& p, const std::string& label, const Curve& c, const std::string& color,
               bool dashed) {
    if (c.empty()) return;
    Line l{label, c.pga_g, c.value, color, 1.5, dashed};
    l.points = true;
    p.lines.push_back(std::move(l));
}

// A horizontal reference line across the levels' PGA range (from 0, the axis origin).
void add_limit(Plot& p, const std::string& label, double y, double pga_max_g) {
    p.lines.push_back(Line{label, {0.0, pga_max_g}, {y, y}, "#000000", 1.0, false});
}

std::vector<const assess::LevelResult*> levels_of(const assess::AssessmentResult& r,
                                                  assess::Direction d) {
    std::vector<const assess::LevelResult*> out;
    for (const assess::LevelResult& l : r.levels) {
        if (l.direction == d) out.push_back(&l);
    }
    return out;
}

double pga_max_g(const std::vector<const assess::LevelResult*>& levels) {
    double out = 0.0;
    for (const assess::LevelResult* l : levels) out = std::max(out, l->pga_g);
    return out;
}

// The statistic of a simulated level that its verdict reads (docs/methods.md s.6 step 3).
double governing_of(const assess::Simulation& sim, const assess::Stats& s) {
    return sim.governing(s);
}

bool biaxial_ran(const assess::LevelResult& l) { return l.biaxial && l.biaxial->ran; }

// The 3D body's runs where they decide the level (alone, or beside the flexible body).
const assess::Simulation* body3d_sim(const assess::LevelResult& l) {
    return l.body3d && l.body3d->ran ? &l.body3d->sim : nullptr;
}

// The sliding demand the level's verdict read, as decide_level reads it (assess/verdict.cpp):
// the 3D body's where it decides; the flexible body's slip, or the biaxial |u| where that is
// larger (or the rigid 3D body's beside it); else, where the simulation
// decides, the biaxial |u| where it ran and the planar slip where not. None where the screen
// decides.
std::optional<double> deciding_slide_m(const assess::LevelResult& l) {
    if (!l.simulation) return std::nullopt;
    const assess::Simulation* body3d = body3d_sim(l);
    if (assess::body3d_decides(l)) return governing_of(*body3d, body3d->slide_m);
    if (l.flexible_simulation) {
        const assess::Simulation& s = l.flexible_simulation->sim;
        double v = governing_of(s, s.slide_m);
        if (biaxial_ran(l)) v = std::max(v, governing_of(s, l.biaxial->slide_m));
        // With the 3D body beside it, the worse verdict governs: the larger demand here.
        if (body3d) v = std::max(v, governing_of(*body3d, body3d->slide_m));
        return v;
    }
    if (body3d) return governing_of(*body3d, body3d->slide_m);
    if (l.screen.passed) return std::nullopt;
    const assess::Simulation& s = *l.simulation;
    return governing_of(s, biaxial_ran(l) ? l.biaxial->slide_m : s.slide_m);
}

// theta_max / alpha that the level's verdict read: the flexible body's where it ran, else the
// planar block's where the simulation decides; none where every set overturned.
std::optional<double> deciding_rock_over_alpha(const assess::LevelResult& l) {
    if (!l.simulation) return std::nullopt;
    const auto standing = [](const assess::Simulation* s) -> std::optional<double> {
        if (!s || s->overturned >= s->histories) return std::nullopt;
        return governing_of(*s, s->rock_over_alpha);
    };
    const auto body3d = standing(body3d_sim(l));
    if (assess::body3d_decides(l)) return body3d;
    const auto other = standing(l.flexible_simulation ? &l.flexible_simulation->sim
                                : l.screen.passed || body3d_sim(l) ? nullptr
                                                                   : &*l.simulation);
    if (body3d && other) return std::max(*body3d, *other);
    return body3d ? body3d : other;
}

void add_finite(Curve& c, double pga_g, double v, double scale = 1.0) {
    if (std::isfinite(v)) c.add(pga_g, v * scale);
}

// The deciding demand: drawn last, in black and wider, over the models it was taken from.
void add_deciding(Plot& p, const Curve& c) {
    if (c.empty()) return;
    Line l{
        "decides: 84th percentile of the deciding model", c.pga_g, c.value, "#000000", 2.6, false};
    l.points = true;
    p.lines.push_back(std::move(l));
}

// Sliding demand against PGA: the ASCE 4 screen and the energy estimate at the lower friction
// bound; at the simulated levels the 84th percentile of each model that ran (planar rigid
// block, biaxial rigid block, flexible body) and the planar maximum; the demand that decided
// each level; the allowable.
std::optional<Figure> slide_demand_figure(const assess::AssessmentResult& r, assess::Direction d) {
    const auto levels = levels_of(r, d);
    Curve asce, energy, planar, planar_max, biaxial, flexible, body3d, deciding;
    for (const assess::LevelResult* l : levels) {
        if (l->sliding.slide_asce_m) asce.add(l->pga_g, *l->sliding.slide_asce_m * 1000.0);
        if (l->sliding.slide_energy_m) energy.add(l->pga_g, *l->sliding.slide_energy_m * 1000.0);
        if (!l->simulation) continue;
        const assess::Simulation& sim = *l->simulation;
        add_finite(planar, l->pga_g, governing_of(sim, sim.slide_m), 1000.0);
        add_finite(planar_max, l->pga_g, sim.slide_m.max, 1000.0);
        if (biaxial_ran(*l))
            add_finite(biaxial, l->pga_g, governing_of(sim, l->biaxial->slide_m), 1000.0);
        if (l->flexible_simulation) {
            const assess::Simulation& f = l->flexible_simulation->sim;
            add_finite(flexible, l->pga_g, governing_of(f, f.slide_m), 1000.0);
        }
        if (const assess::Simulation* b = body3d_sim(*l))
            add_finite(body3d, l->pga_g, governing_of(*b, b->slide_m), 1000.0);
        if (const auto v = deciding_slide_m(*l)) add_finite(deciding, l->pga_g, *v, 1000.0);
    }
    if (asce.empty() && energy.empty() && planar.empty()) return std::nullopt;
    const char* dir = assess::to_string(d);
    const double allowable_mm = r.input.component.allowable_slide_m * 1000.0;
    Plot p;
    p.title = fmt::format("Sliding demand against PGA, direction {}", dir);
    p.x = Axis{"PGA (g)", false, 0.0, {}};
    p.y = Axis{"peak slide (mm)", false, 0.0, {}};
    add_curve(p, "ASCE 4 at the lower friction bound (screen)", asce, palette[0], false);
    add_curve(p, "energy conservation (informational)", energy, palette[1], true);
    add_curve(p, "planar rigid block, 84th percentile", planar, palette[4], false);
    add_curve(p, "planar rigid block, maximum", planar_max, palette[3], true);
    add_curve(p, "biaxial rigid block |u|, 84th percentile", biaxial, palette[5], false);
    add_curve(p, "flexible body, 84th percentile", flexible, palette[6], false);
    add_curve(p, "3D body |u|, 84th percentile (standing sets)", body3d, palette[2], false);
    add_deciding(p, deciding);
    add_limit(p, fmt::format("allowable slide {:.1f} mm (clearance)", allowable_mm), allowable_mm,
              pga_max_g(levels));
    return Figure{fmt::format("demand-slide-{}.svg", dir),
                  fmt::format("Sliding demand against PGA, direction {}: ASCE 4 at the lower "
                              "friction bound (the screen), energy conservation (dashed, "
                              "informational: it never decides), the 84th percentile of each "
                              "model simulated at a level (planar rigid block, biaxial rigid "
                              "block, flexible body, 3D body) with the planar maximum (dashed), the "
                              "demand that decided each simulated level (black: the deciding "
                              "model's 84th percentile, docs/methods.md s.6), and the allowable "
                              "slide.",
                              dir),
                  render_svg(p)};
}

// theta_max / alpha against PGA: the equivalent-linear screen; at the simulated levels the 84th
// percentile of the planar rigid block (at the worse restitution bound) and of the flexible
// body, the planar maximum, and the demand that decided; the limit 1 / FS_required; overturns.
std::optional<Figure> rock_demand_figure(const assess::AssessmentResult& r, assess::Direction d) {
    const auto levels = levels_of(r, d);
    Curve screen, planar, planar_max, flexible, body3d, deciding;
    std::vector<Marker> overturns;
    for (const assess::LevelResult* l : levels) {
        if (l->rocking.theta_rad && l->rocking.alpha_rad > 0.0)
            screen.add(l->pga_g, *l->rocking.theta_rad / l->rocking.alpha_rad);
        if (!l->simulation) continue;
        const assess::Simulation& sim = *l->simulation;
        int over = l->flexible_simulation
                       ? std::max(sim.overturned, l->flexible_simulation->sim.overturned)
                       : sim.overturned;
        if (const assess::Simulation* b = body3d_sim(*l)) {
            over = assess::body3d_decides(*l) ? b->overturned : std::max(over, b->overturned);
            if (b->overturned < b->histories)
                add_finite(body3d, l->pga_g, governing_of(*b, b->rock_over_alpha));
        }
        if (over > 0) {
            // Drawn at theta / alpha = 1, where the block goes over.
            overturns.push_back(Marker{fmt::format("{}/{} overturned", over, sim.histories),
                                       l->pga_g, 1.0, "#000000"});
        }
        if (l->flexible_simulation) {
            const assess::Simulation& f = l->flexible_simulation->sim;
            if (f.overturned < f.histories)
                add_finite(flexible, l->pga_g, governing_of(f, f.rock_over_alpha));
        }
        if (const auto v = deciding_rock_over_alpha(*l)) add_finite(deciding, l->pga_g, *v);
        // The statistics cover the standing histories only: none when all went over.
        if (sim.overturned >= sim.histories) continue;
        add_finite(planar, l->pga_g, governing_of(sim, sim.rock_over_alpha));
        add_finite(planar_max, l->pga_g, sim.rock_over_alpha.max);
    }
    if (screen.empty() && planar.empty() && flexible.empty() && body3d.empty() &&
        overturns.empty())
        return std::nullopt;
    const char* dir = assess::to_string(d);
    const double fs = r.input.component.required_overturn_fs;
    Plot p;
    p.title = fmt::format("Rocking demand against PGA, direction {}", dir);
    // Room above theta / alpha = 1 and right of the last level for the overturn labels; no
    // plotted value exceeds 1 (standing histories, estimates below alpha).
    p.x = Axis{"PGA (g)", false, 0.0, {}};
    if (!overturns.empty()) p.x.max = 1.25 * pga_max_g(levels);
    p.y = Axis{"theta_max / alpha", false, 0.0, 1.2};
    add_curve(p, "equivalent-linear estimate at the upper bounds (screen)", screen, palette[0],
              true);
    add_curve(p, "planar rigid block, 84th percentile (standing sets)", planar, palette[4], false);
    add_curve(p, "planar rigid block, maximum (standing sets)", planar_max, palette[3], true);
    add_curve(p, "flexible body, 84th percentile (standing sets)", flexible, palette[6], false);
    add_curve(p, "3D body, tilt over critical, 84th percentile (standing sets)", body3d,
              palette[2], false);
    add_deciding(p, deciding);
    add_limit(p, fmt::format("1 / FS required = 1 / {:.2f} = {:.3f}", fs, 1.0 / fs), 1.0 / fs,
              p.x.max.value_or(pga_max_g(levels)));
    p.markers = std::move(overturns);
    return Figure{fmt::format("demand-rock-{}.svg", dir),
                  fmt::format("Rocking demand against PGA, direction {}: peak rotation over the "
                              "slenderness angle, the equivalent-linear estimate (dashed, the "
                              "screen), the 84th percentile of the planar rigid block at the "
                              "worse restitution bound, of the flexible body and of the 3D body "
                              "(its tilt over the critical tilt) where they ran, "
                              "the planar maximum (dashed), over the sets that stayed standing, "
                              "the demand that decided each simulated level (black: the deciding "
                              "model's 84th percentile), against the limit 1 / FS required; "
                              "levels with overturned sets are marked at theta / alpha = 1 (any "
                              "overturn fails the level).",
                              dir),
                  render_svg(p)};
}

}  // namespace

std::vector<Figure> figures(const assess::AssessmentResult& r) {
    std::vector<Figure> out;
    for (const auto& d : r.plots.initiation) out.push_back(initiation_figure(r, d));
    for (assess::Direction d : {assess::Direction::x, assess::Direction::y}) {
        if (auto f = slide_demand_figure(r, d)) out.push_back(std::move(*f));
        if (auto f = rock_demand_figure(r, d)) out.push_back(std::move(*f));
    }
    out.push_back(spectra_figure(r));
    if (!r.plots.ground_motion.empty()) {
        const std::string g = r.plots.governing;
        out.push_back(
            history_figure("ground-motion.svg", "Ground acceleration of the governing history",
                           "acceleration (g)", r.plots.ground_motion, "Ground motion: " + g + "."));
        out.push_back(history_figure("slip.svg", "Slip of the block relative to the base",
                                     "slip (m)", r.plots.slip, "Simulated slip: " + g + "."));
        out.push_back(history_figure("rotation.svg", "Rocking angle over the slenderness angle",
                                     "theta / alpha", r.plots.rotation,
                                     "Simulated rotation: " + g + "."));
    }
    return out;
}

}  // namespace freestand::report
