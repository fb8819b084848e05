// The report and result.json state the gravity the case was assessed with (site.g_mps2).
#include <catch2/catch.hpp>

#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "assess/case.hpp"
#include "assess/pipeline.hpp"
#include "report/json.hpp"
#include "report/render.hpp"
#include "support/case_text.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_report_test_gravity_echo {

using namespace freestand;

TEST_CASE("a case at standard gravity is reported at standard gravity", "[report][gravity]") {
    const std::string text = test::box_component +
                             "[site]\npga_g = [0.05]\ng_mps2 = 9.80665\n"
                             "[options]\nsimulate = \"never\"\n";
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
