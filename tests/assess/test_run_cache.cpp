// Simulation runs in the content-addressed cache (assess/run_cache.hpp): the key covers the
// model, the options and the excitation; a run read back is the run simulated, bit for bit.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <string>

#include "assess/run_cache.hpp"
#include "block/block.hpp"
#include "core/sha256.hpp"
#include "core/version.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_assess_test_run_cache {

namespace fs = std::filesystem;
using namespace freestand;
using namespace freestand::assess;

namespace {

struct Folder {
    fs::path path =
        fs::temp_directory_path() / ("freestand_run_cache_" + std::to_string(::getpid()));
    Folder() { fs::remove_all(path); }
    ~Folder() { fs::remove_all(path); }
};

dynamics::BlockModel slender() {
    return dynamics::make_block_model(block::Block::uniform(0.2, 0.6, 100.0), 0.5);
}

dynamics::FlexibleMode mode_at(double frequency_hz) {
    dynamics::FlexibleMode m;
    m.frequency_hz = frequency_hz;
    return m;
}

dynamics::SineSpec sine_spec(double amplitude_g) {
    dynamics::SineSpec s;
    s.amplitude_g = amplitude_g;
    s.frequency_hz = 2.0;
    s.duration_s = 2.0;
    return s;
}

dynamics::Excitation sine(double amplitude_g) {
    return dynamics::sine_excitation(sine_spec(amplitude_g));
}

dynamics::Options quiet() {
    dynamics::Options o;
    o.record_series = false;
    return o;
}

// The summary's bits apart from the integration's wall-clock time.
std::string bits(dynamics::Summary s) {
    s.wall_s = 0.0;
    return encode_summary(s);
}

}  // namespace

TEST_CASE("a run's summary encoded and decoded is the same summary, bit for bit",
          "[assess][cache][runs]") {
    const dynamics::Summary s = dynamics::simulate(slender(), sine(0.5), quiet()).summary;
    REQUIRE(s.rock_max_rad > 0.0);
    const std::string bytes = encode_summary(s);
    const auto back = decode_summary(bytes);
    REQUIRE(back);
    CHECK(encode_summary(*back) == bytes);
    CHECK(std::memcmp(&back->rock_max_over_alpha, &s.rock_max_over_alpha, sizeof(double)) == 0);
    CHECK(back->overturn_mode == s.overturn_mode);
    // Truncated or extended bytes are not a summary.
    CHECK_FALSE(decode_summary(bytes.substr(0, bytes.size() - 1)));
    CHECK_FALSE(decode_summary(bytes + "x"));
    const dynamics::FlexibleModel flex = dynamics::make_flexible_model(slender(), mode_at(8.0));
    const dynamics::FlexibleSummary f =
        dynamics::simulate_flexible(flex, sine(0.5), quiet()).summary;
    const auto f_back = decode_flexible_summary(encode_flexible_summary(f));
    REQUIRE(f_back);
    CHECK(encode_flexible_summary(*f_back) == encode_flexible_summary(f));
    CHECK_FALSE(decode_summary(encode_flexible_summary(f)));
}

TEST_CASE("a run's key changes with anything the run depends on", "[assess][cache][runs]") {
    const dynamics::BlockModel m = slender();
    const dynamics::Excitation ex = sine(0.5);
    const dynamics::Options o = quiet();
    const std::string key = rigid_run_key(m, excitation_key(ex), o);
    CHECK(key.size() == 64);
    CHECK(rigid_run_key(m, excitation_key(ex), o) == key);
    dynamics::BlockModel other_r = m;
    other_r.restitution = 0.9;
    CHECK(rigid_run_key(other_r, excitation_key(ex), o) != key);
    dynamics::BlockModel other_mu = m;
    other_mu.mu_k = 0.4;
    CHECK(rigid_run_key(other_mu, excitation_key(ex), o) != key);
    dynamics::Options other_g = o;
    other_g.g_mps2 = 9.80665;
    CHECK(rigid_run_key(m, excitation_key(ex), other_g) != key);
    dynamics::Excitation other_ex = ex;
    other_ex.horizontal_mps2[10] = std::nextafter(other_ex.horizontal_mps2[10], 1e9);
    CHECK(rigid_run_key(m, excitation_key(other_ex), o) != key);
    // The label names the excitation only.
    dynamics::Excitation renamed = ex;
    renamed.label = "another name";
    CHECK(rigid_run_key(m, excitation_key(renamed), o) == key);
    // One model and excitation, three kinds of run: three keys.
    const dynamics::FlexibleModel flex = dynamics::make_flexible_model(m, mode_at(8.0));
    CHECK(flexible_run_key(flex, excitation_key(ex), o) != key);
    dynamics::FlexibleModel stiffer = flex;
    stiffer.frequency_hz = 9.0;
    CHECK(flexible_run_key(stiffer, excitation_key(ex), o) !=
          flexible_run_key(flex, excitation_key(ex), o));
}

TEST_CASE("runs are read from the store when it holds them, simulated and stored when not",
          "[assess][cache][runs]") {
    const Folder folder;
    const core::ContentStore store(folder.path);
    const dynamics::BlockModel m = slender();
    const dynamics::Excitation ex = sine(0.5);
    const dynamics::Options o = quiet();
    const dynamics::Summary direct = dynamics::simulate(m, ex, o).summary;
    const dynamics::Summary first = rigid_run(&store, m, ex, excitation_key(ex), o);
    CHECK(bits(first) == bits(direct));
    REQUIRE(store.get(rigid_run_key(m, excitation_key(ex), o)));
    CHECK(store.info().entries == 1);
    // What the store holds under the key is what a run returns: plant a different summary.
    dynamics::Summary planted = direct;
    planted.slide_max_m = 123.0;
    REQUIRE(store.put(rigid_run_key(m, excitation_key(ex), o), encode_summary(planted)));
    CHECK(rigid_run(&store, m, ex, excitation_key(ex), o).slide_max_m == 123.0);
    // Bytes that are not a summary are simulated again and replaced.
    REQUIRE(store.put(rigid_run_key(m, excitation_key(ex), o), "not a summary"));
    CHECK(bits(rigid_run(&store, m, ex, excitation_key(ex), o)) == bits(direct));
    CHECK(decode_summary(*store.get(rigid_run_key(m, excitation_key(ex), o))));
    // Without a store, or with a series asked for, nothing is read or written.
    CHECK(rigid_run(nullptr, m, ex, excitation_key(ex), o).slide_max_m == direct.slide_max_m);
    dynamics::Options series = o;
    series.record_series = true;
    CHECK(rigid_run(&store, m, ex, excitation_key(ex), series).slide_max_m == direct.slide_max_m);
    CHECK(store.info().entries == 1);
    // The biaxial peak and the flexible body alike.
    const dynamics::BiaxialExcitation bi = dynamics::biaxial_sine_excitation(sine_spec(0.5), 90.0);
    const dynamics::BiaxialModel bm = dynamics::make_biaxial_model(0.3);
    dynamics::Options bo = dynamics::biaxial_options();
    bo.record_series = false;
    const double peak = dynamics::simulate_biaxial(bm, bi, bo).summary.slide_max_m;
    CHECK(biaxial_peak_run(&store, bm, bi, excitation_key(bi), bo) == peak);
    CHECK(biaxial_peak_run(&store, bm, bi, excitation_key(bi), bo) == peak);
    const dynamics::FlexibleModel flex = dynamics::make_flexible_model(m, mode_at(8.0));
    const auto f = flexible_run(&store, flex, ex, excitation_key(ex), o);
    CHECK(encode_flexible_summary(flexible_run(&store, flex, ex, excitation_key(ex), o)) ==
          encode_flexible_summary(f));
    CHECK(store.info().entries == 3);
}

TEST_CASE("a bank keeps one key per excitation, the key of its numbers", "[assess][cache][runs]") {
    ExcitationKeys keys;
    const dynamics::Excitation a = sine(0.5);
    const dynamics::Excitation b = sine(0.6);
    CHECK(keys.of(0, 0, 0.3, a) == excitation_key(a));
    // The first excitation met under an id keeps its key: the id names one excitation.
    CHECK(keys.of(0, 0, 0.3, b) == excitation_key(a));
    CHECK(keys.of(0, 1, 0.3, b) == excitation_key(b));
    CHECK(keys.of(1, 0, 0.3, b) == excitation_key(b));
    CHECK(keys.of(0, 0, 0.4, b) == excitation_key(b));
    CHECK(excitation_key(a) != excitation_key(b));
}

TEST_CASE("the engines' runs of reference scenes are unchanged at this engine_version",
          "[assess][cache][runs]") {
    // A change of the digest means a run's summary changed: raise engine_version (so no cache
    // serves an old engine's run) and update the version and the digests here. One digest per
    // preset that runs the tests (another compiler rounds differently; the key holds the build).
    CHECK(std::string(engine_version) == "2");
    const dynamics::Options o = quiet();
    const dynamics::Excitation ex = sine(0.5);
    dynamics::Summary rigid = dynamics::simulate(slender(), ex, o).summary;
    rigid.wall_s = 0.0;
    dynamics::FlexibleSummary flex =
        dynamics::simulate_flexible(dynamics::make_flexible_model(slender(), mode_at(8.0)), ex, o)
            .summary;
    flex.base.wall_s = 0.0;
    dynamics::Options bo = dynamics::biaxial_options();
    bo.record_series = false;
    const double peak =
        dynamics::simulate_biaxial(dynamics::make_biaxial_model(0.3),
                                   dynamics::biaxial_sine_excitation(sine_spec(0.5), 90.0), bo)
            .summary.slide_max_m;
    const std::string digest =
        core::sha256_hex(encode_summary(rigid) + encode_flexible_summary(flex) +
                         std::string(reinterpret_cast<const char*>(&peak), sizeof peak));
    const std::map<std::string, std::string> digests{
        {"GNU 12.2.0 x86_64; Release -O3 -DNDEBUG; sanitizers OFF", "90904f95a648dffd66b82c1d81c3c84682599b9905a198a4f72a18b35669b08c"},
        {"Clang 14.0.6 x86_64; RelWithDebInfo -O1 -g1 -DNDEBUG; sanitizers ON", "90904f95a648dffd66b82c1d81c3c84682599b9905a198a4f72a18b35669b08c"},
    };
    const std::string build = core::build_identity();
    INFO("build " << build << ": digest " << digest);
    REQUIRE(digests.count(build) == 1);  // a new build: add its digest above
    CHECK(digest == digests.at(build));
}

}  // namespace freestand_test_assess_test_run_cache
