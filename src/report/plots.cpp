#include "report/plots.hpp"

#include <fmt/format.h>

#include <algorithm>

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
        fmt::format("Motion-initiation diagram, direction {}: regions of METHODS.md s.2 for "
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

}  // namespace

std::vector<Figure> figures(const assess::AssessmentResult& r) {
    std::vector<Figure> out;
    for (const auto& d : r.plots.initiation) out.push_back(initiation_figure(r, d));
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
