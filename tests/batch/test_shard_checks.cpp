// `freestand merge` of batch shards checks every value of a record against the run before it
// writes anything: a row's verdict kind against its verdict text, its exit code against its
// status, its report files once each; refused with exit 3 naming the shard file, line and field.
#include <catch2/catch.hpp>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "batch/helpers.hpp"
#include "batch/shard.hpp"
#include "core/errors.hpp"
#include "support/run_cli.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_batch_test_shard_checks {

using namespace freestand;
using namespace freestand::batch;
namespace fs = std::filesystem;
using Catch::Contains;
using nlohmann::json;

namespace {

std::string quoted(const fs::path& p) { return fmt::format("'{}'", p.string()); }

// The lines of a shard file, and the same written back.
std::vector<std::string> lines_of(const fs::path& file) {
    std::vector<std::string> out;
    std::istringstream in(test::slurp(file));
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

void write_lines(const fs::path& file, const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& l : lines) text += l + "\n";
    test::write_text(file, text);
}

// A run of two components whose shard 1 of 1 holds a resting case (assessed, "free-standing
// acceptable") and a missing one (failed, exit code 5).
struct ShardScene {
    fs::path dir = test::batch_dir("shard_checks");
    fs::path shard = dir / "s" / "shard-1-of-1.jsonl";
    ShardScene() {
        test::write_text(dir / "cases" / "rest.toml", test::resting_case("Rest"));
        test::write_text(dir / "list.csv", "file\ncases/rest.toml\ncases/missing.toml\n");
        const auto r = test::run_cli("batch " + quoted(dir / "list.csv") +
                                     " --threads 1 --shard 1/1 --out " + quoted(dir / "s"));
        REQUIRE(r.exit_code == 1);
        REQUIRE(lines_of(shard).size() == 3);
    }
    ~ShardScene() { fs::remove_all(dir); }
    // Edits line (1-based) of the shard as JSON and merges; the merge must write nothing.
    test::CliResult merge_edited(int line, const std::function<void(json&)>& edit) const {
        std::vector<std::string> lines = lines_of(shard);
        json j = json::parse(lines.at(static_cast<std::size_t>(line - 1)));
        edit(j);
        lines[static_cast<std::size_t>(line - 1)] = j.dump();
        write_lines(dir / "edited" / "shard-1-of-1.jsonl", lines);
        const auto r = test::run_cli("merge " + quoted(dir / "edited") + " --out " +
                                     quoted(dir / "m"));
        CHECK_FALSE(fs::exists(dir / "m"));
        return r;
    }
    std::string at(int line) const {
        return (dir / "edited" / "shard-1-of-1.jsonl").string() + ":" + std::to_string(line) + ": ";
    }
};

}  // namespace

TEST_CASE("merge refuses a batch shard whose row contradicts itself, naming file, line and field",
          "[batch][shard][errors]") {
    const ShardScene s;
    SECTION("an untouched shard merges") {
        const auto r = test::run_cli("merge " + quoted(s.dir / "s") + " --out " + quoted(s.dir / "m"));
        CHECK(r.exit_code == 1);
        CHECK(r.err.empty());
    }
    SECTION("verdict_kind anchor beside the text \"free-standing acceptable\"") {
        const auto r = s.merge_edited(2, [](json& j) {
            REQUIRE(j["row"]["outcome"]["verdict"] == "free-standing acceptable");
            j["row"]["outcome"]["verdict_kind"] = "anchor";
        });
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Contains(s.at(2) + "row.outcome.verdict: malformed batch shard: \"free-"
                                             "standing acceptable\" is not the text of a verdict "
                                             "of kind anchor"));
    }
    SECTION("exit_code 70 on an assessed row") {
        const auto r = s.merge_edited(2, [](json& j) { j["row"]["exit_code"] = 70; });
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Contains(s.at(2) + "row.exit_code: malformed batch shard: 70 for an "
                                             "assessed component; expected 0"));
    }
    SECTION("exit_code 0 on a failed row") {
        const auto r = s.merge_edited(3, [](json& j) { j["row"]["exit_code"] = 0; });
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Contains(s.at(3) + "row.exit_code: malformed batch shard: 0 for a "
                                             "component that failed; expected 3, 4, 5 or 70"));
    }
    SECTION("one report file listed twice") {
        std::string name;
        const auto r = s.merge_edited(2, [&](json& j) {
            name = j["files"][0][0].get<std::string>();
            j["files"].push_back(j["files"][0]);
        });
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Contains(s.at(2) + "files: malformed batch shard: the report file \"" +
                                   name + "\" is listed twice"));
    }
    SECTION("a report file's name with a NUL is shown, not cut") {
        const auto r = s.merge_edited(
            2, [](json& j) { j["files"][0][0] = std::string("rep\0ort.md", 10); });
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Contains("\"rep\\x00ort.md\" cannot name a report file\n"));
    }
    SECTION("one component named twice in the header") {
        const auto r = s.merge_edited(1, [](json& j) {
            j["run"]["names"][1] = j["run"]["names"][0];
        });
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Contains(s.at(1) + "run.names: duplicate name \"rest\""));
    }
    SECTION("a fractional exit code") {
        const auto r = s.merge_edited(3, [](json& j) { j["row"]["exit_code"] = 5.5; });
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Contains(s.at(3) + "row.exit_code: malformed batch shard: expected a "
                                             "whole number; got 5.5"));
    }
    SECTION("a UTF-8 BOM before the header is read past") {
        std::vector<std::string> lines = lines_of(s.shard);
        lines[0] = "\xEF\xBB\xBF" + lines[0];
        write_lines(s.dir / "bom" / "shard-1-of-1.jsonl", lines);
        const auto r = test::run_cli("merge " + quoted(s.dir / "bom") + " --out " + quoted(s.dir / "m"));
        CHECK(r.exit_code == 1);
        CHECK(r.err.empty());
    }
}

TEST_CASE("merge_shards checks a row's margin, direction and PGA against what a verdict can say",
          "[batch][shard][errors]") {
    const json run = json::parse(R"({"stamp": {"tool_version": "0.1.0", "commit": "abc",
        "list": "l.csv", "list_sha256": ""}, "names": ["pump"]})");
    BatchRow ok;
    ok.row.name = "pump";
    ok.row.case_sha256 = std::string(64, 'a');
    ok.row.outcome = report::SummaryOutcome{"Pump", "acceptable_with_clearance",
                                            "acceptable with clearance >= 47 mm",
                                            "PGA 0.300 g, direction y", 0.3, "y", "", 1.25,
                                            "1.25", "ASCE 4", "", {}};
    ok.files = {{"report.md", "# r\n"}};
    const SourceLocation at{"s.jsonl", 2, ""};
    const auto merged = [&](const std::function<void(json&)>& edit) {
        json rec = json::parse(shard_record(0, ok).dump());
        edit(rec);
        return merge_shards(run, {rec}, SourceLocation{"s.jsonl", 1, ""}, {at});
    };
    CHECK(merged([](json&) {}).summary.rows.size() == 1);
    CHECK_THROWS_WITH(merged([](json& j) { j["row"]["outcome"]["margin"] = -1.0; }),
                      Contains("s.jsonl:2: row.outcome.margin: value -1 must be a finite number >= 0"));
    CHECK_THROWS_WITH(merged([](json& j) { j["row"]["outcome"]["margin_text"] = "9.99"; }),
                      Contains("s.jsonl:2: row.outcome.margin_text: malformed batch shard: "
                               "\"9.99\" for the margin 1.25; expected \"1.25\""));
    CHECK_THROWS_WITH(merged([](json& j) { j["row"]["outcome"]["governing_direction"] = "z"; }),
                      Contains("s.jsonl:2: row.outcome.governing_direction:"));
    CHECK_THROWS_WITH(merged([](json& j) { j["row"]["outcome"]["governing_pga_g"] = 30.0; }),
                      Contains("s.jsonl:2: row.outcome.governing_pga_g: value 30 is out of range"));
    CHECK_THROWS_WITH(merged([](json& j) { j["row"]["outcome"]["verdict_kind"] = "fine"; }),
                      Contains("s.jsonl:2: row.outcome.verdict_kind: malformed batch shard: "
                               "\"fine\"; expected acceptable"));
    CHECK_THROWS_WITH(merged([](json& j) { j["row"]["case_sha256"] = "ab"; }),
                      Contains("s.jsonl:2: row.case_sha256:"));
    CHECK_THROWS_WITH(merged([](json& j) { j["files"] = json::array(); }),
                      Contains("s.jsonl:2: files: malformed batch shard: none for an assessed "
                               "component"));
    CHECK_THROWS_WITH(merged([](json& j) { j["index"] = -1; }),
                      Contains("s.jsonl:2: index: malformed batch shard: expected a whole number "
                               ">= 0; got -1"));
    CHECK_THROWS_WITH(merged([](json& j) { j["row"].erase("error"); }),
                      Contains("s.jsonl:2: row.error: malformed batch shard: missing"));
}

}  // namespace freestand_test_batch_test_shard_checks
