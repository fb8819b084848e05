// The history cache's keys and entries (assess/history_cache.hpp): a set read back is the set
// generated, bit for bit; every input of the generation moves the key; the generator's version
// is raised when its output changes; the bank reads what it can and generates the rest.
#include "assess/history_cache.hpp"

#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <map>
#include <set>

#include "assess/case.hpp"
#include "core/content_store.hpp"
#include "core/sha256.hpp"
#include "core/version.hpp"
#include "motion/fingerprint.hpp"
#include "spectra/design.hpp"
#include "support/paths.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_assess_test_history_cache {

namespace fs = std::filesystem;
using namespace freestand;
using namespace freestand::assess;

namespace {

motion::TargetSet unit_rg160() {
    motion::TargetSet t = motion::rg160_targets(1.0);
    motion::set_realism(t, motion::rg160_realism());
    return t;
}

const HistorySet& reference_set() {
    static const HistorySet set = [] {
        motion::GenerateOptions go;
        go.seed = 1;
        const motion::GeneratedSet g = motion::generate_set(unit_rg160(), go);
        HistorySet s;
        s.h1 = g.components.at(0).record;
        s.h2 = g.components.at(1).record;
        s.v = g.components.at(2).record;
        for (const auto& c : g.components) s.acceptance.push_back(c.acceptance);
        s.correlations = g.correlations;
        s.passed = g.passed;
        s.method = g.components.at(0).method;
        return s;
    }();
    return set;
}

// The shipped block-ts1 case with n history sets per level.
Case ts1_with_histories(int n) {
    Case c = read_case(fs::path(freestand::test::source_dir()) / "cases" / "block-ts1.toml");
    c.options.histories_per_level = n;
    c.options.max_histories_per_level = n;
    return c;
}

// An empty folder for a store, named after the test and the process.
fs::path empty_folder(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    return dir;
}

}  // namespace

TEST_CASE("a history set encoded and decoded is the same set, bit for bit", "[assess][cache]") {
    const HistorySet& set = reference_set();
    const std::string bytes = encode_history(set);
    const auto back = decode_history(bytes);
    REQUIRE(back);
    CHECK(encode_history(*back) == bytes);
    CHECK(back->h1.accel_mps2 == set.h1.accel_mps2);  // exact doubles
    CHECK(back->v.dt_s == set.v.dt_s);
    CHECK(back->acceptance.size() == 3);
    CHECK(back->acceptance[0].psd_min_ratio == set.acceptance[0].psd_min_ratio);
    CHECK(back->acceptance[2].realism.va_mps_per_g.has_value() ==
          set.acceptance[2].realism.va_mps_per_g.has_value());
    CHECK(back->correlations.size() == set.correlations.size());
    CHECK(back->method == set.method);
    // Truncated, extended or of another format: not a set.
    CHECK_FALSE(decode_history(bytes.substr(0, bytes.size() - 1)));
    CHECK_FALSE(decode_history(bytes + "x"));
    CHECK_FALSE(decode_history(""));
    std::string other = bytes;
    other[0] = 9;
    CHECK_FALSE(decode_history(other));
}

TEST_CASE("the generator's output for a reference request is unchanged at this generator_version",
          "[assess][cache]") {
    // A change of a digest means generated sets changed: raise motion::generator_version (so no
    // cache serves an old set for a new request) and update the version and the digests here.
    // The digest covers the whole set (the records' bits and the acceptance reports) and differs
    // between builds (another compiler rounds some operations differently; the cache key holds
    // the build for that reason): one per preset that runs the tests.
    CHECK(std::string(motion::generator_version) == "1");
    const std::map<std::string, std::string> digests{
        {"GNU 12.2.0 x86_64; Release -O3 -DNDEBUG; sanitizers OFF",
         "b412c14cecfc0f4b959b0f7548a5de39c6d75b85d83e80d88486eae2880635ff"},
        {"Clang 14.0.6 x86_64; RelWithDebInfo -O1 -g1 -DNDEBUG; sanitizers ON",
         "e97422e2bb7cef21326c0ba9c4d29418acc42605cc116d752d6d5e51e4bd4e1a"},
    };
    const std::string build = core::build_identity();
    const std::string digest = core::sha256_hex(encode_history(reference_set()));
    INFO("build " << build << ": digest " << digest);
    REQUIRE(digests.count(build) == 1);  // a new build: add its digest above
    CHECK(digest == digests.at(build));
}

TEST_CASE("every input of a generation moves the cache key", "[assess][cache]") {
    const motion::TargetSet t = unit_rg160();
    motion::GenerateOptions go;
    go.seed = 7;
    std::set<std::string> keys;
    const auto add = [&](const motion::TargetSet& tt, const motion::GenerateOptions& o,
                         std::uint64_t case_seed, std::size_t k) {
        return keys.insert(history_key(tt, o, case_seed, k)).second;
    };
    CHECK(add(t, go, 1, 0));
    CHECK_FALSE(add(t, go, 1, 0));  // the same request, the same key
    CHECK(add(t, go, 2, 0));
    CHECK(add(t, go, 1, 1));
    auto o = go;
    o.seed = 8;
    CHECK(add(t, o, 1, 0));
    o = go;
    o.dt_s = 0.004;
    CHECK(add(t, o, 1, 0));
    o = go;
    o.match.aim = 1.06;
    CHECK(add(t, o, 1, 0));
    o = go;
    o.envelope.strong_s = 11.0;
    CHECK(add(t, o, 1, 0));
    o = go;
    o.seed_records.push_back(core::Record{"r", "s", "h1", 0.01, {0.0, 1.0, 0.0}});
    CHECK(add(t, o, 1, 0));
    o.seed_records.back().accel_mps2[1] = std::nextafter(1.0, 2.0);
    CHECK(add(t, o, 1, 0));
    auto tt = t;
    tt.horizontal.psa_5pct.psa_g[10] *= 1.0 + 1e-15;
    CHECK(add(tt, go, 1, 0));
    tt = t;
    tt.vertical.realism.d5_75_min_s = 5.0;
    CHECK(add(tt, go, 1, 0));
    // The vertical target itself (RG 1.60's vertical spectrum against a ratio of the horizontal).
    tt = t;
    tt.vertical.psa_5pct.psa_g[10] *= 1.0 + 1e-15;
    CHECK(add(tt, go, 1, 0));
    CHECK(add(motion::rg160_targets(1.0, 2.0 / 3.0), go, 1, 0));
    tt = t;
    tt.horizontal_2 = t.horizontal;
    CHECK(add(tt, go, 1, 0));
    // The targets' unit g (a case's site.g_mps2): alone, and with the RG 1.60 spectra drawn in it.
    tt = t;
    tt.vertical.g_mps2 = 9.80665;
    CHECK(add(tt, go, 1, 0));
    CHECK(add(motion::rg160_targets(1.0, 1.0, 9.80665), go, 1, 0));
}

TEST_CASE("a set cached for one gravity is never served to a case at another",
          "[assess][cache][gravity]") {
    const fs::path dir = empty_folder("freestand_bank_g");
    const core::ContentStore store(dir);
    Case c = ts1_with_histories(1);
    RunSettings run(2);
    run.cache = &store;
    REQUIRE(c.site.g_mps2 == 9.81);
    HistoryBank thesis(c, run);
    const auto at_thesis_g = thesis.sets();
    CHECK(thesis.generated_sets() == 1);
    c.site.g_mps2 = 9.80665;
    HistoryBank standard(c, run);
    const auto at_standard_g = standard.sets();
    CHECK(standard.cache_hits() == 0);
    CHECK(standard.generated_sets() == 1);
    // Matched to the same spectrum in a smaller unit g: a weaker record in m/s^2.
    CHECK(encode_history(at_standard_g[0]) != encode_history(at_thesis_g[0]));
    c.site.g_mps2 = 9.81;
    HistoryBank again(c, run);
    CHECK(encode_history(again.sets()[0]) == encode_history(at_thesis_g[0]));
    CHECK(again.cache_hits() == 1);
    fs::remove_all(dir);
}

TEST_CASE("the bank reads what the cache holds and generates the rest", "[assess][cache]") {
    const fs::path dir = empty_folder("freestand_bank");
    const core::ContentStore store(dir);
    Case c = ts1_with_histories(2);
    RunSettings run(2);
    run.cache = &store;
    HistoryBank first(c, run);
    const auto fresh = first.sets();
    CHECK(first.generated_sets() == 2);
    CHECK(first.cache_hits() == 0);
    c.options.histories_per_level = 3;
    c.options.max_histories_per_level = c.options.histories_per_level;
    HistoryBank second(c, run);
    const auto more = second.sets();
    CHECK(second.cache_hits() == 2);
    CHECK(second.generated_sets() == 1);
    for (std::size_t k = 0; k < 2; ++k) CHECK(encode_history(more[k]) == encode_history(fresh[k]));
    HistoryBank uncached(c, RunSettings(1));
    for (std::size_t k = 0; k < 3; ++k)
        CHECK(encode_history(uncached.sets()[k]) == encode_history(more[k]));
    fs::remove_all(dir);
}

}  // namespace freestand_test_assess_test_history_cache
