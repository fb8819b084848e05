// The report and result.json state the gravity the case was assessed with (site.g_mps2).
#include <catch2/catch.hpp>

#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "assess/case.hpp"
#include "assess/pipeline.hpp"
#include "report/json.hpp"
#include "report/render.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_report_test_gravity_echo {

using namespace freestand;

TEST_CASE("a case at standard gravity is reported at standard gravity", "[report][gravity]") {
    const std::string text = R"([component]
name = "Box"
mass_kg = 100.0
cg_height_m = 1.0
cg_to_edge_x_m = [0.4, 0.5]
cg_to_edge_y_m = [0.3, 0.3]
mu_s = 0.3
allowable_slide_m = 0.05
[site]
pga_g = [0.05]
g_mps2 = 9.80665
[options]
simulate = "never"
)";
    const assess::AssessmentResult r =
        assess::assess(assess::parse_case(text, "case.toml"), assess::RunSettings(1));
    const report::Rendered out =
        report::render(r, report::make_stamp(text, "case.toml", 1, "abc123"));
    const auto j = nlohmann::ordered_json::parse(out.json);
    CHECK(j.at("case").at("site").at("g_mps2") == 9.80665);
    std::istringstream lines(out.markdown);
    std::string line, gravity_line;
    while (std::getline(lines, line))
        if (line.find("| gravity |") != std::string::npos) gravity_line = line;
    CHECK(gravity_line.find("9.807") != std::string::npos);
}

}  // namespace freestand_test_report_test_gravity_echo
