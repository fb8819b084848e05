// Realism of generated histories (docs/methods.md s.8 "Realism"): PGA / ZPA,
// V/A, AD/V^2, D/A, D5-75 reported for every history, checked in acceptance, met by generation.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/measures.hpp"
#include "core/units.hpp"
#include "motion/motion.hpp"
#include "own_check.hpp"
#include "spectra/design.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_motion_test_realism {

using namespace freestand;
using Catch::Contains;

namespace {

motion::GeneratedComponent synthetic_h1(const motion::TargetSet& ts, std::uint64_t seed) {
    motion::GenerateOptions o;
    o.components = {"h1"};
    o.seed = seed;
    return motion::generate_set(ts, o).components.front();
}

// A long-period displacement bump d(t) = D sin^4(pi t / T) (zero displacement, velocity and
// acceleration at both ends), as acceleration samples.
std::vector<double> slow_bump(std::size_t n, double dt_s, double amplitude_m) {
    std::vector<double> d(n), a(n, 0.0);
    const double last = static_cast<double>(n - 1);
    for (std::size_t i = 0; i < n; ++i)
        d[i] = amplitude_m * std::pow(std::sin(units::pi * static_cast<double>(i) / last), 4);
    for (std::size_t i = 1; i + 1 < n; ++i) a[i] = (d[i + 1] - 2.0 * d[i] + d[i - 1]) / (dt_s * dt_s);
    return a;
}

}  // namespace

TEST_CASE("ten seeds of RG 1.60 at 0.3 g: every component passes SRP 3.7.1 and realism",
          "[motion][realism]") {
    // The realism acceptance run (docs/methods.md s.8): without clipping and the displacement-aware
    // baseline correction, PGA is 1.10-1.35 x ZPA and D/A 0.93-4.85 m/g.
    const motion::TargetSet ts = motion::rg160_targets(0.3);
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        INFO("seed " << seed);
        const motion::GeneratedSet s = motion::generate_set(ts, [&] {
            motion::GenerateOptions o;
            o.seed = seed;
            return o;
        }());
        CHECK(s.passed);
        for (std::size_t c = 0; c < s.components.size(); ++c) {
            const auto& g = s.components[c];
            INFO("component " << g.record.component);
            const motion::Target& t = c == 2 ? ts.vertical : ts.horizontal;
            test::require_srp(g.record, t);
            CHECK(g.acceptance.srp_passed);
            CHECK(g.acceptance.realism_passed);
        }
    }
}

TEST_CASE("acceptance reports the realism measures from the record's own peaks",
          "[motion][realism]") {
    const motion::TargetSet ts = motion::rg160_targets(0.3);
    const auto g = synthetic_h1(ts, 7);
    const motion::Acceptance& a = g.acceptance;
    const core::GroundMotion gm = core::measure(g.record);
    CHECK(a.zpa_g == Approx(0.3).epsilon(1e-12));
    CHECK(a.pga_over_zpa == Approx(gm.pga_g / 0.3).epsilon(1e-12));
    CHECK(a.va_mps_per_g == Approx(gm.pgv_mps / gm.pga_g).epsilon(1e-12));
    CHECK(a.da_m_per_g == Approx(gm.pgd_m / gm.pga_g).epsilon(1e-12));
    CHECK(a.adv2 == Approx(gm.pga_g * 9.81 * gm.pgd_m / (gm.pgv_mps * gm.pgv_mps)).epsilon(1e-12));
    CHECK(a.arias_mps == Approx(gm.arias_mps).epsilon(1e-12));
    CHECK(a.horizontal);
    REQUIRE(a.realism.va_mps_per_g.has_value());
    CHECK(a.realism.va_mps_per_g->max == 2.0);
}

TEST_CASE("each realism range that fails is named in the reason", "[motion][realism]") {
    const motion::TargetSet ts = motion::rg160_targets(0.3);
    const motion::Target& t = ts.horizontal;
    const auto g = synthetic_h1(ts, 3);
    REQUIRE(g.acceptance.passed);

    SECTION("PGA above 1.1 x ZPA: one sample raised") {
        core::Record r = g.record;
        std::size_t peak = 0;
        for (std::size_t i = 0; i < r.size(); ++i)
            if (std::abs(r.accel_mps2[i]) > std::abs(r.accel_mps2[peak])) peak = i;
        r.accel_mps2[peak] = std::copysign(1.2 * 0.3 * units::g_mps2, r.accel_mps2[peak]);
        const motion::Acceptance a = motion::check_acceptance(r, t);
        CHECK_FALSE(a.realism_passed);
        CHECK_FALSE(a.passed);
        CHECK_THAT(a.reason, Contains("PGA 1.200 x ZPA outside 1-1.1"));
    }
    SECTION("D/A above 1.3 m/g: a slow displacement bump of 0.6 m added") {
        core::Record r = g.record;
        const std::vector<double> bump = slow_bump(r.size(), r.dt_s, 0.6);
        for (std::size_t i = 0; i < r.size(); ++i) r.accel_mps2[i] += bump[i];
        const motion::Acceptance a = motion::check_acceptance(r, t);
        CHECK(a.da_m_per_g > 1.3);
        CHECK_THAT(a.reason, Contains("D/A") && Contains("m/g > 1.3"));
    }
    SECTION("V/A and AD/V^2 outside their ranges when the user narrows them") {
        motion::Target narrow = t;
        narrow.realism.va_mps_per_g = motion::Range{0.5, 0.6};
        narrow.realism.adv2 = motion::Range{10.0, 20.0};
        const motion::Acceptance a = motion::check_acceptance(g.record, narrow);
        CHECK(a.srp_passed);
        CHECK_FALSE(a.realism_passed);
        CHECK_THAT(a.reason, Contains("V/A") && Contains("outside 0.5-0.6") &&
                                 Contains("AD/V^2") && Contains("outside 10-20"));
    }
    SECTION("D5-75 below 6 s: the strong part cut short") {
        core::Record r = g.record;
        for (std::size_t i = 0; i < r.size(); ++i) {
            const double t_s = static_cast<double>(i) * r.dt_s;
            if (t_s < 4.0 || t_s > 7.0) r.accel_mps2[i] *= 0.05;
        }
        const motion::Acceptance a = motion::check_acceptance(r, t);
        CHECK(a.d5_75_s < 6.0);
        CHECK_THAT(a.reason, Contains("D5-75") && Contains("< 6 s"));
    }
}

TEST_CASE("V/A, AD/V^2 and D/A are checked only where a range is set, and on horizontals only",
          "[motion][realism]") {
    // EC8 type 2, ground A: small near events, V/A about 0.4 m/s/g, below RG 1.60's 0.8. No
    // range comes with this target, so the ratios are reported and not checked...
    const auto f = spectra::log_frequencies(0.01, 200.0, 100);
    motion::TargetSet ts = motion::ratio_targets(
        "EC8 2A", spectra::ec8(0.2, spectra::Ec8Type::type2, 'A', 0.05, f), std::nullopt, 2.0 / 3.0);
    CHECK_FALSE(ts.horizontal.realism.va_mps_per_g.has_value());
    const auto g = synthetic_h1(ts, 1);
    CHECK(g.acceptance.passed);
    CHECK(g.acceptance.va_mps_per_g < 0.8);
    // ...and checked once the user gives one.
    motion::RealismLimits lim;
    lim.va_mps_per_g = motion::Range{0.8, 2.0};
    motion::set_realism(ts, lim);
    const motion::Acceptance checked = motion::check_acceptance(g.record, ts.horizontal);
    CHECK_FALSE(checked.passed);
    CHECK_THAT(checked.reason, Contains("V/A"));
    // The vertical component is never held to horizontal ratios.
    const motion::Acceptance vertical = motion::check_acceptance(g.record, ts.vertical);
    CHECK_FALSE(vertical.horizontal);
    CHECK_THAT(vertical.reason, !Contains("V/A"));
}

TEST_CASE("realism limits are validated with the field named", "[motion][realism][errors]") {
    motion::RealismLimits lim;
    lim.va_mps_per_g = motion::Range{2.0, 0.8};
    CHECK_THROWS_WITH(motion::validate_realism(lim),
                      Contains("va_range_mps_per_g") && Contains("expected min < max"));
    lim = motion::RealismLimits{};
    lim.da_max_m_per_g = -1.0;
    CHECK_THROWS_WITH(motion::validate_realism(lim), Contains("da_max_m_per_g"));
    lim = motion::RealismLimits{};
    lim.adv2 = motion::Range{0.0, 8.0};
    CHECK_THROWS_WITH(motion::validate_realism(lim), Contains("adv2_range"));
    motion::TargetSet ts = motion::rg160_targets(0.3);
    lim = motion::RealismLimits{};
    lim.pga_over_zpa = motion::Range{1.1, 1.0};
    CHECK_THROWS_WITH(motion::set_realism(ts, lim), Contains("pga_over_zpa_range"));
}

TEST_CASE("the synthetic seed's peaks are clipped into the PGA band before matching",
          "[motion][realism]") {
    // A Gaussian process has PGA 1.1-1.35 x its spectrum's ZPA; the seed's crest factor is
    // brought down (clipping and re-phasing) so that matching need not fight it.
    const motion::Target t = motion::rg160_targets(0.3).horizontal;
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        const core::Record r = motion::synthesize(t, 20.0, 0.005, seed, motion::Envelope{});
        const double pga_over_zpa = core::measure(r).pga_g / 0.3;
        INFO("seed " << seed);
        CHECK(pga_over_zpa < 1.1);
        CHECK(pga_over_zpa > 0.9);
    }
}

}  // namespace freestand_test_motion_test_realism
