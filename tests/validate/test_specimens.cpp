// The rigid specimens TS1-TS3: geometry from Table 3-2, hand-checkable sine runs and the
// Ishiyama bound against its formula (docs/methods.md s.13).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rocking/checks.hpp"
#include "validate/specimens.hpp"
#include "validate/thesis.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_validate_test_specimens {

using namespace freestand;
using namespace freestand::validate;

namespace {
constexpr double kGeomRelTol = 1e-12;
const Specimen& ts(int i) { return specimens().at(static_cast<std::size_t>(i - 1)); }
}  // namespace

TEST_CASE("specimen blocks have exactly Table 3-2's alpha, R, M and p", "[validate]") {
    REQUIRE(specimens().size() == 3);
    for (const Specimen& s : specimens()) {
        INFO(s.name);
        const block::Block b = specimen_block(s);
        CHECK(b.alpha_rad(block::Edge::right) == Approx(s.alpha_rad).epsilon(kGeomRelTol));
        CHECK(b.R_m(block::Edge::right) == Approx(s.R_m).epsilon(kGeomRelTol));
        CHECK(b.mass_kg == s.mass_kg);
        // p is the table's frequency parameter, with g = 9.81 m/s^2 (docs/methods.md s.1).
        CHECK(b.p_radps(block::Edge::right) == Approx(s.p_radps).epsilon(1e-9));
        CHECK(b.symmetric());
    }
    // Table 3-2's C.G. column (0.15, 0.6) for TS1 agrees with R sin(alpha), R cos(alpha) to 1%.
    const block::Block b1 = specimen_block(ts(1));
    CHECK(b1.b_right_m == Approx(0.15).epsilon(0.01));
    CHECK(b1.h_m == Approx(0.60).epsilon(0.01));
}

TEST_CASE("a specimen that cannot uplift stays still at any frequency", "[validate]") {
    // TS3: tan(alpha) = tan(0.463) = 0.4992; 0.45 g is below it and below mu 0.72 (rest,
    // docs/methods.md s.2), so the rigid block neither rocks nor slides.
    const Specimen& s = ts(3);
    for (double f : {2.0, 10.0}) {
        const auto r = sine_run(specimen_model(s, 0.98), 0.45, f);
        CHECK_FALSE(r.overturned);
        CHECK(r.rock_max_rad == 0.0);
        CHECK(r.slide_max_m == 0.0);
    }
}

TEST_CASE("a 0.8 g sine overturns TS1 at 0.5 Hz without impact and not at 10 Hz",
          "[validate]") {
    // 0.8 g > tan(alpha) = 0.25: uplift at once. At 0.5 Hz the first half-cycle (1 s at
    // >= 0.25 g for 0.84 s) throws the block over (mode 2); at 10 Hz each pulse is too short.
    const auto slow = sine_run(specimen_model(ts(1), 0.98), 0.8, 0.5);
    CHECK(slow.overturned);
    REQUIRE(slow.overturn_mode);
    CHECK(*slow.overturn_mode == 2);
    REQUIRE(slow.overturn_time_s);
    CHECK(*slow.overturn_time_s < 1.0);
    const auto fast = sine_run(specimen_model(ts(1), 0.98), 0.8, 10.0);
    CHECK_FALSE(fast.overturned);
    CHECK(fast.rock_max_rad > 0.0);
    CHECK(fast.rock_max_over_alpha < 0.1);
}

TEST_CASE("Ishiyama's bound of the specimens against Eq. 3.41 by hand", "[validate]") {
    for (const Specimen& s : specimens()) {
        INFO(s.name);
        const double c = std::cos(s.alpha_rad);
        const double by_hand = 0.4 * std::sqrt(8.0 * 9.81 * s.R_m * (1.0 - c) / (3.0 * c));
        CHECK(rocking::ishiyama_velocity_mps(specimen_block(s), block::Edge::right) ==
              Approx(by_hand).epsilon(1e-12));
    }
    // TS1: 0.4 sqrt(8 9.81 0.62 (1 - cos 0.245) / (3 cos 0.245)) = 0.2826 m/s; the thesis
    // prints 0.283. TS3: 0.4092 m/s against the thesis's 0.499 (its slip).
    CHECK(rocking::ishiyama_velocity_mps(specimen_block(ts(1)), block::Edge::right) ==
          Approx(0.2826).margin(5e-5));
    CHECK(rocking::ishiyama_velocity_mps(specimen_block(ts(3)), block::Edge::right) ==
          Approx(0.4092).margin(5e-5));
}

TEST_CASE("the thesis's overturning observations", "[validate]") {
    for (const Specimen& s : specimens()) {
        CHECK(thesis_overturned(s, 0.5));
        CHECK(thesis_overturned(s, 1.0));
        CHECK_FALSE(thesis_overturned(s, 3.0));
    }
    CHECK(thesis_overturned(ts(1), 2.0));
    CHECK(thesis_overturned(ts(2), 2.0));
    CHECK_FALSE(thesis_overturned(ts(3), 2.0));
}

TEST_CASE("the stroke rule: a sine runs when A g / (2 pi f)^2 is at most the table's 75 mm",
          "[validate][stroke]") {
    REQUIRE(table_stroke_m() == 0.075);
    CHECK(within_stroke(0.075));
    CHECK_FALSE(within_stroke(std::nextafter(0.075, 1.0)));
    CHECK(within_stroke(0.0749));
    CHECK_FALSE(within_stroke(0.0751));
    // 0.3 g at 1 Hz: 0.3 x 9.81 / (2 pi)^2 = 0.074547 m, just inside; 0.33 g: 0.082 m, outside.
    CHECK(sine_travel_m(0.3, 1.0) ==
          Approx(0.3 * 9.81 / (4.0 * std::numbers::pi * std::numbers::pi)).epsilon(1e-14));
    CHECK(sine_travel_m(0.3, 1.0) == Approx(0.074547).margin(1e-6));
    CHECK(table_can_play(0.3, 1.0));
    CHECK_FALSE(table_can_play(0.33, 1.0));
    // Around the amplitude whose travel is the stroke exactly, at 2 Hz.
    const double at_stroke_g = 0.075 * (4.0 * std::numbers::pi) * (4.0 * std::numbers::pi) / 9.81;
    CHECK(table_can_play(at_stroke_g * (1.0 - 1e-9), 2.0));
    CHECK_FALSE(table_can_play(at_stroke_g * (1.0 + 1e-9), 2.0));
    // 0.8 g (Table 3-5): 0.5 and 1 Hz beyond the stroke, 2 Hz (0.050 m) within.
    CHECK_FALSE(table_can_play(0.8, 0.5));
    CHECK_FALSE(table_can_play(0.8, 1.0));
    CHECK(table_can_play(0.8, 2.0));
}

TEST_CASE("the stroke rule marks a row not runnable, keeps its comparison and says why",
          "[validate][stroke]") {
    Row row;
    row.agreement = Agreement::agrees;
    row.difference = "same outcome";
    row.reason = "Earlier reason.";
    row.sources = {"ts.sine_g"};
    apply_stroke_rule(row, 0.8, 2.0);  // 0.050 m: runnable, untouched
    CHECK(row.agreement == Agreement::agrees);
    CHECK(row.reason == "Earlier reason.");
    CHECK(row.sources == std::vector<std::string>{"ts.sine_g"});
    apply_stroke_rule(row, 0.8, 1.0);  // 0.199 m
    CHECK(row.agreement == Agreement::not_runnable);
    CHECK(row.difference == "same outcome");
    CHECK(row.reason ==
          "Not runnable on the thesis's table: a 0.8 g sine at 1 Hz needs +-0.199 m of table "
          "travel (A g / (2 pi f)^2); the table has +-0.075 m (Table 3-1), so the test cannot "
          "have been this input (see the notes). Shown, not counted. Earlier reason.");
    CHECK(row.sources == std::vector<std::string>{"ts.sine_g", "ts.stroke_m"});
    apply_stroke_rule(row, 0.8, 0.5);  // the stroke's source is cited once
    CHECK(std::count(row.sources.begin(), row.sources.end(), "ts.stroke_m") == 1);
}

TEST_CASE("Table 3-4: six runs, X_s and just below, 11 frequencies", "[validate]") {
    const auto& runs = rest_runs();
    REQUIRE(runs.size() == 6);
    const double amplitudes_g[] = {0.25, 0.2, 0.33, 0.3, 0.5, 0.45};
    const char* names[] = {"TS1", "TS1", "TS2", "TS2", "TS3", "TS3"};
    for (std::size_t i = 0; i < runs.size(); ++i) {
        INFO("run " << i + 1);
        CHECK(runs[i].number == static_cast<int>(i) + 1);
        CHECK(runs[i].amplitude_g == amplitudes_g[i]);
        CHECK(runs[i].specimen.name == names[i]);
        CHECK(value(runs[i].key) == amplitudes_g[i]);
    }
    CHECK(rest_frequencies_hz() == std::vector<double>{0.5, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
}

}  // namespace freestand_test_validate_test_specimens
