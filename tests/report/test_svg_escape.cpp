// Figure text is case text: the SVG escapes it as the HTML report does (report/escape.hpp).
#include <catch2/catch.hpp>

#include <string>

#include "report/svg.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_report_test_svg_escape {

using namespace freestand::report;

TEST_CASE("figure titles and labels show control and reordering characters escaped", "[report][svg][escape]") {
    Plot p;
    p.title = "pump\x1b[31m <A&B>";
    p.x = Axis{"f \xE2\x80\xAEHz", false, std::nullopt, std::nullopt};
    p.y = Axis{"y", false, std::nullopt, std::nullopt};
    p.lines.push_back(Line{"l", {0.0, 1.0}, {1.0, 1.0}, "#000000", 1.5, false, false});
    const std::string svg = render_svg(p);
    CHECK(svg.find("pump\\x1B[31m &lt;A&amp;B&gt;") != std::string::npos);
    CHECK(svg.find('\x1b') == std::string::npos);
    CHECK(svg.find("f \\u202EHz") != std::string::npos);
    CHECK(svg.find("\xE2\x80\xAE") == std::string::npos);
}

}  // namespace freestand_test_report_test_svg_escape
