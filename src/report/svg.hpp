#pragma once
/// A small, dependency-free SVG line-plot writer for the reports: linear or log axes, lines,
/// filled regions and labelled markers. Output is deterministic (fixed-precision coordinates)
/// and self-contained (no fonts or scripts fetched). Hand-written because the C++ plotting
/// libraries available drive gnuplot or a GUI; a report needs a static file.
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace freestand::report {

struct Axis {
    std::string label;
    bool log = false;
    std::optional<double> min;  ///< default: data range (log: whole decades)
    std::optional<double> max;
};

struct Line {
    std::string label;  ///< legend text; "" draws no legend row
    std::vector<double> x;
    std::vector<double> y;
    std::string color = "#1f77b4";
    double width = 1.5;
    bool dashed = false;
    bool points = false;  ///< also a dot at each vertex, so a single point stays visible
};

/// A filled polygon in data coordinates, drawn under the lines.
struct Region {
    std::string label;
    std::vector<std::array<double, 2>> polygon;
    std::string fill;
};

struct Marker {
    std::string label;  ///< drawn beside the point
    double x = 0.0;
    double y = 0.0;
    std::string color = "#000000";
};

struct Plot {
    std::string title;
    Axis x;
    Axis y;
    std::vector<Region> regions;
    std::vector<Line> lines;
    std::vector<Marker> markers;
    int width_px = 720;
    int height_px = 380;
};

/// The plot as a standalone <svg> element (with the xmlns attribute, so it is also a valid
/// .svg file). Non-finite points and points outside a log axis's range are skipped.
std::string render_svg(const Plot& plot);

}  // namespace freestand::report
