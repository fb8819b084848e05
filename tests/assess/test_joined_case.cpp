// Two units joined by a tunnel in a case file: [[unit]] x 2 and [tunnel] (docs/methods.md s.10).
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "support/paths.hpp"
#include "assess/case.hpp"
#include "core/errors.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_assess_test_joined_case {

namespace fs = std::filesystem;
using namespace freestand;
using namespace freestand::assess;

namespace {

std::string unit(const std::string& name, const std::string& extra = "") {
    return "[[unit]]\nname = \"" + name +
           "\"\nmass_kg = 400.0\ncg_height_m = 1.0\ncg_to_edge_x_m = [0.5, 0.5]\n"
           "cg_to_edge_y_m = [0.5, 0.5]\nmu_s = 0.15\nallowable_slide_m = 0.05\n" +
           extra;
}
const std::string tunnel = "[tunnel]\nheight_m = 1.5\nallowable_relative_m = 0.025\n";
const std::string site = "[site]\npga_g = [0.1, 0.2]\n";

std::string error_of(const std::string& text) {
    try {
        parse_case(text, "pair.toml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace

TEST_CASE("joined case: two units and a tunnel", "[assess][case][joined]") {
    const Case c = parse_case(unit("A") + unit("B") + tunnel + site,
                              "pair.toml");
    REQUIRE(c.units.size() == 2);
    CHECK(c.units[0].name == "A");
    CHECK(c.units[1].name == "B");
    CHECK(c.units[0].mass_kg == 400.0);
    REQUIRE(c.tunnel);
    CHECK(c.tunnel->height_m == 1.5);
    CHECK(c.tunnel->allowable_relative_m == 0.025);
    CHECK(c.component.name.empty());
}

TEST_CASE("joined case: the shipped unbraced pair parses", "[assess][case][joined]") {
    const Case c = read_case(fs::path(freestand::test::source_dir()) / "cases" /
                             "glovebox-pair-unbraced.toml");
    REQUIRE(c.units.size() == 2);
    CHECK(c.units[0].mass_kg == 466.0);
    CHECK(c.units[1].mass_kg == 620.0);
    CHECK(c.units[0].y.b_left_m == 0.397);
    CHECK(c.tunnel->allowable_relative_m == 0.025);
    CHECK(c.site.pga_g == std::vector<double>{0.1, 0.2, 0.3, 0.4});
}

TEST_CASE("joined case: errors name file:line and key", "[assess][case][joined][errors]") {
    CHECK(error_of(unit("A") + tunnel + site) ==
          "pair.toml:1: unit: expected exactly two [[unit]] tables, got 1");
    CHECK(error_of(unit("A") + unit("B") + unit("C") + tunnel + site) ==
          "pair.toml:17: unit: expected exactly two [[unit]] tables, got 3");
    CHECK(error_of("[component]\nname = \"X\"\n" + unit("A") + unit("B") + tunnel + site) ==
          "pair.toml:1: component: [component] and [[unit]] are exclusive: describe one "
          "component, or two units joined by a [tunnel]");
    CHECK(error_of(unit("A") + unit("B") + site) ==
          "pair.toml: tunnel: missing required table [tunnel] (height_m, allowable_relative_m) "
          "for the two [[unit]] tables");
    CHECK(error_of(unit("A") + unit("B") + "[tunnel]\nheight_m = 1.5\n" + site) ==
          "pair.toml:17: tunnel.allowable_relative_m: missing required key (a number in (0, 10])");
    CHECK(error_of(unit("A") + unit("B") + tunnel + "slack_m = 0.1\n" + site) ==
          "pair.toml:20: tunnel.slack_m: unknown key; allowed keys: height_m, allowable_relative_m");
    CHECK(error_of(unit("A") + unit("B") + "[tunnel]\nheight_m = -1\nallowable_relative_m = 0.02\n" +
                   site) ==
          "pair.toml:18: tunnel.height_m: value -1 is out of range; expected [0, 100]");
    CHECK(error_of(unit("A") + unit("B", "allowable_relative_m = 0.02\n") + tunnel + site) ==
          "pair.toml:17: unit[2].allowable_relative_m: give the relative allowable once, in "
          "[tunnel]");
    CHECK(error_of(unit("A") + unit("B", "mass_kg_typo = 1\n") + tunnel + site)
              .find("pair.toml:17: unit[2].mass_kg_typo: unknown key") == 0);
    CHECK(error_of(unit("A") + "[[unit]]\nname = \"B\"\n" + tunnel + site)
              .find("unit[2].mass_kg: missing required key") != std::string::npos);
    CHECK(error_of("unit = 3\n" + tunnel + site) ==
          "pair.toml:1: unit: expected [[unit]] tables (an array of tables)");
    CHECK(error_of("[component]\nname = \"X\"\n" + tunnel + site) ==
          "pair.toml:3: tunnel: [tunnel] joins two [[unit]] tables; a [component] has none (a "
          "braced pair is one component: give allowable_relative_m there)");
}

TEST_CASE("joined case: neither [component] nor [[unit]] names both", "[assess][case][joined][errors]") {
    CHECK(error_of(site) ==
          "pair.toml: component: missing required table [component] (or two [[unit]] and a "
          "[tunnel])");
}

TEST_CASE("joined case: a DBE is refused at its line (the goal takes one component)",
          "[assess][case][joined][goal]") {
    CHECK(error_of(unit("A") + unit("B") + tunnel + site + "dbe_pga_g = 0.2\n") ==
          "pair.toml:22: site.dbe_pga_g: the performance goal runs the fragility engine, which "
          "takes one component, not two [[unit]] tables");
}

}  // namespace freestand_test_assess_test_joined_case
