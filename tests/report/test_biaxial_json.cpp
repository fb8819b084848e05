// result.json's biaxial object per level (docs/methods.md s.10): statistics, ratio to the planar
// peak and the reason; null where the level was not simulated, slide_m null where the model did not
// apply.
#include <catch2/catch.hpp>
#include <filesystem>

#include "support/paths.hpp"
#include "assess/pipeline.hpp"
#include "report/json.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_report_test_biaxial_json {

namespace fs = std::filesystem;
using namespace freestand;
using namespace freestand::assess;

namespace {

nlohmann::ordered_json levels_json(const char* name, double pga_g) {
    Case c = read_case(fs::path(freestand::test::source_dir()) / "cases" / name);
    c.options.histories_per_level = 1;
    c.options.max_histories_per_level = c.options.histories_per_level;
    // Without the flexible-body inputs no flag is raised: the biaxial model alone decides.
    c.component.fixed_base_frequency_hz.reset();
    c.component.x.free_rocking_band_hz.reset();
    c.component.y.free_rocking_band_hz.reset();
    const AssessmentResult r = assess::assess(with_pga_levels(c, {pga_g}));
    return report::to_json(r, report::make_stamp("case", "case.toml", 1, "abc")).at("levels");
}

}  // namespace

TEST_CASE("result.json: a biaxial level carries its statistics, ratio and reason",
          "[report][json][biaxial]") {
    const auto levels = levels_json("glovebox-single.toml", 0.2);
    const auto& b = levels.at(0).at("biaxial");
    CHECK(b.at("ran") == true);
    const double max_m = b.at("slide_m").at("max").get<double>();
    const double planar_m = b.at("planar_governing_m").get<double>();
    CHECK(max_m > 0.0);
    CHECK(b.at("ratio_to_planar").get<double>() == Approx(max_m / planar_m).epsilon(1e-9));
    CHECK(b.at("reason").get<std::string>().find("slides without rocking") != std::string::npos);
    CHECK(levels.at(0).at("verdict").at("decided_by") ==
          to_string(Model::simulation_biaxial_slide));
    // The planar statistics stay beside it.
    CHECK(levels.at(0).at("simulation").at("slide_m").at("max").get<double>() <= planar_m);
}

TEST_CASE("result.json: biaxial is null unsimulated and empty where the block rocks",
          "[report][json][biaxial]") {
    CHECK(levels_json("glovebox-single.toml", 0.05).at(0).at("biaxial").is_null());
    const auto levels = levels_json("block-ts1.toml", 0.3);
    const auto& b = levels.at(0).at("biaxial");
    CHECK(b.at("ran") == false);
    CHECK(b.at("slide_m").is_null());
    CHECK(b.at("ratio_to_planar").is_null());
    CHECK(b.at("reason").get<std::string>().find("mode rock") != std::string::npos);
}

}  // namespace freestand_test_report_test_biaxial_json
