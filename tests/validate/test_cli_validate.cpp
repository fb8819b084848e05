// `freestand validate`: the table, --json, the reports, exit codes, determinism.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include "report/validation.hpp"
#include "support/paths.hpp"
#include "support/run_cli.hpp"
#include "support/shipped_validation.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_validate_test_cli_validate {

namespace fs = std::filesystem;
using freestand::test::run_cli;
using freestand::test::slurp;

namespace {
fs::path temp_dir(const std::string& name) {
    // The pid keeps concurrent test runs (other build trees, ctest -j) out of each other's way.
    const fs::path d = fs::temp_directory_path() /
                       ("freestand_validate_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}
}  // namespace

TEST_CASE("validate prints the table, writes the reports, prints result.json with --json and "
          "writes what the library computes",
          "[validate][cli][slow]") {
    const fs::path dir = temp_dir("cli");
    const auto a = run_cli("validate --out '" + (dir / "a").string() + "'");
    REQUIRE(a.exit_code == 0);
    CHECK_THAT(a.out, Catch::StartsWith("freestand against the thesis: validation\n"));
    for (const char* text :
         {"[differs, by construction] ts3-ishiyama:", "   thesis:     47 mm (s.5.5)",
          "[agrees, outcome] gb-steel-pads-0.3g:", "[not runnable, outcome] ts1-0.5hz:",
          "Saraswat 2017", "\nnotes\n"})
        CHECK_THAT(a.out, Catch::Contains(text));
    CHECK_THAT(a.err, Catch::Contains("wrote " + (dir / "a").string() + " (127 rows) in "));
    for (const char* f : {"report.md", "report.html", "result.json"}) CHECK(fs::exists(dir / "a" / f));
    const auto j = nlohmann::ordered_json::parse(slurp(dir / "a" / "result.json"));
    // The command's rows and summary are, byte for byte, those of the same validation computed
    // in this process: another process, so they depend on nothing but the inputs.
    const auto& in_process = freestand::test::shipped_validation();
    const auto expected = freestand::report::validation_json(
        in_process, freestand::report::validation_stamp(in_process, "test"));
    CHECK(j.at("rows").dump() == expected.at("rows").dump());
    CHECK(j.at("summary").dump() == expected.at("summary").dump());
    CHECK(a.out == freestand::report::validation_text(in_process));
    REQUIRE(j.at("rows").size() == 127);
    CHECK(j.at("summary").at("rows") == 127);
    // One tally per kind, adding up to the rows; the text says the same.
    const auto& kinds = j.at("summary").at("kinds");
    REQUIRE(kinds.size() == 3);
    int counted = 0;
    for (const auto& k : kinds) {
        counted += k.at("rows").get<int>();
        CHECK(k.at("agrees").get<int>() + k.at("differs").get<int>() +
                  k.at("not_comparable").get<int>() + k.at("not_runnable").get<int>() ==
              k.at("rows").get<int>());
        CHECK_THAT(
            j.at("summary").at("text").get<std::string>(),
            Catch::Contains(fmt::format("{}: {} of {} agree", k.at("kind").get<std::string>(),
                                        k.at("agrees").get<int>(),
                                        k.at("agrees").get<int>() + k.at("differs").get<int>())));
    }
    CHECK(counted == 127);
    CHECK(kinds.at(1).at("kind") == "outcome");
    CHECK(kinds.at(1).at("not_runnable") == 15);
    const auto& first = j.at("rows").at(0);
    for (const char* key :
         {"group", "id", "kind", "test", "thesis", "thesis_value", "predicted", "predicted_value",
          "unit", "difference", "difference_value", "agreement", "reason", "sources"})
        CHECK(first.contains(key));
    CHECK(j.at("thesis").at("reference") == "Saraswat 2017");
    CHECK(j.at("stamp").at("inputs").size() == 4);
    const std::string md = slurp(dir / "a" / "report.md");
    CHECK_THAT(md, Catch::Contains("**Saraswat 2017**"));
    CHECK_THAT(md, Catch::Contains("| ts3-2hz |"));
    const std::string html = slurp(dir / "a" / "report.html");
    CHECK(html.find("http") == std::string::npos);  // self-contained
    fs::remove_all(dir);
}

TEST_CASE("validate CLI errors", "[validate][cli]") {
    const fs::path dir = temp_dir("errors");
    const auto no_cases = run_cli("validate --cases '" + dir.string() + "' --out '" +
                                  (dir / "o").string() + "'");
    CHECK(no_cases.exit_code == 5);
    CHECK_THAT(no_cases.err,
               Catch::Contains(dir.string() + ": expected the shipped cases glovebox-single.toml, "
                                              "glovebox-steel-pads.toml, glovebox-pair.toml"));
    CHECK_FALSE(fs::exists(dir / "o"));
    const auto bad = run_cli("validate --frobnicate");
    CHECK(bad.exit_code == 2);
    CHECK_THAT(bad.err, Catch::Contains("unrecognised option '--frobnicate'"));
    const auto extra = run_cli("validate cases");
    CHECK(extra.exit_code == 2);
    const auto help = run_cli("validate --help");
    CHECK(help.exit_code == 0);
    CHECK_THAT(help.out, Catch::Contains("--json"));
    fs::remove_all(dir);
}

namespace {
// The shipped case `name` with 7 sets per level and no growth: the regress test checks what
// regress does with the validation's rows, not their values, and any number of sets makes them.
void copy_light_case(const std::string& name, const fs::path& to) {
    std::string text = slurp(fs::path(freestand::test::source_dir()) / "cases" / name);
    const std::string options = "[options]\n";
    const auto at = text.find(options);
    REQUIRE(at != std::string::npos);
    text.insert(at + options.size(), "histories_per_level = 7\nmax_histories_per_level = 7\n");
    std::ofstream(to / name) << text;
}

// The four shipped glove-box cases, light, in dir/cases.
void copy_light_cases(const fs::path& dir) {
    fs::create_directories(dir / "cases");
    for (const char* c : {"glovebox-single.toml", "glovebox-steel-pads.toml", "glovebox-pair.toml",
                          "glovebox-pair-unbraced.toml"})
        copy_light_case(c, dir / "cases");
}
}  // namespace

TEST_CASE("regress compares and rewrites reports/validation/", "[validate][cli][regress][slow]") {
    const fs::path dir = temp_dir("regress");
    copy_light_cases(dir);
    const std::string args =
        fmt::format("'{}' --cases '{}' --cache '{}'", (dir / "reports").string(),
                    (dir / "cases").string(), (dir / "cache").string());
    // Two runs (each computes the validation): write the goldens; then, with one row of the
    // validation drifted and one case's golden gone, report both while the other cases stay ok.
    const auto update = run_cli("regress " + args + " --update");
    REQUIRE(update.exit_code == 0);
    // The one-line headline is the summary's text, per kind.
    CHECK_THAT(update.out, Catch::Contains("updated " + (dir / "reports" / "validation").string() +
                                           ": 127 rows; by construction: "));
    CHECK(fs::exists(dir / "reports" / "validation" / "report.html"));
    // Drift one predicted value by 1%.
    const fs::path golden = dir / "reports" / "validation" / "result.json";
    auto j = nlohmann::ordered_json::parse(slurp(golden));
    j["rows"][18]["predicted_value"] = j["rows"][18]["predicted_value"].get<double>() * 1.01;
    std::ofstream(golden) << j.dump(2);
    fs::remove_all(dir / "reports" / "glovebox-pair-unbraced");
    const auto drift = run_cli("regress " + args);
    CHECK(drift.exit_code == 1);
    CHECK_THAT(drift.out, Catch::Contains("CHANGED validation: 1 difference(s)"));
    CHECK_THAT(drift.out, Catch::Contains("/rows/18/predicted_value"));
    CHECK_THAT(drift.out, Catch::Contains("ok      glovebox-single"));
    CHECK_THAT(drift.out, Catch::Contains("MISSING glovebox-pair-unbraced: no golden "));
    fs::remove_all(dir);
}

TEST_CASE("validate --json prints the result.json it writes", "[validate][cli][slow]") {
    const fs::path dir = temp_dir("json");
    copy_light_cases(dir);
    const auto b = run_cli(fmt::format("validate --json --cases '{}' --out '{}'",
                                       (dir / "cases").string(), (dir / "b").string()));
    REQUIRE(b.exit_code == 0);
    CHECK(b.out == slurp(dir / "b" / "result.json"));
    CHECK(nlohmann::json::parse(b.out).at("rows").size() == 127);
    fs::remove_all(dir);
}

}  // namespace freestand_test_validate_test_cli_validate
