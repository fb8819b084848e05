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
#include "dynamics/body3d.hpp"
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

std::string bits(dynamics::Body3dSummary s) {
    s.wall_s = 0.0;
    return encode_body3d_summary(s);
}

// A slender box (it rocks under the diagonal sine) and the same body carrying an 8 Hz mode.
dynamics::Body3dModel box3d() {
    return dynamics::make_body3d_model(dynamics::box_body(0.2, 0.25, 0.6, 100.0), 0.5);
}

dynamics::Body3dModel box3d_with_mode(double frequency_hz = 8.0) {
    return dynamics::with_mode(box3d(), {frequency_hz, frequency_hz, 0.02, 0.4, 0.9});
}

dynamics::BiaxialExcitation diagonal_sine(double amplitude_g) {
    return dynamics::biaxial_sine_excitation(sine_spec(amplitude_g), 0.0);
}

dynamics::Body3dOptions quiet3d() {
    dynamics::Body3dOptions o;
    o.dt_s = 2.5e-4;
    o.tail_s = 1.0;
    o.record_series = false;
    return o;
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
    const dynamics::Body3dSummary b =
        dynamics::simulate_body3d(box3d_with_mode(), diagonal_sine(0.5), quiet3d()).summary;
    REQUIRE(b.tilt_max_rad > 0.0);
    REQUIRE(b.modal_max_m > 0.0);
    const std::string b_bytes = encode_body3d_summary(b);
    const auto b_back = decode_body3d_summary(b_bytes);
    REQUIRE(b_back);
    CHECK(encode_body3d_summary(*b_back) == b_bytes);
    CHECK(std::memcmp(&b_back->slide_max_m, &b.slide_max_m, sizeof(double)) == 0);
    CHECK(b_back->time_in_state_s == b.time_in_state_s);
    CHECK(b_back->phase_time_s == b.phase_time_s);
    CHECK_FALSE(decode_body3d_summary(b_bytes.substr(0, b_bytes.size() - 1)));
    CHECK_FALSE(decode_body3d_summary(encode_flexible_summary(f)));
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
    // The 3D body: its model, its mode, its options and its excitation.
    const dynamics::BiaxialExcitation bi = diagonal_sine(0.5);
    const dynamics::Body3dOptions o3 = quiet3d();
    const std::string key3 = body3d_run_key(box3d(), excitation_key(bi), o3);
    CHECK(key3.size() == 64);
    CHECK(body3d_run_key(box3d(), excitation_key(bi), o3) == key3);
    CHECK(body3d_run_key(box3d_with_mode(), excitation_key(bi), o3) != key3);
    CHECK(body3d_run_key(box3d_with_mode(9.0), excitation_key(bi), o3) !=
          body3d_run_key(box3d_with_mode(), excitation_key(bi), o3));
    dynamics::Body3dModel restituted = box3d();
    restituted.angular_restitution = 0.9;
    CHECK(body3d_run_key(restituted, excitation_key(bi), o3) != key3);
    dynamics::Body3dModel wider = box3d();
    wider.body.footprint_m[0].x() -= 0.01;
    CHECK(body3d_run_key(wider, excitation_key(bi), o3) != key3);
    dynamics::Body3dOptions finer = o3;
    finer.dt_s = 1.25e-4;
    CHECK(body3d_run_key(box3d(), excitation_key(bi), finer) != key3);
    dynamics::Body3dOptions fewer = o3;
    fewer.max_sweeps = 100;
    CHECK(body3d_run_key(box3d(), excitation_key(bi), fewer) != key3);
    dynamics::Body3dOptions stepped = o3;
    stepped.phases = false;
    CHECK(body3d_run_key(box3d(), excitation_key(bi), stepped) != key3);
    CHECK(body3d_run_key(box3d(), excitation_key(diagonal_sine(0.6)), o3) != key3);
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
    // The 3D body alike, with its mode: stored once, then read.
    const dynamics::BiaxialExcitation diagonal = diagonal_sine(0.5);
    const dynamics::Body3dModel body = box3d_with_mode();
    const dynamics::Body3dSummary b = dynamics::simulate_body3d(body, diagonal, quiet3d()).summary;
    CHECK(bits(body3d_run(&store, body, diagonal, excitation_key(diagonal), quiet3d())) ==
          bits(b));
    CHECK(store.info().entries == 4);
    dynamics::Body3dSummary planted3 = b;
    planted3.slide_max_m = 7.0;
    REQUIRE(store.put(body3d_run_key(body, excitation_key(diagonal), quiet3d()),
                      encode_body3d_summary(planted3)));
    CHECK(body3d_run(&store, body, diagonal, excitation_key(diagonal), quiet3d()).slide_max_m ==
          7.0);
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
    CHECK(std::string(engine_version) == "6");
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
        {"GNU 12.2.0 x86_64; Release -O3 -DNDEBUG; sanitizers OFF", "ca8d9f4072fbbf9c04a427b91856c6a443aeaac9561cc24461208d1a7863a739"},
        {"Clang 14.0.6 x86_64; RelWithDebInfo -O1 -g1 -DNDEBUG; sanitizers ON", "ca8d9f4072fbbf9c04a427b91856c6a443aeaac9561cc24461208d1a7863a739"},
    };
    const std::string build = core::build_identity();
    INFO("build " << build << ": digest " << digest);
    REQUIRE(digests.count(build) == 1);  // a new build: add its digest above
    CHECK(digest == digests.at(build));
}

TEST_CASE("the 3D body's runs of reference scenes are unchanged at this engine_version",
          "[assess][cache][runs][3d]") {
    // As above, for the 3D body, rigid, carrying a mode and with a restitution, under a sine.
    CHECK(std::string(engine_version) == "6");
    dynamics::Body3dSummary rigid =
        dynamics::simulate_body3d(box3d(), diagonal_sine(0.5), quiet3d()).summary;
    dynamics::Body3dSummary modal =
        dynamics::simulate_body3d(box3d_with_mode(), diagonal_sine(0.5), quiet3d()).summary;
    dynamics::Body3dModel restituted_model = box3d();
    restituted_model.angular_restitution = 0.98;
    dynamics::Body3dSummary restituted =
        dynamics::simulate_body3d(restituted_model, diagonal_sine(0.5), quiet3d()).summary;
    REQUIRE(rigid.phase_time_s[0] > 0.0);  // the digest covers the phases taken whole
    rigid.wall_s = 0.0;
    modal.wall_s = 0.0;
    restituted.wall_s = 0.0;
    const std::string digest =
        core::sha256_hex(encode_body3d_summary(rigid) + encode_body3d_summary(modal) +
                         encode_body3d_summary(restituted));
    const std::map<std::string, std::string> digests{
        {"GNU 12.2.0 x86_64; Release -O3 -DNDEBUG; sanitizers OFF", "70e8293c091a50108ea2094087ee3a57a5e1122e69006ea5c20872f5afd5db69"},
        {"Clang 14.0.6 x86_64; RelWithDebInfo -O1 -g1 -DNDEBUG; sanitizers ON", "70e8293c091a50108ea2094087ee3a57a5e1122e69006ea5c20872f5afd5db69"},
    };
    const std::string build = core::build_identity();
    INFO("build " << build << ": digest " << digest);
    REQUIRE(digests.count(build) == 1);  // a new build: add its digest above
    CHECK(digest == digests.at(build));
}

}  // namespace freestand_test_assess_test_run_cache
