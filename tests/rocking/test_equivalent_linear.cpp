#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "block/block.hpp"
#include "core/errors.hpp"
#include "rocking/equivalent_linear.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_rocking_test_equivalent_linear {

using freestand::block::Block;
using freestand::block::Edge;
using freestand::spectra::Spectrum;
using namespace freestand::rocking;

namespace {
constexpr double g = 9.81;
constexpr double pi = std::numbers::pi;

// Constant spectral displacement D: PSA = (2 pi f)^2 D / g, a power law (exact under log-log
// interpolation and under psa_at's extrapolation below the first point), up to 1000 Hz.
Spectrum constant_sd(double d_m, double damping = 0.05) {
    Spectrum s;
    s.damping = damping;
    s.label = "constant SD";
    for (double f : {0.01, 0.1, 1.0, 10.0, 100.0, 1000.0}) {
        s.frequency_hz.push_back(f);
        s.psa_g.push_back(std::pow(2.0 * pi * f, 2) * d_m / g);
    }
    return s;
}

Spectrum flat(double psa_g, double damping) {
    Spectrum s;
    s.damping = damping;
    s.label = "flat";
    s.frequency_hz = {1e-4, 1.0, 1e4};
    s.psa_g = {psa_g, psa_g, psa_g};
    return s;
}

DampedSpectra any_damping(const Spectrum& s) {
    return DampedSpectra([s](double) { return s; }, s.label);
}

// The 0.3 x 1.2 m block: b = 0.15, R = 0.61847 m, alpha = 0.2449787 rad.
const Block steel = Block::uniform(0.15, 0.6, 38.0);
}  // namespace

TEST_CASE("Housner free-rocking frequency and CG displacement", "[rocking][el]") {
    // T = (4 / p) arccosh(1 / (1 - theta0 / alpha)); theta0 = alpha / 2: arccosh(2) = 1.3169579.
    CHECK(rocking_frequency_hz(3.0, 0.2, 0.1) == Approx(3.0 / (4.0 * 1.3169579)).epsilon(1e-7));
    // Small amplitude: arccosh(1 + x) ~ sqrt(2 x), accurate through the log1p form.
    CHECK(rocking_frequency_hz(3.0, 0.2, 0.2e-12) ==
          Approx(3.0 / (4.0 * std::sqrt(2e-12))).epsilon(1e-6));
    CHECK(rocking_displacement_m(2.0, 0.3, 0.3) == Approx(2.0 * std::sin(0.3)));
    CHECK_THROWS_WITH(rocking_frequency_hz(3.0, 0.2, 0.2), Catch::Contains("theta0_rad"));
}

TEST_CASE("beta_e = -ln(r) / pi is about 8.4% for a uniform block with alpha = 0.405",
          "[rocking][el]") {
    // docs/methods.md s.5a: r = 1 - 1.5 sin^2(0.405) = 0.76713, beta_e = 0.26510 / pi = 0.0844.
    const Block blk = Block::uniform(std::tan(0.405), 1.0);
    const double beta = damping_from_restitution(blk.housner_restitution(Edge::left));
    CHECK(beta == Approx(0.084).margin(0.0005));
    CHECK(beta == Approx(-std::log(1.0 - 1.5 * std::pow(std::sin(0.405), 2)) / pi).epsilon(1e-12));
    CHECK(damping_from_restitution(1.0) == 0.0);
    CHECK_THROWS_WITH(damping_from_restitution(0.0), Catch::Contains("restitution"));
}

TEST_CASE("damping interpolation on log axes and EN 1998-1 scaling outside the set",
          "[rocking][el]") {
    const DampedSpectra set({flat(0.8, 0.10), flat(1.0, 0.05)});
    // Geometric mean damping: t = 1/2 -> sqrt(1.0 * 0.8).
    CHECK(set.at(std::sqrt(0.005)).psa_g(1.0) == Approx(std::sqrt(0.8)).epsilon(1e-13));
    CHECK(set.at(0.10).psa_g(1.0) == 0.8);
    // 2%: eta(2%) / eta(5%) = sqrt(10 / 7); 20%: eta(20%) / eta(10%) = sqrt(15 / 25).
    CHECK(set.at(0.02).psa_g(1.0) == Approx(std::sqrt(10.0 / 7.0)).epsilon(1e-13));
    CHECK(set.at(0.20).psa_g(1.0) == Approx(0.8 * std::sqrt(15.0 / 25.0)).epsilon(1e-13));
    CHECK(set.at(0.02).note.find("EN 1998-1") != std::string::npos);
    CHECK(set.zpa_g() == 1.0);
    CHECK_THROWS_WITH(DampedSpectra({flat(0.8, 0.05), flat(1.0, 0.05)}),
                      Catch::Contains("distinct dampings"));
    CHECK_THROWS_WITH(DampedSpectra(std::vector<Spectrum>{}), Catch::Contains("at least one"));
}

TEST_CASE("constant-displacement demand: theta0, FS and spectral margin are known exactly",
          "[rocking][el]") {
    // Demand = capacity  <=>  (2 pi f_e)^2 D = (2 pi f_e)^2 R (sin a - sin(a - theta0)), whatever
    // f_e: theta0 = alpha - asin(sin(alpha) - D / R). D = 0.05 m: theta0 = 0.0825753 rad.
    // Overturning once D >= R sin(alpha) = b = 0.15 m: spectral margin 0.15 / 0.05 = 3.
    const double d = 0.05;
    const double R = steel.R_m(Edge::left), a = steel.alpha_rad(Edge::left);
    const double theta0 = a - std::asin(std::sin(a) - d / R);
    ElOptions o;
    o.pga_h_g = 0.5;  // above the gate tan(alpha) = 0.25
    const ElResult r = equivalent_linear_rocking(steel, Edge::left, any_damping(constant_sd(d)), {}, o);
    CHECK(r.gate_exceeded);
    REQUIRE(r.theta0_rad);
    CHECK(*r.theta0_rad == Approx(theta0).epsilon(1e-9));
    CHECK(theta0 == Approx(0.0825753).epsilon(1e-6));
    REQUIRE(r.fs);
    CHECK(*r.fs == Approx(a / theta0).epsilon(1e-9));
    CHECK(r.fs_ok);  // 2.97 >= 1.5
    REQUIRE(r.spectral_margin);
    CHECK(*r.spectral_margin == Approx(3.0).epsilon(2e-6));
    CHECK(*r.f_e_hz == Approx(rocking_frequency_hz(steel.p_radps(Edge::left), a, theta0)).epsilon(1e-8));
    // Required FS above the achieved one fails the check.
    o.fs_required = 3.0;
    CHECK_FALSE(equivalent_linear_rocking(steel, Edge::left, any_damping(constant_sd(d)), {}, o).fs_ok);
}

TEST_CASE("demand beyond the block's reach predicts overturning", "[rocking][el]") {
    ElOptions o;
    o.pga_h_g = 0.5;
    const ElResult r =
        equivalent_linear_rocking(steel, Edge::left, any_damping(constant_sd(0.2)), {}, o);
    CHECK(r.overturning_predicted);
    CHECK_FALSE(r.theta0_rad);
    CHECK(r.theta0_reason.find("overturning predicted") != std::string::npos);
    CHECK_FALSE(r.fs);
    CHECK_FALSE(r.fs_ok);
    REQUIRE(r.spectral_margin);
    CHECK(*r.spectral_margin == Approx(0.15 / 0.2).epsilon(2e-6));
}

TEST_CASE("the gate: no rocking unless PGA > (1 - 0.4 A_v) tan(alpha)", "[rocking][el]") {
    // tan(alpha) = 0.25 exactly; A_v = 0.5 g -> gate 0.8 * 0.25 = 0.2 g.
    const Block blk = Block::uniform(0.25, 1.0);
    ElOptions o;
    o.pga_v_g = 0.5;
    o.pga_h_g = 0.2;
    const ElResult at = equivalent_linear_rocking(blk, Edge::left, any_damping(constant_sd(0.05)), {}, o);
    CHECK(at.gate_g == Approx(0.2).epsilon(1e-15));
    CHECK_FALSE(at.gate_exceeded);
    REQUIRE(at.theta0_rad);
    CHECK(*at.theta0_rad == 0.0);
    CHECK_FALSE(at.fs);
    CHECK(at.fs_ok);
    CHECK(at.fs_reason.find("no rocking") != std::string::npos);
    o.pga_h_g = 0.2000001;
    const ElResult above =
        equivalent_linear_rocking(blk, Edge::left, any_damping(constant_sd(0.05)), {}, o);
    CHECK(above.gate_exceeded);
    CHECK(*above.theta0_rad > 0.0);
}

TEST_CASE("vertical spectrum lowers the effective gravity and the rocking frequency",
          "[rocking][el]") {
    // Flat SA_V = 0.5 g: g_e = g (1 - 0.2), f_e = f_e,g sqrt(0.8). Against a constant-SD demand
    // the angle does not change (both sides scale with f_e^2).
    const double d = 0.05;
    const double a = steel.alpha_rad(Edge::left);
    const double theta0 = a - std::asin(std::sin(a) - d / steel.R_m(Edge::left));
    VerticalDemand v;
    v.spectra = any_damping(flat(0.5, 0.05));
    ElOptions o;
    o.pga_h_g = 0.5;
    const ElResult r = equivalent_linear_rocking(steel, Edge::left, any_damping(constant_sd(d)), v, o);
    CHECK(r.pga_v_g == 0.5);
    CHECK(r.gate_g == Approx(0.8 * 0.25).epsilon(1e-14));
    REQUIRE(r.theta0_rad);
    CHECK(*r.theta0_rad == Approx(theta0).epsilon(1e-9));
    const double fg = rocking_frequency_hz(steel.p_radps(Edge::left), a, theta0);
    CHECK(*r.f_e_hz == Approx(fg * std::sqrt(0.8)).epsilon(1e-9));
    // Ratio form: SA_V = 0.5 SA_H; PGA_v defaults to 0.5 PGA_h.
    VerticalDemand vr;
    vr.ratio = 0.5;
    const ElResult rr = equivalent_linear_rocking(steel, Edge::left, any_damping(constant_sd(d)), vr, o);
    CHECK(rr.pga_v_g == 0.25);
    CHECK(*rr.theta0_rad == Approx(theta0).epsilon(1e-9));
    CHECK(*rr.f_e_hz < fg);
}

TEST_CASE("effective frequency solves its equation for a steep vertical spectrum",
          "[rocking][el]") {
    // SA_V = 0.5 (f / 2)^6 g: the map f -> f_g sqrt(1 - 0.4 SA_V(f)) is expansive near 2 Hz, so
    // the solver must fall back on its bracket. Whatever path it takes, f_e must satisfy
    // f_e = f_g(theta0) sqrt(1 - 0.4 SA_V(f_e)); theta0 is unchanged (constant-SD demand).
    Spectrum sv;
    sv.damping = 0.05;
    sv.label = "steep vertical";
    for (double f : {0.5, 1.0, 2.0, 4.0}) {
        sv.frequency_hz.push_back(f);
        sv.psa_g.push_back(0.5 * std::pow(f / 2.0, 6));
    }
    const double d = 0.05;
    const double a = steel.alpha_rad(Edge::left);
    const double theta0 = a - std::asin(std::sin(a) - d / steel.R_m(Edge::left));
    VerticalDemand v;
    v.spectra = any_damping(sv);
    ElOptions o;
    o.pga_h_g = 0.5;
    o.pga_v_g = 0.1;
    const ElResult r = equivalent_linear_rocking(steel, Edge::left, any_damping(constant_sd(d)), v, o);
    REQUIRE(r.theta0_rad);
    CHECK(*r.theta0_rad == Approx(theta0).epsilon(1e-9));
    const double fg = rocking_frequency_hz(steel.p_radps(Edge::left), a, *r.theta0_rad);
    const double fe = *r.f_e_hz;
    CHECK(fe < fg);
    CHECK(fe == Approx(fg * std::sqrt(std::max(0.0, 1.0 - 0.4 * sv.psa_at(fe)))).epsilon(1e-10));
}

TEST_CASE("restitution: Housner's by default, a measured one overrides it", "[rocking][el]") {
    ElOptions o;
    o.pga_h_g = 0.5;
    const auto demand = any_damping(constant_sd(0.05));
    const ElResult housner = equivalent_linear_rocking(steel, Edge::left, demand, {}, o);
    CHECK(housner.restitution == Approx(1.0 - 1.5 * std::pow(std::sin(steel.alpha_rad(Edge::left)), 2)));
    o.restitution = 0.98;  // steel on steel, docs/methods.md s.7
    const ElResult measured = equivalent_linear_rocking(steel, Edge::left, demand, {}, o);
    CHECK(*measured.beta_e == Approx(-std::log(0.98) / pi).epsilon(1e-14));
    o.restitution = 1.0;
    const ElResult elastic = equivalent_linear_rocking(steel, Edge::left, demand, {}, o);
    CHECK_FALSE(elastic.beta_e);
    CHECK_FALSE(elastic.theta0_rad);
    CHECK(elastic.theta0_reason.find("not applicable") != std::string::npos);
    // Below the gate the restitution does not matter: still "no rocking" (theta0 = 0).
    ElOptions low = o;
    low.pga_h_g = 0.2;  // < tan(alpha) = 0.25
    const ElResult quiet = equivalent_linear_rocking(steel, Edge::left, demand, {}, low);
    CHECK_FALSE(quiet.beta_e);
    REQUIRE(quiet.theta0_rad);
    CHECK(*quiet.theta0_rad == 0.0);
    CHECK(quiet.fs_ok);
    CHECK(quiet.theta0_reason.find("no rocking: PGA 0.2 g <= gate") == 0);
    CHECK(quiet.spectral_margin_reason.find("not applicable") != std::string::npos);
    // r = 0 is within the case reader's and the simulator's range [0, 1], so it must not be
    // refused as "restitution ... expected (0, 1]": the estimate is not applicable instead.
    o.restitution = 0.0;
    const ElResult plastic = equivalent_linear_rocking(steel, Edge::left, demand, {}, o);
    CHECK_FALSE(plastic.beta_e);
    CHECK_FALSE(plastic.theta0_rad);
    CHECK(plastic.theta0_reason.find("not applicable") != std::string::npos);
    CHECK(plastic.beta_e_reason.find("the block does not rebound") != std::string::npos);
    o.restitution = 1.5;
    CHECK_THROWS_WITH(equivalent_linear_rocking(steel, Edge::left, demand, {}, o),
                      Catch::Contains("restitution"));
    o.restitution.reset();
    o.fs_required = 0.0;
    CHECK_THROWS_WITH(equivalent_linear_rocking(steel, Edge::left, demand, {}, o),
                      Catch::Contains("fs_required"));
}

TEST_CASE("asymmetric block: each edge estimated, the smaller margin governs", "[rocking][el]") {
    // tan(alpha_L) = 0.2, tan(alpha_R) = 0.4, h = 1: b_L = 0.2 m, b_R = 0.4 m. Against a
    // constant SD of 0.1 m the margins are b / D: 2 (left) and 4 (right).
    const Block blk = Block::general(0.2, 0.4, 1.0, 100.0, 20.0);
    ElOptions o;
    o.pga_h_g = 1.0;
    const ElBlockResult r = equivalent_linear_rocking(blk, any_damping(constant_sd(0.1)), {}, o);
    CHECK(r.governing_edge == Edge::left);
    CHECK(*r.left.spectral_margin == Approx(2.0).epsilon(2e-6));
    CHECK(*r.right.spectral_margin == Approx(4.0).epsilon(2e-6));
    CHECK(*r.left.theta0_rad > *r.right.theta0_rad);
}

}  // namespace freestand_test_rocking_test_equivalent_linear
