// Fragility end to end on scenes with an exact answer, and its reproducibility (docs/methods.md
// s.9).
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "assess/case.hpp"
#include "fragility/fragility.hpp"
#include "support/sliding_sine.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_fragility_test_fragility {

namespace fs = std::filesystem;
using namespace freestand;

namespace {

using test::critical_mu;

struct Scene {
    fs::path dir;
    assess::Case c;
    std::string record;
};

// A block 4 m wide and 0.2 m tall (tan alpha = 20: it can only slide) with friction uniform on
// [0.1, 0.2], and a 2 Hz sine of unit amplitude for 5 s as a CSV record.
Scene sliding_scene() {
    Scene s;
    s.dir = fs::temp_directory_path() / ("freestand_fragility_" + std::to_string(::getpid()));
    fs::create_directories(s.dir);
    s.record = (s.dir / "sine.csv").string();
    {
        std::ofstream out(s.record);
        out << "time_s,accel_g\n";
        for (int i = 0; i <= 5000; ++i)
            out << i * 0.001 << "," << std::sin(2.0 * M_PI * 2.0 * i * 0.001) << "\n";
    }
    const fs::path case_file = s.dir / "slider.toml";
    std::ofstream(case_file) << R"([component]
name = "slider"
mass_kg = 100.0
width_m = 4.0
depth_m = 4.0
height_m = 0.2
mu_s = 0.15
restitution = 0.5
allowable_slide_m = 0.03
[site]
pga_g = [0.3]
[uncertainty]
mu_s = { dist = "uniform", lo = 0.1, hi = 0.2 }
)";
    s.c = assess::read_case(case_file);
    return s;
}

}  // namespace

TEST_CASE("a pure-sliding block under a sine: P(slide > allowable) is the exact probability",
          "[fragility][exact]") {
    const Scene s = sliding_scene();
    const double mu_star = critical_mu(0.3, 2.0, 5.0, 0.03);
    const double exact = (mu_star - 0.1) / (0.2 - 0.1);  // P(mu < mu*), mu uniform on [0.1, 0.2]
    INFO("mu* = " << mu_star << ", exact P = " << exact);
    REQUIRE(exact > 0.1);
    REQUIRE(exact < 0.9);
    fragility::Config cfg;
    cfg.pga_g = {0.3};
    cfg.samples = 400;
    cfg.seed = 7;
    cfg.record_files = {s.record};
    fragility::Runner runner(s.c, cfg);
    runner.prepare(assess::RunSettings(2));
    std::vector<std::size_t> all(runner.total());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    const fragility::Result r =
        fragility::aggregate(fragility::make_meta(s.c, cfg), fragility::run_samples(runner, all, 2));
    const fragility::Count& slide = r.levels[0].events[1];
    CHECK(slide.n == 400);
    // Binomial sampling error only: within 3.5 standard deviations of the exact value, and the
    // exact value inside the 95% interval.
    CHECK(std::abs(slide.p - exact) < 3.5 * std::sqrt(exact * (1.0 - exact) / 400.0));
    CHECK(slide.ci[0] <= exact);
    CHECK(slide.ci[1] >= exact);
    // Each sample individually: slides beyond the allowable exactly when its mu is below mu*
    // (a margin of 0.002 around mu* for the sampled sine and the grid of the reference).
    for (const fragility::SampleResult& x : r.samples) {
        if (std::abs(x.mu_s - mu_star) < 0.002) continue;
        CHECK((x.slide_max_m > 0.03) == (x.mu_s < mu_star));
        CHECK_FALSE(x.overturned);
        CHECK(x.rock_max_over_alpha == 0.0);
    }
    fs::remove_all(s.dir);
}

TEST_CASE("samples depend on (seed, level, sample) only: any threads, any subsets",
          "[fragility][reproducible]") {
    const Scene s = sliding_scene();
    fragility::Config cfg;
    cfg.pga_g = {0.2, 0.3, 0.4};
    cfg.samples = 20;
    cfg.seed = 11;
    cfg.record_files = {s.record};
    fragility::Runner runner(s.c, cfg);
    runner.prepare(assess::RunSettings(1));
    std::vector<std::size_t> all(runner.total());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    const auto one = fragility::run_samples(runner, all, 1);
    const auto two = fragility::run_samples(runner, all, 2);
    // Three "shards": every third index, run separately, in reverse order.
    std::vector<fragility::SampleResult> shards;
    for (std::size_t k = 0; k < 3; ++k) {
        std::vector<std::size_t> mine;
        for (std::size_t i = all.size(); i-- > 0;)
            if (i % 3 == k) mine.push_back(i);
        const auto part = fragility::run_samples(runner, mine, 2);
        shards.insert(shards.end(), part.begin(), part.end());
    }
    const fragility::Meta meta = fragility::make_meta(s.c, cfg);
    const auto a = fragility::aggregate(meta, one);
    const auto b = fragility::aggregate(meta, two);
    const auto c = fragility::aggregate(meta, shards);
    REQUIRE(a.samples.size() == 60);
    for (std::size_t i = 0; i < a.samples.size(); ++i) {
        CHECK(a.samples[i].mu_s == b.samples[i].mu_s);
        CHECK(a.samples[i].slide_max_m == b.samples[i].slide_max_m);
        CHECK(a.samples[i].mu_s == c.samples[i].mu_s);
        CHECK(a.samples[i].slide_max_m == c.samples[i].slide_max_m);
    }
    // Another seed draws other properties.
    cfg.seed = 12;
    fragility::Runner other(s.c, cfg);
    other.prepare(assess::RunSettings(1));
    CHECK(other.run(0).mu_s != a.samples[0].mu_s);
    // Missing or repeated samples are refused.
    auto missing = one;
    missing.pop_back();
    CHECK_THROWS_WITH(fragility::aggregate(meta, missing), Catch::Contains("expected 60 samples"));
    auto repeated = one;
    repeated[5] = repeated[4];
    CHECK_THROWS_WITH(fragility::aggregate(meta, repeated), Catch::Contains("missing or repeated"));
    fs::remove_all(s.dir);
}

TEST_CASE("fragility inputs are refused at their field", "[fragility][errors]") {
    fragility::Config cfg;
    CHECK_THROWS_WITH(fragility::validate(cfg), Catch::Contains("pga_g") && Catch::Contains("at least one"));
    cfg.pga_g = {0.3, 0.2};
    CHECK_THROWS_WITH(fragility::validate(cfg), Catch::Contains("strictly increasing"));
    cfg.pga_g = {0.2, 0.3};
    cfg.samples = 0;
    CHECK_THROWS_WITH(fragility::validate(cfg), Catch::Contains("samples"));
    cfg.samples = 10;
    cfg.pool = 0;
    CHECK_THROWS_WITH(fragility::validate(cfg), Catch::Contains("pool"));
}

}  // namespace freestand_test_fragility_test_fragility
