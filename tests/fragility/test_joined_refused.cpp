// A two-unit case ([[unit]] x 2, [tunnel]) has no fragility analysis: refused, naming the tables.
#include <catch2/catch.hpp>

#include "assess/case.hpp"
#include "core/errors.hpp"
#include "fragility/fragility.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_fragility_test_joined_refused {

using namespace freestand;

TEST_CASE("fragility refuses two joined units", "[fragility][joined][errors]") {
    std::string unit = "[[unit]]\nname = \"U\"\nmass_kg = 400.0\ncg_height_m = 0.5\n"
                       "cg_to_edge_x_m = [1.0, 1.0]\ncg_to_edge_y_m = [1.0, 1.0]\nmu_s = 0.2\n"
                       "allowable_slide_m = 0.05\n";
    const assess::Case c = assess::parse_case(
        unit + unit + "[tunnel]\nheight_m = 1.0\nallowable_relative_m = 0.02\n[site]\n"
                      "pga_g = [0.3]\n",
        "pair.toml");
    fragility::Config config;
    config.pga_g = {0.3};
    CHECK_THROWS_MATCHES(fragility::run_all(c, config, assess::RunSettings(1)), InputError,
                         Catch::Matchers::Message("pair.toml: unit: the fragility analysis takes "
                                                  "one component, not two [[unit]] tables"));
}

}  // namespace freestand_test_fragility_test_joined_refused
