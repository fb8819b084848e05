// Every user-reachable error path of the motion stage: type and message.
#include <catch2/catch.hpp>

#include "support/paths.hpp"
#include "core/errors.hpp"
#include "core/readers.hpp"
#include "motion/criteria.hpp"
#include "motion/motion.hpp"
#include "spectra/design.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_motion_test_errors {

using namespace freestand;
using Catch::Contains;

namespace {
spectra::Spectrum good() {
    spectra::Spectrum s;
    s.damping = 0.05;
    s.frequency_hz = {0.1, 1.0, 10.0, 50.0};
    s.psa_g = {0.02, 0.5, 0.6, 0.2};
    s.label = "user target";
    return s;
}
motion::TargetSet targets() { return motion::ratio_targets("t", good(), std::nullopt, 2.0 / 3.0); }
}  // namespace

TEST_CASE("bad targets are InputErrors naming the point", "[motion][errors]") {
    auto s = good();
    s.psa_g[2] = 0.0;
    CHECK_THROWS_MATCHES(
        motion::validate_target(s, 0.05), InputError,
        Catch::Message("user target: point 3: PSA 0 g at 10 Hz; expected finite > 0"));
    s = good();
    s.frequency_hz[2] = 1.0;
    CHECK_THROWS_MATCHES(motion::validate_target(s, 0.05), InputError,
                         Catch::Message("user target: point 3: frequency 1 Hz not above the "
                                        "previous 1 Hz; frequencies must be strictly increasing"));
    s = good();
    s.damping = 0.02;
    CHECK_THROWS_WITH(motion::validate_target(s, 0.05), Contains("user target: damping 0.02"));
    CHECK_THROWS_WITH(motion::validate_target(s, 0.05), Contains("give a 0.05 target"));
    s = good();
    s.psa_g.pop_back();
    CHECK_THROWS_AS(motion::validate_target(s, 0.05), InputError);
    CHECK_THROWS_WITH(motion::ratio_targets("t", good(), std::nullopt, 0.0),
                      Contains("vertical_ratio"));
}

TEST_CASE("impossible requests are InputErrors saying what SRP 3.7.1 needs", "[motion][errors]") {
    motion::GenerateOptions o;
    o.components = {"h1"};
    o.dt_s = 0.02;
    CHECK_THROWS_MATCHES(
        motion::generate_set(targets(), o), InputError,
        Catch::Message(
            "dt_s: dt 0.02 s is too coarse: SRP 3.7.1 needs dt <= 0.01 s, and the Nyquist "
            "frequency 25 Hz is below the 50 Hz top of the acceptance band"));
    o.dt_s = 0.005;
    o.duration_s = 10.0;
    CHECK_THROWS_MATCHES(
        motion::generate_set(targets(), o), InputError,
        Catch::Message("duration_s: duration 10 s is too short: SRP 3.7.1 needs >= 20 s"));
    o.duration_s = 20.0;
    o.components = {"h1", "x"};
    CHECK_THROWS_MATCHES(
        motion::generate_set(targets(), o), InputError,
        Catch::Message("components: unknown component \"x\"; expected h1, h2 or v"));
    o.components = {"h1", "h1"};
    CHECK_THROWS_WITH(motion::generate_set(targets(), o), Contains("given twice"));
    o.components = {"h1", "h2"};
    o.seed_records = {
        core::read_at2(std::string(freestand::test::data_dir()) + "/RSN175_IMPVALL.H_H-E12140.AT2")};
    CHECK_THROWS_MATCHES(
        motion::generate_set(targets(), o), InputError,
        Catch::Message(
            "seed_records: 1 seed records for 2 components; give one seed record per component"));
    core::Record short_rec = o.seed_records[0];
    short_rec.accel_mps2.resize(2000);  // 10 s
    short_rec.source = "short.AT2";
    o.components = {"h1"};
    o.seed_records = {short_rec};
    CHECK_THROWS_MATCHES(
        motion::generate_set(targets(), o), InputError,
        Catch::Message("short.AT2: duration: seed record lasts 9.995 s; SRP 3.7.1 needs >= 20 s"));
    // An all-zero seed record has an infinite scale factor to the target: unchecked, both
    // generate_set and match_record alone say a misleading "sample 0 is not a finite number".
    core::Record zero = short_rec;
    zero.accel_mps2.assign(5000, 0.0);  // 25 s
    zero.source = "zero.csv";
    zero.name = "zero";
    o.seed_records = {zero};
    CHECK_THROWS_MATCHES(
        motion::generate_set(targets(), o), InputError,
        Catch::Message("zero.csv: seed record \"zero\" is zero at all 5000 samples; a seed record "
                       "needs motion to match"));
    CHECK_THROWS_WITH(motion::match_record(zero, targets().horizontal, motion::MatchOptions{}),
                      Contains("zero.csv: seed record \"zero\" has no usable response"));
    motion::Envelope e;
    e.strong_s = 30.0;
    CHECK_THROWS_WITH(motion::synthesize(targets().horizontal, 20.0, 0.005, 1, e),
                      Contains("exceed the duration 20 s"));
}

TEST_CASE("the acceptance report names every failed criterion", "[motion][acceptance]") {
    const motion::Target t = motion::rg160_targets(0.3).horizontal;
    core::Record r =
        core::read_at2(std::string(freestand::test::data_dir()) + "/RSN175_IMPVALL.H_H-E12140.AT2");
    // Unmatched, unscaled (PGA about 0.14 g against 0.3 g): far below the target.
    motion::Acceptance a = motion::check_acceptance(r, t);
    CHECK_FALSE(a.passed);
    CHECK(a.min_ratio < 0.9);
    CHECK_THAT(a.reason, Contains("min ratio") && Contains("adjacent points below target"));
    CHECK(a.check_points >= 270);
    // Too short and too coarse: both named.
    core::Record coarse;
    coarse.dt_s = 0.02;
    for (std::size_t i = 0; i < r.size() / 4 && coarse.accel_mps2.size() < 500; i += 4)
        coarse.accel_mps2.push_back(r.accel_mps2[i]);
    a = motion::check_acceptance(coarse, t);
    CHECK_FALSE(a.passed);
    CHECK_THAT(a.reason, Contains("dt 0.02 s > 0.01 s") && Contains("duration 9.760 s < 20 s"));
    // Band follows Nyquist: 25 Hz at dt = 0.02 s.
    CHECK(a.check_points == 241);  // ceil(100 log10(250)) + 1
    // A drifting record: the final velocity is named.
    core::Record drift = r;
    for (double& x : drift.accel_mps2) x += 0.01;
    a = motion::check_acceptance(drift, t);
    CHECK_THAT(a.reason, Contains("final velocity") && Contains("final displacement"));
}

TEST_CASE("RG 1.60's vertical target: its own spectrum, scaled to a ZPA ratio up to 2",
          "[motion][errors][vertical]") {
    const std::vector<double> f{0.1, 0.25, 1.0, 3.5, 9.0, 33.0, 50.0};
    const motion::Target own = motion::rg160_vertical_target(0.3, 1.0, f);
    const motion::Target half = motion::rg160_vertical_target(0.3, 0.5, f);
    CHECK_FALSE(own.horizontal);
    CHECK_FALSE(own.rg160_psd_pga_g.has_value());
    // RG 1.60: the vertical ZPA is the horizontal PGA; 2/3 of the horizontal below 0.25 Hz,
    // equal above 3.5 Hz (docs/methods.md s.8).
    const spectra::Spectrum h = spectra::rg160(0.3, 0.05, false, f);
    CHECK(motion::zero_period_g(own.psa_5pct) == Approx(0.3).epsilon(1e-15));
    CHECK(own.psa_5pct.psa_g[0] / h.psa_g[0] == Approx(1.37 / 2.05).epsilon(1e-12));
    CHECK(own.psa_5pct.psa_g[3] / h.psa_g[3] == Approx(1.0).epsilon(0.002));
    for (std::size_t i = 0; i < f.size(); ++i) {
        CHECK(half.psa_5pct.psa_g[i] == Approx(0.5 * own.psa_5pct.psa_g[i]).epsilon(1e-14));
        CHECK(half.psa_10pct->psa_g[i] == Approx(0.5 * own.psa_10pct->psa_g[i]).epsilon(1e-14));
    }
    CHECK(motion::zero_period_g(motion::rg160_targets(0.3, 0.5).vertical.psa_5pct) ==
          Approx(0.15).epsilon(1e-15));
    CHECK(motion::rg160_targets(0.3).vertical.psa_5pct.psa_g ==
          motion::rg160_targets(0.3, 1.0).vertical.psa_5pct.psa_g);
    CHECK_THROWS_MATCHES(
        motion::rg160_vertical_target(0.3, 0.0, f), InputError,
        Catch::Message("vertical_ratio: value 0 is out of range; expected (0, 2]"));
}

TEST_CASE("the SRP limits on dt, duration and the cap band hold within their tolerances",
          "[motion][errors]") {
    namespace criteria = motion::criteria;
    // An ulp above 0.01 s is still the 0.01 s step; a step 1e-9 s coarser is refused.
    CHECK_FALSE(criteria::dt_too_coarse(0.01));
    CHECK_FALSE(criteria::dt_too_coarse(std::nextafter(0.01, 1.0)));
    CHECK(criteria::dt_too_coarse(0.01 + 1e-9));
    // (n - 1) dt a rounding below 20 s still meets the minimum; 1e-6 s short does not.
    CHECK_FALSE(criteria::too_short(20.0 - 1e-12));
    CHECK(criteria::too_short(20.0 - 1e-6));
    CHECK(criteria::in_cap_band(0.2 - 1e-15));
    CHECK(criteria::in_cap_band(25.0 + 1e-15));
    CHECK_FALSE(criteria::in_cap_band(0.2 - 1e-9));
    CHECK_FALSE(criteria::in_cap_band(25.0 + 1e-9));
}

}  // namespace freestand_test_motion_test_errors
