// api::run_batch: each component assessed as api::assess_report assesses it, failures kept in
// their rows, the same bytes whatever the thread count, in this process and in two.
#include <catch2/catch.hpp>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "api/assess.hpp"
#include "api/batch.hpp"
#include "batch/helpers.hpp"
#include "batch/list.hpp"
#include "batch/run.hpp"
#include "core/errors.hpp"
#include "support/run_cli.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_api_test_batch_run {

using namespace freestand;
using namespace freestand::batch;
namespace fs = std::filesystem;

namespace {

std::string quoted(const fs::path& p) { return fmt::format("'{}'", p.string()); }

const report::SummaryRow& row_named(const BatchRun& run, const std::string& name) {
    for (const report::SummaryRow& r : run.summary.rows)
        if (r.name == name) return r;
    FAIL("no row " << name);
    throw std::logic_error("unreachable");
}

// The result.json of row i's report folder.
std::string result_json(const BatchRun& run, std::size_t i) {
    for (const core::OutputFile& f : run.reports.at(i))
        if (f.name == "result.json") return f.contents;
    FAIL("row " << i << " has no result.json");
    return "";
}

nlohmann::json without_stamp(const std::string& json_text) {
    nlohmann::json j = nlohmann::json::parse(json_text);
    j.erase("stamp");
    return j;
}

api::BatchRequest request_of(const fs::path& list, int threads) {
    api::BatchRequest request;
    request.list = list;
    request.commit = "test";
    request.run = assess::RunSettings(threads);
    return request;
}

BatchRun run_batch(const BatchList& list, int threads) {
    return api::run_batch(list, request_of(list.source, threads));
}

// The bytes of a case file as assess's report folder holds its result.json.
std::string assessed_json(const fs::path& case_file) {
    api::AssessRequest request;
    request.case_file = case_file;
    request.commit = "test";
    return api::assess_report(request).rendered.json;
}

// Every regular file under dir, by its path relative to dir.
std::map<std::string, std::string> tree_files(const fs::path& dir) {
    std::map<std::string, std::string> out;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) out[fs::relative(e.path(), dir).string()] = test::slurp(e.path());
    return out;
}

// Six rows: four cases, one overridden, one missing file.
void write_thread_list(const fs::path& dir) {
    test::write_text(dir / "cases" / "rest.toml", test::resting_case("Rest"));
    test::write_text(dir / "cases" / "slide.toml", test::sliding_case("Slider"));
    test::write_text(dir / "list.csv",
                     "file,name,pga_g,seed\ncases/slide.toml,s1,,\ncases/rest.toml,r1,,\n"
                     "cases/missing.toml,gone,,\ncases/rest.toml,r2,0.06,\n"
                     "cases/slide.toml,s2,,4\ncases/rest.toml,r3,,\n");
}

}  // namespace

TEST_CASE("an overridden case is assessed as the case file carrying the values",
          "[api][batch][overrides]") {
    const fs::path dir = test::batch_dir("overrides");
    test::write_text(dir / "cases" / "rest.toml", test::resting_case("Rest"));
    test::write_text(dir / "cases" / "slide.toml", test::sliding_case("Slider"));
    test::write_text(dir / "list.toml", R"([[case]]
file = "cases/rest.toml"
name = "rest-hdpe"
base_material = "HDPE"
pga_g = [0.04, 0.06]

[[case]]
file = "cases/slide.toml"
seed = 9
histories_per_level = 2
)");
    // The same cases with the values written in by hand.
    std::string rest = test::resting_case("Rest");
    rest.replace(rest.find("base_material = \"steel\""), 23, "base_material = \"HDPE\"");
    rest.replace(rest.find("pga_g = [0.05]"), 14, "pga_g = [0.04, 0.06]");
    test::write_text(dir / "edited" / "rest.toml", rest);
    std::string slide = test::sliding_case("Slider");
    slide.replace(slide.find("histories_per_level = 1\nseed = 3"), 32,
                  "histories_per_level = 2\nseed = 9");
    test::write_text(dir / "edited" / "slide.toml", slide);

    const BatchRun run = run_batch(read_batch_list(dir / "list.toml"), 2);
    REQUIRE(run.all_assessed());
    const std::string slide_json = assessed_json(dir / "edited" / "slide.toml");
    CHECK(without_stamp(result_json(run, 0)) ==
          without_stamp(assessed_json(dir / "edited" / "rest.toml")));
    CHECK(without_stamp(result_json(run, 1)) == without_stamp(slide_json));
    CHECK(nlohmann::json::parse(result_json(run, 1))["stamp"]["seed"] == 9);
    // The seed and count were used.
    CHECK(nlohmann::json::parse(slide_json)["histories_generated"].get<int>() > 0);
    CHECK(row_named(run, "rest-hdpe").overrides ==
          "pga_g = [0.04, 0.06]; base_material = \"HDPE\"");
    CHECK(row_named(run, "slide").overrides == "seed = 9; histories_per_level = 2");
    fs::remove_all(dir);
}

TEST_CASE("the thread count does not change a byte", "[api][batch][threads][determinism]") {
    const fs::path dir = test::batch_dir("threads");
    write_thread_list(dir);
    const BatchList list = read_batch_list(dir / "list.csv");
    const std::vector<core::OutputFile> one = batch_files(run_batch(list, 1));
    const std::vector<core::OutputFile> three = batch_files(run_batch(list, 3));
    REQUIRE(one.size() == three.size());
    for (std::size_t i = 0; i < one.size(); ++i) {
        INFO(one[i].name);
        CHECK(one[i].name == three[i].name);
        CHECK(one[i].contents == three[i].contents);
    }
    CHECK(one.size() > 20);  // four summary files and five report folders
    fs::remove_all(dir);
}

TEST_CASE("two processes at 1 and 3 threads write the same batch folder",
          "[api][batch][cli][threads][determinism]") {
    // The in-process check above shares the process's state between its runs; separate
    // processes also catch what a static or an address would carry from one run to the next.
    const fs::path dir = test::batch_dir("processes");
    write_thread_list(dir);
    const std::string list = quoted(dir / "list.csv");
    const auto one = test::run_cli("batch " + list + " --no-cache --threads 1 --out " +
                                   quoted(dir / "one"));
    const auto three = test::run_cli("batch " + list + " --no-cache --threads 3 --out " +
                                     quoted(dir / "three"));
    CHECK(one.exit_code == 1);  // the missing case's row
    CHECK(three.exit_code == 1);
    const auto a = tree_files(dir / "one");
    const auto b = tree_files(dir / "three");
    CHECK(a.size() > 20);  // four summary files and five report folders
    REQUIRE(a.size() == b.size());
    for (const auto& [name, bytes] : a) {
        INFO(name);
        REQUIRE(b.count(name) == 1);
        CHECK(bytes == b.at(name));
    }
    fs::remove_all(dir);
}

TEST_CASE("a case of two units is a failed row naming the case's unit tables",
          "[api][batch][errors]") {
    const fs::path dir = test::batch_dir("pair");
    const std::string unit = "[[unit]]\nname = \"U\"\nmass_kg = 400.0\ncg_height_m = 0.5\n"
                             "cg_to_edge_x_m = [1.0, 1.0]\ncg_to_edge_y_m = [1.0, 1.0]\n"
                             "mu_s = 0.3\nallowable_slide_m = 5.0\n";
    test::write_text(dir / "pair.toml", unit + unit +
                                            "[tunnel]\nheight_m = 1.0\nallowable_relative_m = "
                                            "0.001\n[site]\npga_g = [0.3]\n");
    test::write_text(dir / "rest.toml", test::resting_case("Rest"));
    const BatchRun run = run_batch(read_batch_list(dir), 1);
    REQUIRE(run.summary.rows.size() == 2);
    const report::SummaryRow& pair = row_named(run, "pair");
    CHECK_FALSE(pair.outcome.has_value());
    CHECK(pair.exit_code == 3);
    CHECK_THAT(pair.error, Catch::StartsWith((dir / "pair.toml").string() +
                                             ": unit: two [[unit]] tables where one component "
                                             "is expected"));
    CHECK(row_named(run, "rest").outcome.has_value());
    fs::remove_all(dir);
}

TEST_CASE("a path that is no list is an input error naming the list", "[api][batch][errors]") {
    const fs::path dir = test::batch_dir("nolist");
    test::write_text(dir / "list.txt", "file\na.toml\n");
    try {
        (void)api::read_list(request_of(dir / "list.txt", 1));
        FAIL("no InputError");
    } catch (const InputError& e) {
        CHECK(e.where().field == "list");
        CHECK(e.where().file == (dir / "list.txt").string());
        CHECK(e.message() == "a list is a folder of case files, a .csv or a .toml file; got \".txt\"");
    }
    fs::remove_all(dir);
}

TEST_CASE("a shard request runs every n-th entry from the k-th", "[api][batch]") {
    BatchList list;
    list.entries.resize(5);
    api::BatchRequest request;
    CHECK(api::shard_entries(list, request) == std::vector<std::size_t>{0, 1, 2, 3, 4});
    request.shard = std::array<int, 2>{2, 2};
    CHECK(api::shard_entries(list, request) == std::vector<std::size_t>{1, 3});
}

}  // namespace freestand_test_api_test_batch_run
