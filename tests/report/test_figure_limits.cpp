// Figures and result numbers at the ends of the double range: a bounded number of axis ticks
// for any data, and result.json's 10-digit rounding for denormal and near-overflow values.
#include <catch2/catch.hpp>

#include <limits>
#include <string>

#include "report/json.hpp"
#include "report/svg.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_report_test_figure_limits {

using namespace freestand::report;

namespace {

// Grid lines drawn: one per tick on either axis.
std::size_t grid_lines(const std::string& svg) {
    std::size_t n = 0;
    for (std::size_t at = svg.find("#dddddd"); at != std::string::npos;
         at = svg.find("#dddddd", at + 1))
        ++n;
    return n;
}

Plot plot_of(bool log_x, std::vector<double> x) {
    Plot p;
    p.title = "t";
    p.x = Axis{"x", log_x, std::nullopt, std::nullopt};
    p.y = Axis{"y", false, std::nullopt, std::nullopt};
    const std::vector<double> y(x.size(), 1.0);
    p.lines.push_back(Line{"l", std::move(x), y, "#000000", 1.5, false, false});
    return p;
}

}  // namespace

TEST_CASE("an axis has a bounded number of ticks whatever its range", "[report][svg][limits]") {
    // A log axis from a denormal to 1 spans over 300 decades, and from 5e-324 the decade rounds
    // to 0, which ten times itself never leaves.
    CHECK(grid_lines(render_svg(plot_of(true, {1e-310, 1.0}))) <= 24);
    CHECK(grid_lines(render_svg(plot_of(true, {1e-300, 1e300}))) <= 24);
    CHECK(grid_lines(render_svg(plot_of(true, {5e-324, 1.0}))) <= 24);
    // A linear axis whose span is below its values' rounding.
    CHECK(grid_lines(render_svg(plot_of(false, {1e16, 1e16 + 2.0}))) <= 24);
    // An ordinary axis keeps one tick per decade (0.1 to 100 Hz), and y 0 to 2 by 0.5.
    CHECK(grid_lines(render_svg(plot_of(true, {0.1, 100.0}))) == 4 + 5);
}

TEST_CASE("result numbers next to the ends of the double range are kept, not an exception",
          "[report][json][limits]") {
    // The 10-digit text of a denormal or of the largest double is out of range for std::stod
    // (out_of_range: an internal error, an IndexError in Python); the value is kept instead.
    CHECK(round10(1.5e-310) == 1.5e-310);
    const double largest = std::numeric_limits<double>::max();
    CHECK(round10(largest) == largest);
    CHECK(json_number(-largest).get<double>() == -largest);
    CHECK(round10(0.1234567890123) == 0.123456789);
}

}  // namespace freestand_test_report_test_figure_limits
