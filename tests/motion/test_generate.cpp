// Generation and matching against design targets, checked with the tests' own spectrum call
// (own_check.hpp), plus the hard cases of generation (docs/methods.md s.8).
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "support/paths.hpp"
#include "core/readers.hpp"
#include "motion/motion.hpp"
#include "own_check.hpp"
#include "spectra/design.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_motion_test_generate {

using namespace freestand;

namespace {

const char* const kSeeds[] = {"RSN175_IMPVALL.H_H-E12140.AT2", "RSN175_IMPVALL.H_H-E12230.AT2",
                              "RSN1546_CHICHI_TCU122-N.AT2"};

core::Record seed(const std::string& file) {
    return core::read_at2(std::string(freestand::test::data_dir()) + "/" + file);
}

std::vector<double> grid() { return spectra::log_frequencies(0.01, 200.0, 100); }

// One component through the full generator (retries included); returns it after the own check.
motion::GeneratedComponent one(const motion::Target& target, const std::string& seed_file,
                               std::uint64_t rng_seed = 1) {
    motion::TargetSet ts;
    ts.horizontal = target;
    ts.vertical = target;
    motion::GenerateOptions o;
    o.components = {"h1"};
    o.seed = rng_seed;
    if (!seed_file.empty()) o.seed_records = {seed(seed_file)};
    motion::GeneratedSet s = motion::generate_set(ts, o);
    REQUIRE(s.components.size() == 1);
    return s.components.front();
}

// Synthetic and every seed record pass SRP 3.7.1 and realism, except the seed named `rejected`,
// which must come back failing with `why` among its reasons (a record that cannot meet both is
// rejected, never returned as passing).
void require_all_methods(const motion::Target& target, const std::string& rejected = "",
                         const std::string& why = "") {
    {
        INFO("synthetic");
        const auto g = one(target, "");
        CHECK(g.stop == "passed");
        test::require_srp(g.record, target);
    }
    for (const char* s : kSeeds) {
        INFO("seed " << s);
        const auto g = one(target, s);
        if (s == rejected) {
            CHECK(g.stop == "attempt limit");
            CHECK_FALSE(g.acceptance.passed);
            CHECK_THAT(g.acceptance.reason, Catch::Contains(why));
            continue;
        }
        CHECK(g.stop == "passed");
        test::require_srp(g.record, target);
    }
}

}  // namespace

TEST_CASE("RG 1.60 at 0.1-0.4 g: synthetic and every seed record meet SRP 3.7.1 and realism",
          "[motion][generate]") {
    for (double pga : {0.1, 0.2, 0.3, 0.4}) {
        INFO("PGA " << pga << " g");
        require_all_methods(motion::rg160_targets(pga).horizontal);
    }
}

TEST_CASE("ASCE 7 and Eurocode 8 targets: synthetic and seed records meet SRP 3.7.1 or are rejected",
          "[motion][generate]") {
    SECTION("ASCE 7, SDS 1.0 g, SD1 0.6 g, TL 8 s") {
        // The 90 s Chi-Chi record cannot hold its PGA within 1.1 x ZPA while ASCE 7's ramp
        // below T0 asks 1.25 x ZPA at 50 Hz: its matches overshoot the 1.3 cap instead.
        require_all_methods(motion::ratio_targets("ASCE 7", spectra::asce7(1.0, 0.6, 8.0, grid()),
                                                  std::nullopt, 2.0 / 3.0)
                                .horizontal,
                            kSeeds[2], "> 1.3 in 0.2-25 Hz");
    }
    SECTION("EC8 type 1, ground B, a_g 0.3 g") {
        const auto f = grid();
        require_all_methods(motion::ratio_targets(
                                "EC8", spectra::ec8(0.3, spectra::Ec8Type::type1, 'B', 0.05, f),
                                spectra::ec8(0.3, spectra::Ec8Type::type1, 'B', 0.10, f), 2.0 / 3.0)
                                .horizontal);
    }
}

TEST_CASE("three components: independent, matched to their own targets, 10% ratio reported",
          "[motion][generate]") {
    const motion::TargetSet ts = motion::rg160_targets(0.3);
    motion::GenerateOptions o;  // h1, h2, v synthetic, seed 1
    const motion::GeneratedSet s = motion::generate_set(ts, o);
    REQUIRE(s.components.size() == 3);
    CHECK(s.passed);
    test::require_srp(s.components[0].record, ts.horizontal);
    test::require_srp(s.components[1].record, ts.horizontal);
    test::require_srp(s.components[2].record, ts.vertical);
    CHECK(s.components[2].record.component == "v");
    REQUIRE(s.correlations.size() == 3);
    for (const auto& c : s.correlations) CHECK(std::abs(c.rho) <= 0.16);
    // Own zero-lag correlation of h1 and h2 equals the reported one.
    const auto& a = s.components[0].record.accel_mps2;
    const auto& b = s.components[1].record.accel_mps2;
    double ma = 0, mb = 0, sab = 0, saa = 0, sbb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        ma += a[i];
        mb += b[i];
    }
    ma /= static_cast<double>(a.size());
    mb /= static_cast<double>(b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        sab += (a[i] - ma) * (b[i] - mb);
        saa += (a[i] - ma) * (a[i] - ma);
        sbb += (b[i] - mb) * (b[i] - mb);
    }
    CHECK(s.correlations[0].rho == Approx(sab / std::sqrt(saa * sbb)).margin(1e-12));
    // The 10% ratio is reported (informational; RG 1.60's 5% and 10% shapes disagree).
    for (const auto& c : s.components) {
        REQUIRE(c.acceptance.ratio_10pct_min.has_value());
        CHECK(*c.acceptance.ratio_10pct_min > 0.5);
        CHECK(*c.acceptance.ratio_10pct_max < 2.0);
    }
}

TEST_CASE("hard case: coarse dt = 0.01 s against RG 1.60 defined to 50 Hz",
          "[motion][generate][hard]") {
    const motion::TargetSet ts = motion::rg160_targets(0.3);
    motion::GenerateOptions o;
    o.components = {"h1"};
    o.dt_s = 0.01;
    const auto s = motion::generate_set(ts, o);
    CHECK(s.components[0].record.dt_s == 0.01);
    CHECK(s.components[0].acceptance.check_points >= 270);  // 0.1-50 Hz = Nyquist
    test::require_srp(s.components[0].record, ts.horizontal);
}

TEST_CASE("hard case: 90 s Chi-Chi seed far from a short-period EC8 type 2 ground A target",
          "[motion][generate][hard]") {
    const auto f = grid();
    const motion::Target t =
        motion::ratio_targets("EC8 type 2 A",
                              spectra::ec8(0.2, spectra::Ec8Type::type2, 'A', 0.05, f),
                              std::nullopt, 2.0 / 3.0)
            .horizontal;
    const core::Record chichi = seed(kSeeds[2]);
    REQUIRE(chichi.duration_s() > 89.0);
    // Far: unscaled, its 5% spectrum shape is off by a factor > 3 somewhere in the band.
    const test::OwnCheck before = test::own_check(chichi, t.psa_5pct);
    CHECK(before.max_ratio / before.min_ratio > 3.0);
    const auto g = one(t, kSeeds[2]);
    CHECK(g.record.duration_s() == Approx(chichi.duration_s()));
    test::require_srp(g.record, t);
}

TEST_CASE("hard case: narrow-band targets", "[motion][generate][hard]") {
    // Decision: a 5%-damped spectrum cannot be narrower than the oscillator's own bandwidth
    // (half-power width 2 zeta = 10% in frequency). A bump about 1.5 bandwidths wide must be
    // matched; a spike narrower than one bandwidth cannot pass the 1.3 cap and 0.9 floor
    // together, and the generator must say so (failing, with the reason) rather than return a
    // record as passing.
    const motion::Target base = motion::rg160_targets(0.2).horizontal;
    auto bumped = [&](double width) {
        spectra::Spectrum s = base.psa_5pct;
        for (std::size_t i = 0; i < s.frequency_hz.size(); ++i) {
            const double x = std::log(s.frequency_hz[i] / 5.0) / width;
            s.psa_g[i] *= 1.0 + 1.5 * std::exp(-x * x);  // x2.5 at 5 Hz
        }
        s.label = "RG 1.60 with a bump at 5 Hz";
        motion::Target t;
        t.psa_5pct = s;
        return t;
    };
    SECTION("bump x2.5 at 5 Hz with a log-width of 0.15 (about +-15%) is matched") {
        const motion::Target t = bumped(0.15);
        test::require_srp(one(t, "").record, t);
        test::require_srp(one(t, kSeeds[0]).record, t);
    }
    SECTION("spike with a log-width of 0.02 (+-2%) is reported failing, with the reason") {
        const motion::Target t = bumped(0.02);
        motion::TargetSet ts;
        ts.horizontal = ts.vertical = t;
        motion::GenerateOptions o;
        o.components = {"h1"};
        o.max_attempts = 2;
        o.match.max_iterations = 15;
        const auto s = motion::generate_set(ts, o);
        CHECK_FALSE(s.passed);
        CHECK_FALSE(s.components[0].acceptance.passed);
        CHECK(s.components[0].stop == "attempt limit");
        CHECK_THAT(s.components[0].acceptance.reason, Catch::Contains("ratio"));
        CHECK(s.notes.size() >= 2);
    }
}

TEST_CASE("deterministic: the same inputs and seed give bit-identical records",
          "[motion][generate]") {
    const motion::TargetSet ts = motion::rg160_targets(0.2);
    motion::GenerateOptions o;
    o.components = {"h1", "v"};
    o.seed = 42;
    const auto a = motion::generate_set(ts, o);
    const auto b = motion::generate_set(ts, o);
    for (std::size_t c = 0; c < a.components.size(); ++c) {
        CHECK(a.components[c].record.accel_mps2 == b.components[c].record.accel_mps2);
        CHECK(a.components[c].seed == b.components[c].seed);
    }
    o.seed = 43;
    const auto other = motion::generate_set(ts, o);
    CHECK(other.components[0].record.accel_mps2 != a.components[0].record.accel_mps2);
}

TEST_CASE("correlated components are reported failing with the pair named", "[motion][generate]") {
    // The same seed record for h1 and h2 cannot give independent components (rho ~ 1): a seed
    // record is not regenerated, so the set fails and the note names the pair.
    const motion::TargetSet ts = motion::rg160_targets(0.3);
    motion::GenerateOptions o;
    o.components = {"h1", "h2"};
    o.seed_records = {seed(kSeeds[1]), seed(kSeeds[1])};
    const auto s = motion::generate_set(ts, o);
    CHECK(s.components[0].acceptance.passed);
    REQUIRE(s.correlations.size() == 1);
    CHECK(s.correlations[0].rho > 0.9);
    CHECK_FALSE(s.passed);
    REQUIRE_FALSE(s.notes.empty());
    CHECK_THAT(s.notes.back(), Catch::Contains("h1-h2: |rho| = ") && Catch::Contains("> 0.16"));
}

}  // namespace freestand_test_motion_test_generate
