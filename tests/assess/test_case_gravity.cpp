// A case's gravity, site.g_mps2 (docs/methods.md, Conventions): read in Earth's surface range,
// and the one value of the case's physics and of its unit g, in every closed form it assesses.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "assess/case.hpp"
#include "assess/pipeline.hpp"
#include "core/errors.hpp"
#include "support/case_text.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_assess_test_case_gravity {

using namespace freestand;
using namespace freestand::assess;

namespace {

// Standard gravity (CGPM 1901), exactly; the thesis's 9.81 is the default.
constexpr double standard_g_mps2 = 9.80665;
constexpr double pi = 3.141592653589793;
// Closed forms against the code: the same operations in another order.
constexpr double kRel = 1e-12;

// A wide box that slides at 0.3 g without rocking (tan alpha = 1 > A = 0.3 / 0.85), assessed by
// the closed forms only, its energy estimate from a table displacement of 0.04 m.
std::string sliding_box(double g_mps2) {
    return fmt::format(R"([component]
name = "Wide box"
mass_kg = 100.0
cg_height_m = 0.5
cg_to_edge_x_m = [0.5, 0.5]
cg_to_edge_y_m = [0.5, 0.5]
mu_s = 0.2
allowable_slide_m = 0.05
[site]
pga_g = [0.3]
vertical_ratio = 0.5
energy_table_displacement_m = [0.04]
g_mps2 = {}
[options]
simulate = "never"
)",
                       g_mps2);
}

AssessmentResult assess_box(double g_mps2) {
    return assess::assess(parse_case(sliding_box(g_mps2), "case.toml"), RunSettings(1));
}

std::string with_gravity(const std::string& value) {
    return test::box_component + test::box_site + "g_mps2 = " + value + "\n";
}

}  // namespace

TEST_CASE("site.g_mps2 accepts Earth's surface gravity only, 9.81 when absent",
          "[assess][case][gravity]") {
    CHECK(parse_case(test::box_component + test::box_site, "case.toml").site.g_mps2 == 9.81);
    CHECK(parse_case(with_gravity("9.80665"), "case.toml").site.g_mps2 == standard_g_mps2);
    CHECK(parse_case(with_gravity("9.78"), "case.toml").site.g_mps2 == 9.78);
    CHECK(parse_case(with_gravity("9.84"), "case.toml").site.g_mps2 == 9.84);
    CHECK(test::case_error(with_gravity("9.7")) ==
          "case.toml:11: site.g_mps2: value 9.7 is out of range; expected [9.78, 9.84]");
    CHECK(test::case_error(with_gravity("32.2")) ==
          "case.toml:11: site.g_mps2: value 32.2 is out of range; expected [9.78, 9.84]");
    CHECK(test::case_error(with_gravity("9.8401")) ==
          "case.toml:11: site.g_mps2: value 9.8401 is out of range; expected [9.78, 9.84]");
}

TEST_CASE("a given p_radps becomes inertia with the case's gravity", "[assess][case][gravity]") {
    // Direction x of the box: R = sqrt(0.4^2 + 1^2) about the critical (narrower) edge;
    // I_O = M g R / p^2 and I_c = I_O - M R^2 (docs/methods.md s.1).
    const std::string text =
        test::box_component + "p_radps = 2.0\n" + test::box_site + "g_mps2 = 9.80665\n";
    const Case c = parse_case(text, "case.toml");
    const double R2 = 0.4 * 0.4 + 1.0;
    const double i_c = 100.0 * standard_g_mps2 * std::sqrt(R2) / 4.0 - 100.0 * R2;
    CHECK(c.component.x.inertia_cg_kgm2 == Approx(i_c).epsilon(kRel));
    // p < sqrt(g / R): 3.0175 rad/s with standard gravity (3.0180 with 9.81).
    const std::string too_fast =
        test::box_component + "p_radps = [3.0178, 3.0]\n" + test::box_site + "g_mps2 = 9.80665\n";
    CHECK(test::case_error(too_fast) ==
          "case.toml:9: component.p_radps: p_x = 3.0178 rad/s is out of range; expected (0, "
          "3.0175) (p < sqrt(g / R) of direction x's critical edge)");
}

TEST_CASE("at standard gravity the ASCE 4 sliding and the rocking checks use 9.80665",
          "[assess][gravity]") {
    const AssessmentResult r = assess_box(standard_g_mps2);
    const LevelResult& x = r.levels.at(0);
    REQUIRE(x.initiation_lower.mode == Mode::slide);
    // Lower friction bound 0.8 x 0.2; A_v = 0.5 x 0.3 g: mu_e = mu (1 - 0.4 A_v / g) (ASCE 4).
    const double mu_e = 0.16 * (1.0 - 0.4 * 0.15);
    const double c_s_mps2 = 2.0 * mu_e * standard_g_mps2;
    CHECK(x.sliding.c_s_mps2 == Approx(c_s_mps2).epsilon(kRel));
    REQUIRE(x.sliding.f_es_hz.has_value());
    const double w = 2.0 * pi * *x.sliding.f_es_hz;
    CHECK(*x.sliding.slide_asce_m == Approx(c_s_mps2 / (w * w)).epsilon(kRel));
    // Energy method (docs/methods.md s.4): 0.5 w^2 d^2 + 4 mu_e g d - g DeltaD = 0.
    const double a = 0.5 * w * w, b = 4.0 * mu_e * standard_g_mps2, q = standard_g_mps2 * 0.04;
    REQUIRE(x.sliding.slide_energy_m.has_value());
    CHECK(*x.sliding.slide_energy_m ==
          Approx((-b + std::sqrt(b * b + 4.0 * a * q)) / (2.0 * a)).epsilon(kRel));
    // Rocking about either edge: R = sqrt(0.5^2 + 0.5^2), alpha = 45 degrees.
    const double R = std::sqrt(0.5);
    const double i_o = r.input.component.x.inertia_cg_kgm2 + 100.0 * R * R;
    CHECK(x.rocking.p_radps == Approx(std::sqrt(100.0 * standard_g_mps2 * R / i_o)).epsilon(kRel));
    const double c = std::cos(pi / 4.0);
    CHECK(x.rocking.ishiyama_v_mps ==
          Approx(0.4 * std::sqrt(8.0 * standard_g_mps2 * R * (1.0 - c) / (3.0 * c))).epsilon(kRel));
}

TEST_CASE("what scales with gravity scales by exactly its ratio between 9.78 and 9.84",
          "[assess][gravity]") {
    // A stage that read the default 9.81 instead of the case's value breaks these ratios.
    const AssessmentResult lo = assess_box(9.78);
    const AssessmentResult hi = assess_box(9.84);
    const double ratio = 9.84 / 9.78;
    for (std::size_t i = 0; i < lo.levels.size(); ++i) {
        const LevelResult& l = lo.levels.at(i);
        const LevelResult& h = hi.levels.at(i);
        // C_s = 2 mu_e g; in the case's unit g it is 2 mu_e at either gravity.
        CHECK(h.sliding.c_s_mps2 / l.sliding.c_s_mps2 == Approx(ratio).epsilon(1e-14));
        CHECK(h.sliding.mu_e == l.sliding.mu_e);
        // p and the Ishiyama bound go as sqrt(g).
        CHECK(h.rocking.p_radps / l.rocking.p_radps == Approx(std::sqrt(ratio)).epsilon(1e-14));
        CHECK(h.rocking.ishiyama_v_mps / l.rocking.ishiyama_v_mps ==
              Approx(std::sqrt(ratio)).epsilon(1e-14));
    }
    // RG 1.60 in the case's g: below 0.25 Hz (constant ground displacement per g of PGA) its PSA
    // in g goes as 1 / g; above 33 Hz it is the PGA at either gravity.
    REQUIRE_FALSE(lo.plots.spectra.empty());
    const auto& s_lo = lo.plots.spectra.front();
    const auto& s_hi = hi.plots.spectra.front();
    REQUIRE(s_lo.x.front() < 0.25);
    CHECK(s_hi.y.front() / s_lo.y.front() == Approx(1.0 / ratio).epsilon(1e-12));
    CHECK(s_hi.y.back() == s_lo.y.back());
}

}  // namespace freestand_test_assess_test_case_gravity
