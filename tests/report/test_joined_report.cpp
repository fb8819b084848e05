// The reports of two units joined by a tunnel: the pair's section, then each unit's report.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "assess/joined.hpp"
#include "assess/pipeline.hpp"
#include "report/render.hpp"
#include "report/verdict_line.hpp"
#include "core/errors.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_report_test_joined_report {

using namespace freestand;

namespace {

std::string unit(const std::string& name, const std::string& mu) {
    return "[[unit]]\nname = \"" + name +
           "\"\nmass_kg = 400.0\ncg_height_m = 0.5\ncg_to_edge_x_m = [1.0, 1.0]\n"
           "cg_to_edge_y_m = [1.0, 1.0]\nmu_s = " + mu + "\nallowable_slide_m = 5.0\n";
}

}  // namespace

TEST_CASE("joined report: a failing tunnel heads the report with its remedy", "[report][joined]") {
    const assess::Case c = assess::parse_case(
        unit("A", "0.1") + unit("B", "0.3") +
            "[tunnel]\nheight_m = 1.0\nallowable_relative_m = 0.001\n[site]\npga_g = [0.3]\n"
            "[options]\nhistories_per_level = 1\nsimulate = \"always\"\n",
        "pair.toml");
    const assess::AssessmentResult r = assess::assess(c);
    const report::Rendered out = report::render(r, report::Stamp{});
    CHECK(out.markdown.find("# Anchoring assessment: A + B\n\n**Verdict: tunnel fails at PGA "
                            "0.300 g") == 0);
    CHECK(out.markdown.find("brace the units together into one body") != std::string::npos);
    CHECK(out.markdown.find("two rigid planar blocks under the same base motion "
                            "(docs/methods.md s.10)") != std::string::npos);
    CHECK(out.markdown.find("# Anchoring assessment: A\n") != std::string::npos);
    CHECK(out.markdown.find("# Anchoring assessment: B\n") != std::string::npos);
    CHECK(out.html.find("<h1>Anchoring assessment: A</h1>") != std::string::npos);
    CHECK(out.html.find("<h1>Anchoring assessment: B</h1>") != std::string::npos);
    CHECK(out.html.find("</html>") == out.html.rfind("</html>"));  // one document
    for (const auto& f : out.figures)
        CHECK((f.file.rfind("unit1-", 0) == 0 || f.file.rfind("unit2-", 0) == 0));
    const auto j = nlohmann::json::parse(out.json);
    CHECK(j["verdict"].get<std::string>().find("tunnel fails") == 0);
    CHECK(j["pair"]["passes"] == false);
    CHECK(j["pair"]["levels"][0]["relative_demand_m"].get<double>() > 0.001);
    CHECK(j["pair"]["levels"][0]["passes"] == false);
    CHECK(j["units"].size() == 2);
    CHECK(report::verdict_line(r).find("A + B: tunnel fails") == 0);
}


}  // namespace freestand_test_report_test_joined_report
