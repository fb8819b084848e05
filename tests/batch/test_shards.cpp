// `batch --shard K/N` and `freestand merge` of batch shards (docs/methods.md s.12): the merged
// folder is the single run's, byte for byte and with its exit code; shards that do not make one run
// are refused, naming the file.
#include <catch2/catch.hpp>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "batch/helpers.hpp"
#include "batch/list.hpp"
#include "batch/shard.hpp"
#include "core/errors.hpp"
#include "support/run_cli.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_batch_test_shards {

using namespace freestand;
using namespace freestand::batch;
namespace fs = std::filesystem;
using Catch::Contains;

namespace {

std::string quoted(const fs::path& p) { return fmt::format("'{}'", p.string()); }

// Every file under dir (markers included), by path relative to dir.
std::map<std::string, std::string> tree(const fs::path& dir) {
    std::map<std::string, std::string> out;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file())
            out[fs::relative(e.path(), dir).string()] = test::slurp(e.path());
    return out;
}

// A list of five components, one of them failing (its case file is missing).
fs::path shard_scene(const std::string& name) {
    const fs::path dir = test::batch_dir(name);
    test::write_text(dir / "cases" / "rest.toml", test::resting_case("Rest"));
    test::write_text(dir / "cases" / "slide.toml", test::sliding_case("Slider"));
    test::write_text(dir / "list.csv", "file,name,pga_g\ncases/rest.toml,,\n"
                                       "cases/slide.toml,,\ncases/missing.toml,,\n"
                                       "cases/rest.toml,rest-06,0.06\ncases/slide.toml,s2,0.25\n");
    return dir;
}

std::string batch_cmd(const fs::path& dir, const std::string& tail) {
    return "batch " + quoted(dir / "list.csv") + " --threads 1 " + tail;
}

}  // namespace

TEST_CASE("two batch shards merged are the single run's folder, byte for byte",
          "[batch][shard][determinism]") {
    const fs::path dir = shard_scene("shards");
    const auto single = test::run_cli(batch_cmd(dir, "--out " + quoted(dir / "single")));
    CHECK(single.exit_code == 1);  // the missing case
    const auto s1 = test::run_cli(batch_cmd(dir, "--shard 1/2 --out " + quoted(dir / "s1")));
    const auto s2 = test::run_cli(batch_cmd(dir, "--shard 2/2 --out " + quoted(dir / "s2")));
    // Shard 1 has components 1, 3 and 5 (the missing case is 3); shard 2 has 2 and 4.
    CHECK(s1.exit_code == 1);
    CHECK_THAT(s1.out, Contains("shard 1 of 2: 3 of 5 components (1 failed) written to"));
    CHECK_THAT(s1.out, Contains("missing: error: "));
    CHECK(s2.exit_code == 0);
    CHECK_THAT(s2.out, Contains("shard 2 of 2: 2 of 5 components (0 failed)"));
    CHECK(tree(dir / "s2").size() == 1);  // only the shard file: no report is written
    const auto merged = test::run_cli("merge " + quoted(dir / "s2") + " " + quoted(dir / "s1") +
                                      " --out " + quoted(dir / "merged"));
    CHECK(merged.exit_code == 1);
    CHECK(merged.err.empty());
    CHECK_THAT(merged.out, Contains(": 5 components, 1 failed\n"));

    const auto a = tree(dir / "single");
    const auto b = tree(dir / "merged");
    CHECK(a.size() > 25);  // four summary files, four report folders, the markers
    REQUIRE(a.size() == b.size());
    for (const auto& [name, bytes] : a) {
        INFO(name);
        REQUIRE(b.count(name) == 1);
        CHECK(b.at(name) == bytes);
    }
    // --json prints the merged summary.json.
    const auto json = test::run_cli("merge " + quoted(dir / "s1") + " " + quoted(dir / "s2") +
                                    " --json --out " + quoted(dir / "merged"));
    CHECK(json.out == a.at("summary.json"));
    fs::remove_all(dir);
}

TEST_CASE("merge refuses batch shards that do not make one run, naming the file",
          "[batch][shard][errors]") {
    const fs::path dir = shard_scene("shard_errors");
    REQUIRE(test::run_cli(batch_cmd(dir, "--shard 1/2 --out " + quoted(dir / "a"))).exit_code ==
            1);
    const auto merge = [&](const std::vector<fs::path>& parts) {
        std::vector<std::string> words{"merge"};
        for (const fs::path& p : parts) words.push_back(quoted(p));
        words.push_back("--out " + quoted(dir / "m"));
        return test::run_cli(fmt::format("{}", fmt::join(words, " ")));
    };
    SECTION("a missing shard") {
        const auto r = merge({dir / "a"});
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Contains("shard 2 of 2 is missing"));
    }
    SECTION("the same shard twice") {
        fs::create_directories(dir / "b");
        fs::copy_file(dir / "a" / "shard-1-of-2.jsonl", dir / "b" / "shard-1-of-2.jsonl");
        const auto r = merge({dir / "a", dir / "b"});
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Contains((dir / "b" / "shard-1-of-2.jsonl").string() + ":1: shard: "
                                   "shard 1 of 2 is also in"));
    }
    SECTION("a shard of another list") {
        test::write_text(dir / "other.csv", "file\ncases/rest.toml\ncases/slide.toml\n");
        REQUIRE(test::run_cli("batch " + quoted(dir / "other.csv") + " --shard 2/2 --out " +
                              quoted(dir / "b"))
                    .exit_code == 0);
        const auto r = merge({dir / "a", dir / "b"});
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Contains((dir / "b" / "shard-2-of-2.jsonl").string() +
                                   ":1: run: this shard belongs to another run"));
    }
    SECTION("a shard of another kind") {
        std::string header = R"({"freestand_shard":1,"kind":"fragility","shard":2,"of":2,"run":{}})";
        test::write_text(dir / "b" / "shard-2-of-2.jsonl", header + "\n");
        const auto r = merge({dir / "a", dir / "b"});
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Contains("shard-2-of-2.jsonl:1: run: this shard belongs to another run"));
    }
    CHECK_FALSE(fs::exists(dir / "m"));
    fs::remove_all(dir);
}

TEST_CASE("batch --shard CLI errors", "[batch][shard][cli][errors]") {
    const fs::path dir = shard_scene("shard_cli");
    for (const char* bad : {"0/2", "3/2", "x"}) {
        const auto r = test::run_cli(batch_cmd(dir, std::string("--shard ") + bad));
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.err, Contains("--shard"));
    }
    const auto json = test::run_cli(batch_cmd(dir, "--shard 1/2 --json"));
    CHECK(json.exit_code == 2);
    CHECK_THAT(json.err, Contains("--json prints the whole batch's summary"));
    fs::remove_all(dir);
}

namespace {

nlohmann::json a_run() {
    return nlohmann::json::parse(R"({"stamp": {"tool_version": "0.1.0", "commit": "abc",
        "list": "l.csv", "list_sha256": ""}, "names": ["pump", "rack"]})");
}

nlohmann::json a_record(std::size_t index, const std::string& name) {
    BatchRow row;
    row.row.name = name;
    row.row.error = "gone";
    row.row.exit_code = 5;
    return nlohmann::json::parse(shard_record(index, row).dump());
}

}  // namespace

TEST_CASE("merge_shards rebuilds rows exactly and refuses records that do not fit the header",
          "[batch][shard]") {
    BatchRow ok;
    ok.row.name = "pump";
    ok.row.case_file = "cases/pump.toml";
    ok.row.case_sha256 = std::string(64, 'a');
    ok.row.overrides = "seed = 4";
    // Not representable in 10 digits: the record keeps every bit for the summary to round.
    ok.row.outcome = report::SummaryOutcome{"Pump", "anchor", "anchor", "PGA 0.300 g, direction y",
                                            0.1 + 0.2, "y", "HDPE", 1.0 / 3.0, "0.33",
                                            "static initiation", "HDPE", {"a", "b"}};
    ok.files = {{"report.md", "# r\n"}, {"fragility.svg", "<svg/>"}};
    const std::vector<nlohmann::json> both{
        a_record(1, "rack"), nlohmann::json::parse(shard_record(0, ok).dump())};
    const BatchRun run = merge_shards(a_run(), both);
    REQUIRE(run.summary.rows.size() == 2);
    const report::SummaryRow& r = run.summary.rows[0];
    CHECK(r.case_file == "cases/pump.toml");
    CHECK(r.overrides == "seed = 4");
    REQUIRE(r.outcome);
    CHECK(r.outcome->governing_pga_g == 0.1 + 0.2);
    CHECK(r.outcome->margin == 1.0 / 3.0);
    CHECK(r.outcome->open_conditions == std::vector<std::string>{"a", "b"});
    CHECK(run.reports[0].size() == 2);
    CHECK(run.reports[0][1].name == "fragility.svg");
    CHECK(run.summary.rows[1].exit_code == 5);
    CHECK(run.reports[1].empty());
    CHECK(run.summary.stamp.commit == "abc");

    const auto refused = [&](std::vector<nlohmann::json> records, const std::string& why) {
        CHECK_THROWS_WITH(merge_shards(a_run(), records), Contains(why));
    };
    refused({a_record(0, "pump")}, "component 2 (rack) is in no shard");
    refused({a_record(0, "pump"), a_record(1, "rack"), a_record(1, "rack")},
            "component 2 (rack) is in two records");
    refused({a_record(0, "pump"), a_record(2, "rack")}, "component 3 of a list of 2");
    refused({a_record(0, "rack"), a_record(1, "pump")},
            "component 1 is named \"pump\" in the header and \"rack\" in its record");
    nlohmann::json evil = nlohmann::json::parse(shard_record(0, ok).dump());
    evil["files"] = nlohmann::json::array({nlohmann::json::array({"../../x", "y"})});
    refused({evil, a_record(1, "rack")}, "\"../../x\" cannot name a report file");
    nlohmann::json no_row = a_record(0, "pump");
    no_row.erase("row");
    refused({no_row, a_record(1, "rack")}, "row: malformed batch shard: missing");
    nlohmann::json bad_header = a_run();
    bad_header["names"][1] = "../etc";
    CHECK_THROWS_AS(merge_shards(bad_header, {a_record(0, "pump")}), InputError);
}

TEST_CASE("shard K of N takes every N-th component from the K-th", "[batch][shard]") {
    CHECK(shard_indices(5, 1, 2) == std::vector<std::size_t>{0, 2, 4});
    CHECK(shard_indices(5, 2, 2) == std::vector<std::size_t>{1, 3});
    CHECK(shard_indices(2, 3, 3).empty());
}

}  // namespace freestand_test_batch_test_shards
