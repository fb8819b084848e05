// Limit messages and the PGA levels every entry point checks (core/limits.hpp, README Limits).
#include <catch2/catch.hpp>

#include <limits>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/limits.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_core_test_limit_messages {

using namespace freestand;
namespace limits = core::limits;

namespace {

const SourceLocation where{"", 0, "x"};

std::string above_message(double needed, double limit) {
    try {
        limits::require_within(needed, limit, where, "what");
    } catch (const InputError& e) {
        return e.message();
    }
    return "no error";
}

std::string below_message(double given, double limit) {
    try {
        limits::require_at_least(given, limit, where, "what");
    } catch (const InputError& e) {
        return e.message();
    }
    return "no error";
}

std::string levels_message(const std::vector<double>& pga_g) {
    try {
        limits::require_pga_levels(pga_g, SourceLocation{"case.toml", 4, "site.pga_g"});
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace

TEST_CASE("a value just beyond a limit never reads as the limit itself", "[core][limits]") {
    // At 4 significant digits 3.0001 reads "3 is above the limit 3" and 100001 "1e+05 is above
    // the limit 1e+05": as many digits as tell the two apart.
    CHECK(above_message(3.0001, 3.0) ==
          "what: 3.0001 is above the limit 3 (README, Limits)");
    CHECK(above_message(100001.0, 1e5) ==
          "what: 100001 is above the limit 100000 (README, Limits)");
    CHECK(above_message(1.0 + 1e-15, 1.0) ==
          "what: 1.000000000000001 is above the limit 1 (README, Limits)");
    CHECK(below_message(0.00099999, 1e-3) ==
          "what: 0.00099999 is below the limit 0.001 (README, Limits)");
    // Values far apart keep their 4-digit text.
    CHECK(above_message(8e11, 1e7) == "what: 8e+11 is above the limit 1e+07 (README, Limits)");
    CHECK(below_message(1e-300, 1e-3) ==
          "what: 1e-300 is below the limit 0.001 (README, Limits)");
    CHECK(above_message(3.0, 3.0) == "no error");
}

TEST_CASE("PGA levels: 1 to 1000 of them, each in [0.001, 3] g, strictly increasing",
          "[core][limits]") {
    CHECK(levels_message({0.001, 0.1, 3.0}) == "no error");
    CHECK(levels_message({}) == "case.toml:4: site.pga_g: expected at least one PGA level");
    // A denormal level and one of 1e-300 g are not assessments (a 300-digit margin, and a
    // value the results' rounding cannot read back).
    CHECK(levels_message({1e-310, 0.1}) ==
          "case.toml:4: site.pga_g: value 1e-310 is out of range; expected [0.001, 3]");
    CHECK(levels_message({1e-300}) ==
          "case.toml:4: site.pga_g: value 1e-300 is out of range; expected [0.001, 3]");
    CHECK(levels_message({0.0}) ==
          "case.toml:4: site.pga_g: value 0 is out of range; expected [0.001, 3]");
    CHECK(levels_message({3.0001}) ==
          "case.toml:4: site.pga_g: value 3.0001 is out of range; expected [0.001, 3]");
    CHECK(levels_message({0.2, 0.1}) ==
          "case.toml:4: site.pga_g: levels must be strictly increasing; 0.1 follows 0.2");
    std::vector<double> many(1001);
    for (std::size_t i = 0; i < many.size(); ++i) many[i] = 0.001 * static_cast<double>(i + 1);
    CHECK(levels_message(many) ==
          "case.toml:4: site.pga_g: PGA levels: 1001 is above the limit 1000 (README, Limits)");
    many.pop_back();
    CHECK(levels_message(many) == "no error");
}

TEST_CASE("one range table: a case's friction and restitution are the command line's",
          "[core][limits]") {
    CHECK(limits::within(2.0, limits::friction));
    CHECK_FALSE(limits::within(2.0000001, limits::friction));
    CHECK_FALSE(limits::within(1e300, limits::friction));
    CHECK_FALSE(limits::within(-0.1, limits::friction));
    CHECK(limits::within(0.0, limits::restitution));
    CHECK_FALSE(limits::within(1.5, limits::restitution));
    CHECK_FALSE(limits::within(std::numeric_limits<double>::quiet_NaN(), limits::friction));
    CHECK(limits::describe(limits::friction) == "[0, 2]");
    CHECK(limits::describe(limits::mass_kg) == "[0.001, 100000000]");
}

}  // namespace freestand_test_core_test_limit_messages
