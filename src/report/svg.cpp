#include "report/svg.hpp"

#include "report/escape.hpp"
#include "core/steps.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace freestand::report {

namespace {

constexpr double margin_left = 70.0;
constexpr double margin_right = 20.0;
constexpr double margin_top = 34.0;
constexpr double margin_bottom = 48.0;
constexpr double legend_row_px = 16.0;

struct Scale {
    double lo = 0.0;
    double hi = 1.0;
    bool log = false;
    double px0 = 0.0;  // pixel of lo
    double px1 = 1.0;  // pixel of hi

    double operator()(double v) const {
        const double t = log ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo))
                             : (v - lo) / (hi - lo);
        return px0 + t * (px1 - px0);
    }
    bool contains(double v) const { return std::isfinite(v) && (!log || v > 0.0); }
};

// A "nice" step of 1, 2 or 5 x 10^k giving about `target` intervals.
double nice_step(double span, int target) {
    const double raw = span / target;
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0}) {
        if (m * mag >= raw) return m * mag;
    }
    return 10.0 * mag;
}

Scale make_scale(const Axis& axis, std::vector<double> values, double px0, double px1) {
    Scale s;
    s.log = axis.log;
    s.px0 = px0;
    s.px1 = px1;
    values.erase(
        std::remove_if(values.begin(), values.end(),
                       [&](double v) { return !std::isfinite(v) || (axis.log && v <= 0.0); }),
        values.end());
    double lo =
        values.empty() ? (axis.log ? 0.1 : 0.0) : *std::min_element(values.begin(), values.end());
    double hi = values.empty() ? 1.0 : *std::max_element(values.begin(), values.end());
    if (axis.log) {
        lo = std::pow(10.0, std::floor(std::log10(lo)));
        hi = std::pow(10.0, std::ceil(std::log10(hi)));
        if (hi <= lo) hi = lo * 10.0;
    } else {
        if (hi <= lo) {
            hi = lo + 1.0;
            lo -= 1.0;
        }
        const double step = nice_step(hi - lo, 5);
        lo = std::floor(lo / step) * step;
        hi = std::ceil(hi / step) * step;
    }
    s.lo = axis.min.value_or(lo);
    s.hi = axis.max.value_or(hi);
    return s;
}

// Ticks on one axis, at most: a log axis from a denormal to 1 spans over 300 decades, and a
// linear step below the values' rounding never advances, so the loops are bounded by count.
constexpr std::size_t max_ticks = 12;

// Powers of ten from lo (every stride-th decade when there are more than max_ticks).
std::vector<double> log_ticks(const Scale& s) {
    std::vector<double> out;
    if (!(s.lo > 0.0 && s.hi >= s.lo && std::isfinite(s.hi))) return out;
    // A span of whole decades (0.1 to 100) whose logarithms differ by a rounding short of 3
    // still counts all of them.
    constexpr double whole_decade_guard = 1e-7;
    const double decades =
        std::floor(std::log10(s.hi) - std::log10(s.lo) + whole_decade_guard) + 1.0;
    const int stride = static_cast<int>(std::ceil(decades / static_cast<double>(max_ticks)));
    for (double v = s.lo; v <= s.hi * 1.0000001 && out.size() < max_ticks;) {
        out.push_back(v);
        for (int k = 0; k < stride; ++k) v *= 10.0;
    }
    return out;
}

std::vector<double> linear_ticks(const Scale& s) {
    std::vector<double> out;
    const double step = nice_step(s.hi - s.lo, 5);
    if (!(step > 0.0 && std::isfinite(step))) return out;
    const double near_step = step * core::tol::relative;
    for (double v = core::steps_covering(s.lo / step) * step;
         v <= s.hi + near_step && out.size() < max_ticks; v += step) {
        out.push_back(std::abs(v) < near_step ? 0.0 : v);
    }
    return out;
}

std::vector<double> ticks(const Scale& s) { return s.log ? log_ticks(s) : linear_ticks(s); }

std::string tick_label(double v) {
    if (v == 0.0) return "0";
    const double a = std::abs(v);
    if (a >= 1e4 || a < 1e-3) return fmt::format("{:.0e}", v);
    std::string s = fmt::format("{:.4f}", v);
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s;
}

std::string points_attr(const std::vector<double>& x, const std::vector<double>& y, const Scale& sx,
                        const Scale& sy) {
    std::string out;
    const std::size_t n = std::min(x.size(), y.size());
    for (std::size_t i = 0; i < n; ++i) {
        if (!sx.contains(x[i]) || !sy.contains(y[i])) continue;
        // Clamp to the frame so off-scale points do not leave the picture.
        const double px = std::clamp(sx(x[i]), std::min(sx.px0, sx.px1), std::max(sx.px0, sx.px1));
        const double py = std::clamp(sy(y[i]), std::min(sy.px0, sy.px1), std::max(sy.px0, sy.px1));
        out += fmt::format("{}{:.1f},{:.1f}", out.empty() ? "" : " ", px, py);
    }
    return out;
}

std::string vertex_dots(const Line& l, const Scale& sx, const Scale& sy) {
    std::string out;
    const std::size_t n = std::min(l.x.size(), l.y.size());
    for (std::size_t i = 0; i < n; ++i) {
        if (!sx.contains(l.x[i]) || !sy.contains(l.y[i])) continue;
        out += fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"3\" fill=\"{}\"/>\n",
                           sx(l.x[i]), sy(l.y[i]), l.color);
    }
    return out;
}

/// Every plotted value of each axis: the lines', the regions' corners and the markers'.
std::array<std::vector<double>, 2> plotted_values(const Plot& plot) {
    std::vector<double> xs, ys;
    for (const Line& l : plot.lines) {
        xs.insert(xs.end(), l.x.begin(), l.x.end());
        ys.insert(ys.end(), l.y.begin(), l.y.end());
    }
    for (const Region& r : plot.regions) {
        for (const auto& p : r.polygon) {
            xs.push_back(p[0]);
            ys.push_back(p[1]);
        }
    }
    for (const Marker& m : plot.markers) {
        xs.push_back(m.x);
        ys.push_back(m.y);
    }
    return {std::move(xs), std::move(ys)};
}

/// The plot area's geometry in pixels.
struct Frame {
    double width_px, height_px, bottom_px;
    Scale sx, sy;
};

std::string svg_head(const Plot& plot, const Frame& f) {
    std::string out = fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" viewBox=\"0 "
        "0 "
        "{:.0f} {:.0f}\" font-family=\"sans-serif\" font-size=\"11\">\n",
        f.width_px, f.height_px, f.width_px, f.height_px);
    out +=
        fmt::format("<title>{}</title>\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n",
                    html_escape(plot.title));
    out +=
        fmt::format("<text x=\"{:.1f}\" y=\"18\" font-size=\"13\" font-weight=\"bold\">{}</text>\n",
                    margin_left, html_escape(plot.title));
    return out;
}

std::string region_polygons(const Plot& plot, const Frame& f) {
    std::string out;
    for (const Region& r : plot.regions) {
        std::vector<double> rx, ry;
        for (const auto& p : r.polygon) {
            rx.push_back(p[0]);
            ry.push_back(p[1]);
        }
        out += fmt::format("<polygon points=\"{}\" fill=\"{}\" stroke=\"none\"/>\n",
                           points_attr(rx, ry, f.sx, f.sy), r.fill);
    }
    return out;
}

/// Grid lines with their tick labels, then the frame and the axis labels.
std::string axes(const Plot& plot, const Frame& f) {
    const double w = f.width_px, frame_bottom = f.bottom_px;
    std::string out;
    for (double t : ticks(f.sx)) {
        const double px = f.sx(t);
        out += fmt::format(
            "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" "
            "stroke=\"#dddddd\"/>\n"
            "<text x=\"{0:.1f}\" y=\"{3:.1f}\" text-anchor=\"middle\">{4}</text>\n",
            px, margin_top, frame_bottom, frame_bottom + 14.0, tick_label(t));
    }
    for (double t : ticks(f.sy)) {
        const double py = f.sy(t);
        out += fmt::format(
            "<line x1=\"{1:.1f}\" y1=\"{0:.1f}\" x2=\"{2:.1f}\" y2=\"{0:.1f}\" "
            "stroke=\"#dddddd\"/>\n"
            "<text x=\"{3:.1f}\" y=\"{4:.1f}\" text-anchor=\"end\">{5}</text>\n",
            py, margin_left, w - margin_right, margin_left - 4.0, py + 4.0, tick_label(t));
    }
    out += fmt::format(
        "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"none\" "
        "stroke=\"#333333\"/>\n",
        margin_left, margin_top, w - margin_right - margin_left, frame_bottom - margin_top);
    out += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>\n",
                       (margin_left + w - margin_right) / 2.0, frame_bottom + 32.0,
                       html_escape(plot.x.label));
    out += fmt::format(
        "<text transform=\"translate(16 {:.1f}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n",
        (margin_top + frame_bottom) / 2.0, html_escape(plot.y.label));
    return out;
}

std::string lines_and_markers(const Plot& plot, const Frame& f) {
    std::string out;
    for (const Line& l : plot.lines) {
        out += fmt::format(
            "<polyline points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{:.1f}\"{}/>\n",
            points_attr(l.x, l.y, f.sx, f.sy), l.color, l.width,
            l.dashed ? " stroke-dasharray=\"5 3\"" : "");
        if (l.points) out += vertex_dots(l, f.sx, f.sy);
    }
    for (const Marker& m : plot.markers) {
        if (!f.sx.contains(m.x) || !f.sy.contains(m.y)) continue;
        out += fmt::format(
            "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"4\" fill=\"{}\"/>\n"
            "<text x=\"{:.1f}\" y=\"{:.1f}\">{}</text>\n",
            f.sx(m.x), f.sy(m.y), m.color, f.sx(m.x) + 6.0, f.sy(m.y) - 6.0,
            html_escape(m.label));
    }
    return out;
}

/// One legend row per region, then per labelled line, below the plot area.
std::string legend(const Plot& plot) {
    std::string out;
    double row_y = plot.height_px + 4.0;
    for (const Region& r : plot.regions) {
        out += fmt::format(
            "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"14\" height=\"10\" fill=\"{}\"/>"
            "<text x=\"{:.1f}\" y=\"{:.1f}\">{}</text>\n",
            margin_left, row_y, r.fill, margin_left + 20.0, row_y + 9.0, html_escape(r.label));
        row_y += legend_row_px;
    }
    for (const Line& l : plot.lines) {
        if (l.label.empty()) continue;
        out += fmt::format(
            "<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"{}\" "
            "stroke-width=\"2\"{}/><text x=\"{:.1f}\" y=\"{:.1f}\">{}</text>\n",
            margin_left, row_y + 5.0, margin_left + 14.0, row_y + 5.0, l.color,
            l.dashed ? " stroke-dasharray=\"5 3\"" : "", margin_left + 20.0, row_y + 9.0,
            html_escape(l.label));
        row_y += legend_row_px;
    }
    return out;
}

}  // namespace

std::string render_svg(const Plot& plot) {
    const double w = plot.width_px;
    // Unlabelled lines (interval bars, say) have no legend row.
    const std::size_t legend_rows =
        plot.regions.size() +
        static_cast<std::size_t>(std::count_if(plot.lines.begin(), plot.lines.end(),
                                               [](const Line& l) { return !l.label.empty(); }));
    const double frame_bottom = plot.height_px - margin_bottom;
    const auto [xs, ys] = plotted_values(plot);
    const Frame f{w, plot.height_px + legend_row_px * static_cast<double>(legend_rows),
                  frame_bottom, make_scale(plot.x, xs, margin_left, w - margin_right),
                  make_scale(plot.y, ys, frame_bottom, margin_top)};
    return svg_head(plot, f) + region_polygons(plot, f) + axes(plot, f) +
           lines_and_markers(plot, f) + legend(plot) + "</svg>\n";
}

}  // namespace freestand::report
