// Running a batch (README "Batch"): each component assessed and written as `assess` does, failures
// kept in their rows, the same bytes whatever the thread count, and a summary in four formats.
#include <catch2/catch.hpp>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "support/paths.hpp"
#include "batch/helpers.hpp"
#include "batch/list.hpp"
#include "batch/run.hpp"
#include "core/csv_table.hpp"
#include "core/errors.hpp"
#include "report/summary.hpp"
#include "support/run_cli.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_batch_test_batch {

using namespace freestand;
using namespace freestand::batch;
namespace fs = std::filesystem;
using Catch::Contains;

namespace {

// Every file of a folder (its marker too), by name.
std::map<std::string, std::string> folder_files(const fs::path& dir) {
    std::map<std::string, std::string> out;
    for (const auto& e : fs::directory_iterator(dir))
        out[e.path().filename().string()] = test::slurp(e.path());
    return out;
}

std::string quoted(const fs::path& p) { return fmt::format("'{}'", p.string()); }

}  // namespace

TEST_CASE("a component's folder is the bytes `assess --out` writes, overridden or not",
          "[batch][cli][determinism]") {
    const fs::path dir = test::batch_dir("identical");
    test::write_text(dir / "cases" / "rest.toml", test::resting_case("Rest"));
    test::write_text(dir / "cases" / "slide.toml", test::sliding_case("Slider"));
    test::write_text(dir / "list.csv", "file,name,pga_g\ncases/rest.toml,,\n"
                                       "cases/slide.toml,slide-03,0.3\n");
    const auto b = test::run_cli("batch " + quoted(dir / "list.csv") + " --threads 1 --out " +
                                 quoted(dir / "batch"));
    REQUIRE(b.exit_code == 0);
    const auto a1 = test::run_cli("assess " + quoted(dir / "cases" / "rest.toml") + " --out " +
                                  quoted(dir / "alone" / "rest"));
    REQUIRE(a1.exit_code == 0);
    const auto a2 = test::run_cli("assess " + quoted(dir / "cases" / "slide.toml") +
                                  " --pga 0.3 --out " + quoted(dir / "alone" / "slide-03"));
    REQUIRE(a2.exit_code == 0);
    for (const char* name : {"rest", "slide-03"}) {
        INFO(name);
        const auto batch_files = folder_files(dir / "batch" / name);
        const auto alone_files = folder_files(dir / "alone" / name);
        CHECK(batch_files.size() >= 6);  // report.md, report.html, result.json, figures, marker
        CHECK(batch_files == alone_files);
    }
    fs::remove_all(dir);
}

TEST_CASE("a failing case gets its row and exit 1 while the others' reports are written",
          "[batch][cli][errors]") {
    const fs::path dir = test::batch_dir("failing");
    test::write_text(dir / "cases" / "rest.toml", test::resting_case("Rest"));
    test::write_text(dir / "cases" / "syntax.toml", "[component\n");
    test::write_text(dir / "cases" / "unknown.toml",
                     test::resting_case("Unknown") + "colour = \"red\"\n");
    // No generated history can meet D/A <= 0.01 m/g: a numerical failure (exit class 4).
    std::string unreachable = test::sliding_case("Unreachable");
    unreachable.replace(unreachable.find("[options]"), 9, "da_max_m_per_g = 0.01\n\n[options]");
    test::write_text(dir / "cases" / "unreachable.toml", unreachable);
    test::write_text(dir / "list.csv", "file,name,pga_g\ncases/rest.toml,,\n"
                                       "cases/missing.toml,,\ncases/syntax.toml,,\n"
                                       "cases/unknown.toml,,\ncases/rest.toml,heavy,1.6\n"
                                       "cases/rest.toml,last,\ncases/unreachable.toml,,\n");
    const auto r = test::run_cli("batch " + quoted(dir / "list.csv") + " --threads 2 --out " +
                                 quoted(dir / "out"));
    CHECK(r.exit_code == 1);
    CHECK(r.err.empty());
    const auto summary = nlohmann::json::parse(test::slurp(dir / "out" / "summary.json"));
    CHECK(summary["counts"]["components"] == 7);
    CHECK(summary["counts"]["assessed"] == 2);
    CHECK(summary["counts"]["failed"] == 5);
    const auto& rows = summary["rows"];
    CHECK(rows[0]["status"] == "ok");
    CHECK(rows[0]["outcome"]["verdict_kind"] == "acceptable");
    CHECK(rows[1]["exit_code"] == 5);
    CHECK(rows[1]["error"] == (dir / "cases" / "missing.toml").string() +
                                  ": cannot open file for reading");
    CHECK(rows[1]["case_sha256"].is_null());
    CHECK(rows[2]["exit_code"] == 3);
    CHECK_THAT(rows[2]["error"].get<std::string>(),
               Contains("syntax.toml:1: TOML syntax error"));
    CHECK(rows[3]["exit_code"] == 3);
    CHECK_THAT(rows[3]["error"].get<std::string>(), Contains("unknown.toml:"));
    CHECK_THAT(rows[3]["error"].get<std::string>(), Contains("colour: unknown key"));
    // An input error of an overridden case names the list's values: they have no line.
    CHECK(rows[4]["exit_code"] == 3);
    CHECK_THAT(rows[4]["error"].get<std::string>(),
               Contains("rest.toml: site.pga_g: PGA 1.6 g with a vertical/horizontal ratio"));
    CHECK_THAT(rows[4]["error"].get<std::string>(),
               Contains("(with pga_g = [1.6] from " + (dir / "list.csv").string() + ":6)"));
    CHECK(rows[5]["status"] == "ok");
    CHECK(rows[6]["exit_code"] == 4);
    CHECK_THAT(rows[6]["error"].get<std::string>(),
               Contains("no synthetic record passed SRP 3.7.1 and the realism checks"));
    CHECK(fs::exists(dir / "out" / "rest" / "report.html"));
    CHECK(fs::exists(dir / "out" / "last" / "report.html"));
    for (const char* failed : {"missing", "syntax", "unknown", "heavy", "unreachable"})
        CHECK_FALSE(fs::exists(dir / "out" / failed));
    CHECK_THAT(r.out, Contains("rest: Rest: free-standing acceptable (governing PGA 0.050 g"));
    CHECK_THAT(r.out, Contains("missing: error: "));
    CHECK_THAT(r.out, Contains(": 7 components, 5 failed, in "));
    CHECK_THAT(test::slurp(dir / "out" / "summary.csv"),
               Contains(",error: " + (dir / "cases" / "missing.toml").string() +
                        ": cannot open file for reading,5,\r\n"));
    fs::remove_all(dir);
}

TEST_CASE("batch --json prints the summary that summary.json holds, the default folder is "
          "out/batch/",
          "[batch][cli]") {
    const fs::path dir = test::batch_dir("json");
    test::write_text(dir / "cases" / "rest.toml", test::resting_case("Rest"));
    const std::string cmd = "cd " + quoted(dir) + " && '" + freestand::test::exe() +
                            "' batch cases --json >" + quoted(dir / "stdout.txt") + " 2>" +
                            quoted(dir / "stderr.txt");
    REQUIRE(std::system(cmd.c_str()) == 0);
    const std::string json = test::slurp(dir / "out" / "batch" / "summary.json");
    CHECK(test::slurp(dir / "stdout.txt") == json);
    const auto j = nlohmann::json::parse(json);
    CHECK(j["list"] == "cases");
    CHECK(j["stamp"]["list_sha256"].is_null());
    CHECK(j["rows"][0]["case_file"] == "cases/rest.toml");
    CHECK(j["rows"][0]["outcome"]["margin"].is_number());
    CHECK(fs::exists(dir / "out" / "batch" / "rest" / "result.json"));
    CHECK(test::slurp(dir / "stderr.txt").empty());
    fs::remove_all(dir);
}

TEST_CASE("batch CLI errors: a bad list or output folder stops before anything runs",
          "[batch][cli][errors]") {
    const fs::path dir = test::batch_dir("cli_errors");
    test::write_text(dir / "cases" / "rest.toml", test::resting_case("Rest"));
    test::write_text(dir / "bad.csv", "file,pga\ncases/rest.toml,0.1\n");
    const std::string out = " --out " + quoted(dir / "out");
    const auto bad = test::run_cli("batch " + quoted(dir / "bad.csv") + out);
    CHECK(bad.exit_code == 3);
    CHECK(bad.err == "freestand batch: error: " + (dir / "bad.csv").string() +
                         ":1: pga: unknown column (column 2); allowed columns: file, name, "
                         "pga_g, base_material, seed, histories_per_level\n");
    CHECK_FALSE(fs::exists(dir / "out"));
    const auto missing = test::run_cli("batch " + quoted(dir / "none.csv") + out);
    CHECK(missing.exit_code == 5);
    CHECK_THAT(missing.err, Contains("none.csv: no such file or folder"));
    const auto no_list = test::run_cli("batch " + quoted(dir / "cases" / "rest.toml") + out);
    CHECK(no_list.exit_code == 3);
    CHECK_THAT(no_list.err, Contains("rest.toml:1: component: unknown key; a batch list holds "
                                     "[[case]] tables (this looks like a case file"));
    test::write_text(dir / "list.txt", "x");
    const auto txt = test::run_cli("batch " + quoted(dir / "list.txt") + out);
    CHECK(txt.exit_code == 2);
    // --threads 0 means every core, as for assess and fragility.
    for (const char* t : {"x", "1.5", "2000"}) {
        const auto r = test::run_cli("batch " + quoted(dir / "cases") + out + " --threads " + t);
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.err, Contains("--threads: expected"));
    }
    CHECK(test::run_cli("batch").exit_code == 2);
    // An output folder freestand did not write is refused before the first component runs.
    test::write_text(dir / "mine" / "thesis.tex", "x");
    const auto refused =
        test::run_cli("batch " + quoted(dir / "cases") + " --out " + quoted(dir / "mine"));
    CHECK(refused.exit_code == 5);
    CHECK_THAT(refused.err, Contains("was not written by freestand"));
    CHECK(refused.out.empty());
    CHECK_FALSE(fs::exists(dir / "out"));
    fs::remove_all(dir);
}

TEST_CASE("the summary quotes CSV fields and escapes HTML and Markdown", "[batch][summary]") {
    const std::string hostile = "Pump, \"A\" <script>alert(1)</script> | *b*";
    report::SummaryRow ok;
    ok.name = "pump";
    ok.case_file = "cases/pump,1.toml";
    ok.outcome = report::SummaryOutcome{hostile, "anchor", "anchor", "PGA 0.300 g, direction y",
                                        0.3, "y", "", 0.8123, "0.81", "static initiation", "",
                                        {"flexible <b>"}};
    report::SummaryRow failed;
    failed.name = "rack";
    failed.case_file = "rack.toml";
    failed.error = "rack.toml:3: component.name: <script>";
    failed.exit_code = 3;
    const report::Summary s{{ok, failed}, {"0.1.0", "abc", "list.csv", "f00"}};
    const report::RenderedSummary out = report::render_summary(s);

    const auto records = core::parse_csv_table(out.csv, "summary.csv");
    REQUIRE(records.size() == 3);
    CHECK(records[0].fields[2] == "component");
    CHECK(records[1].fields[1] == "cases/pump,1.toml");
    CHECK(records[1].fields[2] == hostile);
    CHECK(records[1].fields[5] == "0.3");
    CHECK(records[1].fields[9] == "0.81");
    CHECK(records[1].fields[12] == "flexible <b>");
    CHECK(records[2].fields[14] == "error: rack.toml:3: component.name: <script>");
    CHECK(records[2].fields[15] == "3");
    CHECK_THAT(out.csv, Contains("\"Pump, \"\"A\"\" <script>alert(1)</script> | *b*\""));

    CHECK(out.html.find("<script") == std::string::npos);
    CHECK_THAT(out.html, Contains("Pump, &quot;A&quot; &lt;script&gt;alert(1)&lt;/script&gt;"));
    CHECK_THAT(out.html, Contains("error: rack.toml:3: component.name: &lt;script&gt;"));
    CHECK(out.html.find("https://") == std::string::npos);
    CHECK(out.html.find("<link") == std::string::npos);
    CHECK_THAT(out.html, Contains("<a href=\"pump/report.html\">pump</a>"));
    CHECK(out.markdown.find("<script>") == std::string::npos);
    CHECK_THAT(out.markdown, Contains("&lt;script>alert(1)&lt;/script> \\| \\*b\\*"));
    CHECK_THAT(out.markdown, Contains("[pump](pump/report.md)"));

    const auto j = nlohmann::json::parse(out.json);
    CHECK(j["rows"][0]["outcome"]["component"] == hostile);
    CHECK(j["rows"][0]["outcome"]["margin"] == 0.8123);
    CHECK(j["rows"][1]["outcome"].is_null());
    CHECK(j["rows"][1]["exit_code"] == 3);
    CHECK(j["counts"]["failed"] == 1);
    CHECK(j["stamp"]["list_sha256"] == "f00");
}

}  // namespace freestand_test_batch_test_batch
