// The history cache and the thread count from the command line: assess, fragility (shards
// included) and batch write the same bytes with any thread count, without the cache, with a
// cold one and a warm one, and after an entry was damaged; `freestand cache` and its errors.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/paths.hpp"
#include "support/run_cli.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_cli_test_cache_cli {

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using freestand::test::run_cli;
using freestand::test::slurp;

namespace {

struct Dir {
    fs::path path;
    explicit Dir(const std::string& tag)
        : path(fs::temp_directory_path() /
               ("freestand_cachecli_" + tag + "_" + std::to_string(::getpid()))) {
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~Dir() { fs::remove_all(path); }
    std::string operator/(const std::string& name) const { return "'" + (path / name).string() + "'"; }
};

std::vector<fs::path> entries(const fs::path& cache) {
    std::vector<fs::path> out;
    if (!fs::exists(cache)) return out;
    for (const auto& e : fs::directory_iterator(cache))
        if (e.path().extension() == ".entry") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

// Every file of a (flat) output folder, by name.
void check_same_folder(const fs::path& a, const fs::path& b) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(a)) names.push_back(e.path().filename().string());
    std::size_t in_b = 0;
    for (const auto& e : fs::directory_iterator(b)) in_b += e.path().filename() != "" ? 1 : 0;
    CHECK(names.size() == in_b);
    for (const std::string& n : names) {
        INFO(n);
        REQUIRE(fs::exists(b / n));
        if (fs::is_regular_file(a / n)) CHECK(slurp(a / n) == slurp(b / n));
    }
}

}  // namespace

TEST_CASE("assess writes the same bytes at any thread count, with or without the history cache",
          "[cli][cache][reproducible]") {
    const Dir d("assess");
    const std::string cache = (d.path / "cache").string();
    const std::string base = "assess cases/glovebox-single.toml --pga 0.2 --out ";
    const auto reference = run_cli(base + (d / "none") + " --no-cache --threads 1");
    REQUIRE(reference.exit_code == 0);
    CHECK(entries(cache).empty());
    const auto cold = run_cli(base + (d / "cold") + " --cache '" + cache + "' --threads 2");
    REQUIRE(cold.exit_code == 0);
    const auto stored = entries(cache);
    // The sets the run used: the case's histories_per_level, 30 more per batch an unsettled
    // level needed.
    CHECK(stored.size() >= 30);
    CHECK(stored.size() % 30 == 0);
    // The runs are cached beside the sets (runs/); the warm run reads them all and adds none.
    const auto runs = entries(d.path / "cache" / "runs");
    CHECK_FALSE(runs.empty());
    const auto warm = run_cli(base + (d / "warm") + " --cache '" + cache + "'");
    REQUIRE(warm.exit_code == 0);
    CHECK(entries(cache) == stored);
    CHECK(entries(d.path / "cache" / "runs") == runs);
    // A damaged entry is detected, regenerated and rewritten; the outputs do not change.
    {
        std::string bytes = slurp(stored[3]);
        bytes[bytes.size() / 3] ^= 0x10;
        std::ofstream(stored[3], std::ios::binary | std::ios::trunc) << bytes;
    }
    const auto repaired = run_cli(base + (d / "repaired") + " --cache '" + cache + "' --threads 3");
    REQUIRE(repaired.exit_code == 0);
    CHECK(entries(cache) == stored);
    for (const char* out : {"cold", "warm", "repaired"}) {
        INFO(out);
        check_same_folder(d.path / "none", d.path / out);
    }
    // The verdict line is the same; only the timing differs.
    CHECK(reference.out.substr(0, reference.out.find('\n')) == warm.out.substr(0, warm.out.find('\n')));
}

TEST_CASE("fragility shards read the pool from a filled cache and merge to the single run's bytes",
          "[cli][cache][reproducible]") {
    const Dir d("shards");
    const std::string cache = " --cache '" + (d.path / "cache").string() + "'";
    const std::string run = "fragility cases/block-ts1.toml --pga 0.2,0.5 --samples 6 --pool 3";
    REQUIRE(run_cli(run + " --no-cache --threads 1 --out " + (d / "single")).exit_code == 0);
    const auto filled = run_cli("cache fill cases/block-ts1.toml --sets 3" + cache);
    INFO(filled.err);
    REQUIRE(filled.exit_code == 0);
    CHECK_THAT(filled.out, Contains("3 history sets") && Contains("0 already there, 3 generated"));
    const auto again = run_cli("cache fill cases/block-ts1.toml --sets 3" + cache);
    CHECK_THAT(again.out, Contains("3 already there, 0 generated"));
    for (int k = 1; k <= 2; ++k)
        REQUIRE(run_cli(run + cache + " --shard " + std::to_string(k) + "/2 --out " + (d / "shards"))
                    .exit_code == 0);
    REQUIRE(run_cli("merge " + (d / "shards") + " --out " + (d / "merged")).exit_code == 0);
    REQUIRE(run_cli(run + cache + " --threads 2 --out " + (d / "threads")).exit_code == 0);
    for (const char* f : {"fragility.json", "samples.csv", "report.md", "report.html"}) {
        INFO(f);
        CHECK(slurp(d.path / "single" / f) == slurp(d.path / "merged" / f));
        CHECK(slurp(d.path / "single" / f) == slurp(d.path / "threads" / f));
    }
}

TEST_CASE("fragility --models case shards merge to the single run's bytes, and never with planar "
          "shards",
          "[cli][cache][reproducible]") {
    const Dir d("case_models");
    const std::string cache = " --cache '" + (d.path / "cache").string() + "'";
    // TS2 at 0.4 g rocks: its samples run the 3D body.
    const std::string run =
        "fragility cases/block-ts2.toml --pga 0.4 --samples 4 --pool 2 --models case" + cache;
    REQUIRE(run_cli(run + " --out " + (d / "single")).exit_code == 0);
    for (int k = 1; k <= 2; ++k)
        REQUIRE(run_cli(run + " --shard " + std::to_string(k) + "/2 --out " + (d / "shards"))
                    .exit_code == 0);
    REQUIRE(run_cli("merge " + (d / "shards") + " --out " + (d / "merged")).exit_code == 0);
    for (const char* f : {"fragility.json", "samples.csv", "report.md"}) {
        INFO(f);
        CHECK(slurp(d.path / "single" / f) == slurp(d.path / "merged" / f));
    }
    CHECK_THAT(slurp(d.path / "merged" / "report.md"), Contains("runs the 3D rigid body"));
    // A planar shard 2 of 2 beside the case-models shard 1 of 2: another run.
    const std::string planar =
        "fragility cases/block-ts2.toml --pga 0.4 --samples 4 --pool 2" + cache;
    REQUIRE(run_cli(run + " --shard 1/2 --out " + (d / "mixed")).exit_code == 0);
    REQUIRE(run_cli(planar + " --shard 2/2 --out " + (d / "mixed")).exit_code == 0);
    const auto mixed = run_cli("merge " + (d / "mixed") + " --out " + (d / "bad"));
    CHECK(mixed.exit_code == 3);
    CHECK_THAT(mixed.err, Contains("belongs to another run"));
}

TEST_CASE("batch writes the same bytes with and without the cache", "[cli][cache][reproducible]") {
    const Dir d("batch");
    fs::create_directories(d.path / "cases");
    // TS3: simulated at one level only (0.4 g), so three batch runs stay cheap.
    fs::copy_file(freestand::test::source_dir() + "/cases/block-ts3.toml",
                  d.path / "cases" / "block-ts3.toml");
    const std::string list = (d / "cases");
    REQUIRE(run_cli("batch " + list + " --no-cache --threads 1 --out " + (d / "a")).exit_code == 0);
    const std::string cache = " --cache '" + (d.path / "cache").string() + "'";
    REQUIRE(run_cli("batch " + list + cache + " --out " + (d / "b")).exit_code == 0);
    REQUIRE(run_cli("batch " + list + cache + " --threads 2 --out " + (d / "c")).exit_code == 0);
    CHECK_FALSE(entries(d.path / "cache").empty());
    for (const char* f : {"summary.json", "summary.md", "block-ts3/result.json",
                          "block-ts3/report.html"}) {
        INFO(f);
        CHECK(slurp(d.path / "a" / f) == slurp(d.path / "b" / f));
        CHECK(slurp(d.path / "a" / f) == slurp(d.path / "c" / f));
    }
}

TEST_CASE("freestand cache info and clear report the folder, clear leaves other files",
          "[cli][cache]") {
    const Dir d("info");
    const std::string cache = " --cache '" + (d.path / "cache").string() + "'";
    REQUIRE(run_cli("cache fill cases/block-ts1.toml --sets 2 --threads 1" + cache).exit_code == 0);
    std::ofstream(d.path / "cache" / "notes.txt") << "mine";
    const auto info = run_cli("cache info" + cache);
    REQUIRE(info.exit_code == 0);
    CHECK_THAT(info.out, Contains(": 2 entries (history sets), ") && Contains(" MiB of 1024 MiB"));
    // cache fill simulates nothing: the runs' folder is empty.
    CHECK_THAT(info.out, Contains("runs: 0 entries (runs), "));
    const auto bound = run_cli("cache info" + cache, "FREESTAND_CACHE_MAX_MB=5 ");
    CHECK_THAT(bound.out, Contains("of 5 MiB"));
    const auto cleared = run_cli("cache clear" + cache);
    REQUIRE(cleared.exit_code == 0);
    CHECK_THAT(cleared.out, Contains("removed 2 files"));
    CHECK(fs::exists(d.path / "cache" / "notes.txt"));
    CHECK_THAT(run_cli("cache info" + cache).out, Contains(": 0 entries"));
}

TEST_CASE("cache and run options are checked before anything runs", "[cli][cache][errors]") {
    const Dir d("errors");
    const auto both = run_cli("assess cases/block-ts1.toml --no-cache --cache " + (d / "c") +
                              " --out " + (d / "o"));
    CHECK(both.exit_code == 2);
    CHECK_THAT(both.err, Contains("--cache and --no-cache: give one"));
    CHECK_FALSE(fs::exists(d.path / "o"));
    const auto bad_mb = run_cli("assess cases/block-ts1.toml --out " + (d / "o"),
                                "FREESTAND_CACHE_MAX_MB=lots ");
    CHECK(bad_mb.exit_code == 3);
    CHECK_THAT(bad_mb.err, Contains("FREESTAND_CACHE_MAX_MB") && Contains("'lots'"));
    CHECK_FALSE(fs::exists(d.path / "o"));
    const auto threads = run_cli("assess cases/block-ts1.toml --threads -1 --out " + (d / "o"));
    CHECK(threads.exit_code == 2);
    CHECK_THAT(threads.err, Contains("--threads"));
    CHECK(run_cli("cache fill" + std::string(" --cache ") + (d / "c")).exit_code == 2);
    CHECK(run_cli("cache info cases/block-ts1.toml --cache " + (d / "c")).exit_code == 2);
    CHECK(run_cli("cache frob --cache " + (d / "c")).exit_code == 2);
    CHECK(run_cli("cache info --no-cache").exit_code == 2);
    // Without XDG_CACHE_HOME and HOME there is no default folder: the run goes on uncached,
    // and cache info says what to give.
    const auto homeless = run_cli("cache info", "env -u XDG_CACHE_HOME -u HOME ");
    CHECK(homeless.exit_code == 2);
    CHECK_THAT(homeless.err, Contains("give --cache DIR"));
    CHECK(run_cli("assess cases/block-ts1.toml --pga 0.1 --out " + (d / "o"),
                  "env -u XDG_CACHE_HOME -u HOME ")
              .exit_code == 0);
}

TEST_CASE("an unwritable cache folder is a warning, never a failure", "[cli][cache]") {
    const Dir d("unwritable");
    std::ofstream(d.path / "file") << "a file where the cache folder would be";
    const auto r = run_cli("assess cases/block-ts1.toml --pga 0.5 --cache '" +
                           (d.path / "file" / "cache").string() + "' --out " + (d / "o"));
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.err, Contains("warning: history sets were not cached in") && Contains("cannot create"));
    CHECK_THAT(r.err, Contains("warning: runs were not cached in"));
    CHECK(fs::exists(d.path / "o" / "result.json"));
}

}  // namespace freestand_test_cli_test_cache_cli
