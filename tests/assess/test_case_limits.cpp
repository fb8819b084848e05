// A case's PGA levels, friction, restitution and mass: the ranges and counts of
// core/limits.hpp, the same as the command line's (README, Limits).
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <string>

#include "support/case_text.hpp"
#include "assess/case.hpp"
#include "core/errors.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_assess_test_case_limits {

using namespace freestand;
using namespace freestand::assess;

namespace {

// A valid case whose [site] pga_g is levels (lines 9-10: [site], pga_g).
std::string with_levels(const std::string& levels) {
    return test::box_component + "[site]\npga_g = " + levels + "\n";
}

// n levels 0.001, 0.002, ... g as a TOML array, 100 to a line (a case line holds at most 4096
// characters).
std::string levels_text(int n) {
    std::string out = "[";
    for (int i = 1; i <= n; ++i)
        out += fmt::format("{}{:.3f}", i == 1 ? "" : i % 100 == 1 ? ",\n" : ", ", 0.001 * i);
    return out + "]";
}

}  // namespace

TEST_CASE("a PGA level near zero is refused at its key", "[assess][case][limits]") {
    // The static margin grows as 1 / PGA: a 300-digit number at 1e-300 g.
    CHECK(test::case_error(with_levels("[1e-310, 0.1]")) ==
          "case.toml:10: site.pga_g: value 1e-310 is out of range; expected [0.001, 3]");
    CHECK(test::case_error(with_levels("[1e-300, 0.1]")) ==
          "case.toml:10: site.pga_g: value 1e-300 is out of range; expected [0.001, 3]");
    CHECK(test::case_error(with_levels("[0.0009, 0.1]")) ==
          "case.toml:10: site.pga_g: value 0.0009 is out of range; expected [0.001, 3]");
    CHECK(test::case_error(with_levels("[0.001, 0.1]")) == "no error");
    const std::string dbe = with_levels("[0.1]") + "dbe_pga_g = 1e-300\n";
    CHECK(test::case_error(dbe) ==
          "case.toml:11: site.dbe_pga_g: value 1e-300 is out of range; expected [0.001, 3]");
}

TEST_CASE("a case holds at most 1000 PGA levels, checked as it is read",
          "[assess][case][limits]") {
    // Each level costs about 70 KB of results: 1e5 levels exhaust the memory.
    CHECK(test::case_error(with_levels(levels_text(1001))) ==
          "case.toml:10: site.pga_g: PGA levels: 1001 is above the limit 1000 (README, Limits)");
    // Up to 1 g: a level of 1 g at RG 1.60's vertical ratio of 1 is weightless.
    const std::string thousand = with_levels(levels_text(1000)) + "vertical_ratio = 0.5\n";
    CHECK(parse_case(thousand, "case.toml").site.pga_g.size() == 1000);
}

TEST_CASE("a case's fragility run is bounded as levels x samples", "[assess][case][limits]") {
    const std::string o = with_levels("[0.1]") + "[options]\nfragility = true\n";
    CHECK(test::case_error(o + "fragility_pga_g = " + levels_text(11) +
                           "\nfragility_samples = 100000\n") ==
          "case.toml:14: options.fragility_samples: the fragility run's samples (levels x "
          "fragility_samples): 1.1e+06 is above the limit 1e+06 (README, Limits)");
    CHECK(test::case_error(o + "fragility_pga_g = " + levels_text(10) +
                           "\nfragility_samples = 100000\n") == "no error");
}

TEST_CASE("a case's mass is a block's mass: 1 g to 100,000 t", "[assess][case][limits]") {
    const auto with_mass = [](const std::string& mass) {
        std::string text = test::box_component + test::box_site;
        text.replace(text.find("mass_kg = 100.0"), 15, "mass_kg = " + mass);
        return text;
    };
    CHECK(test::case_error(with_mass("5e7")) == "no error");
    CHECK(test::case_error(with_mass("1e-4")) ==
          "case.toml:3: component.mass_kg: value 0.0001 is out of range; expected [0.001, "
          "100000000]");
}

TEST_CASE("a drawn friction stays within a case's friction range", "[assess][case][limits]") {
    // The model takes a case's friction range (core::limits::friction, [0, 2]): a drawn value
    // beyond it would stop a fragility run in its middle.
    const std::string u = test::box_component + test::box_site + "[uncertainty]\n";
    CHECK(test::case_error(u + "mu_s = { dist = \"uniform\", lo = 0.5, hi = 3 }\n") ==
          "case.toml:12: uncertainty.mu_s.hi: value 3 is out of range; expected [0, 2]");
    const Case c =
        parse_case(u + "mu_s = { dist = \"lognormal\", median = 0.5, beta = 1 }\n", "case.toml");
    REQUIRE(c.uncertainty.mu_s.has_value());
    CHECK(c.uncertainty.mu_s->upper == 2.0);
}

}  // namespace freestand_test_assess_test_case_limits
