// The models a fragility sample runs (fragility::Models): the flexible body at the levels and
// directions asked for, biaxial sliding for a sample that only slides, the 3D body for one that
// rocks; the default is the rigid planar block.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "assess/body3d_level.hpp"
#include "assess/case.hpp"
#include "assess/histories.hpp"
#include "core/content_store.hpp"
#include "dynamics/biaxial.hpp"
#include "dynamics/body3d.hpp"
#include "fragility/fragility.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_fragility_test_models {

namespace fs = std::filesystem;
using namespace freestand;

namespace {

fs::path scratch(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("freestand_models_" + name + "_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

// A block 4 m wide and 0.4 m tall (tan alpha = 10: it only slides), friction 0.1-0.2.
const char* slider_toml = R"([component]
name = "slider"
mass_kg = 100.0
width_m = 4.0
depth_m = 4.0
height_m = 0.4
mu_s = 0.15
restitution = 0.5
allowable_slide_m = 0.03
[site]
pga_g = [0.3]
[options]
histories_per_level = 1
)";

// A block 0.4 x 0.5 m, 1.6 m tall (tan alpha 0.25 and 0.31) on steel: at 0.5 g it rocks.
const char* rocker_toml = R"([component]
name = "rocker"
mass_kg = 150.0
width_m = 0.4
depth_m = 0.5
height_m = 1.6
base_material = "steel"
allowable_slide_m = 0.03
[site]
pga_g = [0.5]
[options]
histories_per_level = 1
)";

std::vector<fragility::SampleResult> run(const assess::Case& c, const fragility::Config& cfg,
                                         const assess::RunSettings& settings) {
    fragility::Runner runner(c, cfg);
    runner.prepare(settings);
    std::vector<std::size_t> all(runner.total());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    return fragility::run_samples(runner, all, 1);
}

// One thread, the history sets from `cache` (shared by the runs compared).
assess::RunSettings cached(const core::ContentStore& cache) {
    assess::RunSettings settings(1);
    settings.cache = &cache;
    return settings;
}

// Three samples at one level from a pool of one history set.
fragility::Config three_samples_at(double pga_g) {
    fragility::Config cfg;
    cfg.pga_g = {pga_g};
    cfg.samples = 3;
    cfg.pool = 1;
    return cfg;
}

// The pool's one history set (from the cache the runs filled) at pga_g, as the whole body
// takes it.
dynamics::BiaxialExcitation first_set(const assess::Case& c, const assess::RunSettings& settings,
                                      double pga_g) {
    assess::HistoryBank bank(c, settings);
    const assess::HistorySet& set = bank.sets().front();
    return dynamics::biaxial_excitation_from_records(set.h1, set.h2, pga_g, &set.v);
}

}  // namespace

TEST_CASE("the flexible body runs at the levels and directions asked for, and only there",
          "[fragility][models]") {
    const fs::path dir = scratch("flexible");
    const std::string record = (dir / "sine.csv").string();
    {
        std::ofstream out(record);
        out << "time_s,accel_g\n";
        for (int i = 0; i <= 4000; ++i)
            out << i * 0.001 << "," << std::sin(2.0 * M_PI * 2.5 * i * 0.001) << "\n";
    }
    assess::Case c = assess::parse_case(slider_toml, (dir / "slider.toml").string());
    c.component.fixed_base_frequency_hz = 3.0;  // a mode near the 2.5 Hz drive
    fragility::Config cfg;
    cfg.pga_g = {0.3, 0.4};
    cfg.samples = 4;
    cfg.record_files = {record};
    const auto rigid = run(c, cfg, assess::RunSettings(1));
    cfg.models.flexible = {{true, true}, {false, false}};
    const auto flexible = run(c, cfg, assess::RunSettings(1));
    REQUIRE(rigid.size() == 8);
    for (std::size_t i = 0; i < rigid.size(); ++i) {
        INFO("sample " << i);
        CHECK(flexible[i].mu_s == rigid[i].mu_s);  // the same draws
        if (i < 4)
            CHECK(flexible[i].slide_max_m != rigid[i].slide_max_m);
        else
            CHECK(flexible[i].slide_max_m == rigid[i].slide_max_m);
    }
    cfg.models.flexible = {{true, true}};
    CHECK_THROWS_WITH(
        fragility::validate(cfg),
        Catch::Contains("models") && Catch::Contains("1 flexible-body entries for 2"));
    cfg.models.flexible.clear();
    cfg.models.biaxial_slide = true;
    CHECK_THROWS_WITH(fragility::validate(cfg),
                      Catch::Contains("models") && Catch::Contains("generated three-component"));
    cfg.models.biaxial_slide = false;
    cfg.models.body3d = true;
    CHECK_THROWS_WITH(fragility::validate(cfg), Catch::Contains("models") &&
                                                    Catch::Contains("the 3D body needs generated"));
    fs::remove_all(dir);
}

TEST_CASE("a sample that only slides takes its slide from biaxial sliding", "[fragility][models]") {
    const fs::path dir = scratch("biaxial");
    const core::ContentStore cache(dir / "cache");
    assess::RunSettings settings(1);
    settings.cache = &cache;
    const assess::Case c = assess::parse_case(slider_toml, (dir / "slider.toml").string());
    fragility::Config cfg;
    cfg.pga_g = {0.3};
    cfg.samples = 3;
    cfg.pool = 1;
    const auto planar = run(c, cfg, settings);
    cfg.models.biaxial_slide = true;
    const auto biaxial = run(c, cfg, settings);
    // The same set (from the cache) run directly: both horizontals at once, the sample's friction.
    assess::HistoryBank bank(c, settings);
    const assess::HistorySet& set = bank.sets().front();
    const auto ex = dynamics::biaxial_excitation_from_records(set.h1, set.h2, 0.3, &set.v);
    dynamics::Options opt = dynamics::biaxial_options();
    opt.record_series = false;
    for (std::size_t i = 0; i < planar.size(); ++i) {
        INFO("sample " << i << ", mu_s " << biaxial[i].mu_s);
        const auto model = dynamics::make_biaxial_model(biaxial[i].mu_s, biaxial[i].mu_s);
        const double direct = dynamics::simulate_biaxial(model, ex, opt).summary.slide_max_m;
        CHECK(biaxial[i].slide_max_m == direct);
        CHECK(biaxial[i].slide_max_m != planar[i].slide_max_m);
        CHECK(biaxial[i].rock_max_over_alpha == planar[i].rock_max_over_alpha);
    }
    fs::remove_all(dir);
}

TEST_CASE("a sample that rocks runs the 3D body with its friction and restitution, one that "
          "only slides does not",
          "[fragility][models]") {
    const fs::path dir = scratch("body3d");
    const core::ContentStore cache(dir / "cache");
    const assess::RunSettings settings = cached(cache);
    fragility::Config cfg = three_samples_at(0.5);
    const assess::Case rocker = assess::parse_case(rocker_toml, (dir / "rocker.toml").string());
    const auto planar = run(rocker, cfg, settings);
    cfg.models.biaxial_slide = true;
    cfg.models.body3d = true;
    const auto whole = run(rocker, cfg, settings);
    // The same set (from the cache) run directly with the 3D body of the assessment.
    const auto ex = first_set(rocker, settings, 0.5);
    for (std::size_t i = 0; i < whole.size(); ++i) {
        INFO("sample " << i << ", mu_s " << whole[i].mu_s << ", r " << whole[i].restitution_x);
        const double r = std::max(whole[i].restitution_x, whole[i].restitution_y);
        const auto model = dynamics::make_body3d_model(assess::component_body3d(rocker.component),
                                                       whole[i].mu_s, whole[i].mu_s, 0.0, r);
        const auto direct =
            dynamics::simulate_body3d(model, ex, assess::body3d_options(9.81)).summary;
        REQUIRE(planar[i].rock_max_over_alpha > 0.01);  // it rocks
        CHECK(whole[i].rock_max_over_alpha == direct.tilt_max_over_critical);
        CHECK(whole[i].overturned == direct.overturned);
        CHECK(whole[i].slide_max_m == (direct.overturned ? 0.0 : direct.slide_max_m));
        CHECK(whole[i].rock_max_over_alpha != planar[i].rock_max_over_alpha);
    }
    // A block that cannot rock keeps the biaxial slide with the 3D body turned on.
    const assess::Case slider = assess::parse_case(slider_toml, (dir / "slider.toml").string());
    cfg.pga_g = {0.3};
    const auto slides = run(slider, cfg, settings);
    cfg.models.body3d = false;
    const auto biaxial = run(slider, cfg, settings);
    for (std::size_t i = 0; i < slides.size(); ++i) {
        CHECK(slides[i].slide_max_m == biaxial[i].slide_max_m);
        CHECK(slides[i].rock_max_over_alpha == 0.0);
    }
    fs::remove_all(dir);
}

TEST_CASE("at a flagged level a sample that rocks runs the 3D body carrying the case's mode, in "
          "place of the planar flexible runs",
          "[fragility][models][flexible]") {
    const fs::path dir = scratch("body3d_mode");
    const core::ContentStore cache(dir / "cache");
    const assess::RunSettings settings = cached(cache);
    fragility::Config cfg = three_samples_at(0.5);
    cfg.models.biaxial_slide = true;
    cfg.models.body3d = true;
    cfg.models.flexible = {{true, true}};
    const std::string toml =
        std::string(rocker_toml).replace(std::string(rocker_toml).find("[site]"), 6,
                                         "fixed_base_frequency_hz = 8.0\n[site]");
    const assess::Case c = assess::parse_case(toml, (dir / "rocker.toml").string());
    const auto samples = run(c, cfg, settings);
    const auto ex = first_set(c, settings, 0.5);
    for (std::size_t i = 0; i < samples.size(); ++i) {
        INFO("sample " << i << ", mu_s " << samples[i].mu_s);
        const double r = std::max(samples[i].restitution_x, samples[i].restitution_y);
        const auto rigid = dynamics::make_body3d_model(assess::component_body3d(c.component),
                                                       samples[i].mu_s, samples[i].mu_s, 0.0, r);
        const auto mode =
            assess::body3d_mode(c.component, {samples[i].mu_s, samples[i].mu_s, r, false, ""});
        CHECK(mode.frequency_x_hz == 8.0);
        const auto direct = dynamics::simulate_body3d(dynamics::with_mode(rigid, mode), ex,
                                                      assess::body3d_options(9.81))
                                .summary;
        const auto without = dynamics::simulate_body3d(rigid, ex, assess::body3d_options(9.81))
                                 .summary;
        CHECK(samples[i].rock_max_over_alpha == direct.tilt_max_over_critical);
        CHECK(samples[i].overturned == direct.overturned);
        CHECK(samples[i].slide_max_m == (direct.overturned ? 0.0 : direct.slide_max_m));
        CHECK(direct.tilt_max_over_critical != without.tilt_max_over_critical);
    }
    fs::remove_all(dir);
}

}  // namespace freestand_test_fragility_test_models
