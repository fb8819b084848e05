// api::regress: golden result.json files compared with fresh ones, numbers within a tolerance.
#include <catch2/catch.hpp>

#include "api/regress.hpp"
#include "batch/helpers.hpp"
#include "core/errors.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_api_test_regress {

using namespace freestand;
namespace fs = std::filesystem;

TEST_CASE("regress comparison: tolerance, verdict change, stamp ignored", "[api][regress]") {
    auto golden = api::json::parse(
        R"({"verdict": "anchor", "levels": [{"x": 1.0}], "stamp": {"commit": "a"}})");
    auto fresh = golden;
    fresh["stamp"]["commit"] = "b";
    fresh["levels"][0]["x"] = 1.0 + 5e-7;
    CHECK(api::compare_results(golden, fresh, 1e-6).empty());
    fresh["levels"][0]["x"] = 1.0 + 2e-6;
    auto d = api::compare_results(golden, fresh, 1e-6);
    REQUIRE(d.size() == 1);
    CHECK(d[0].path == "/levels/0/x");
    fresh = golden;
    fresh["verdict"] = "free-standing acceptable";
    d = api::compare_results(golden, fresh, 1e-6);
    REQUIRE(d.size() == 1);
    CHECK(d[0].path == "/verdict");
    fresh = golden;
    fresh["levels"].push_back(api::json::object());
    CHECK(api::compare_results(golden, fresh, 1e-6).at(0).path == "/levels/length");
}

TEST_CASE("regress refuses a negative tolerance naming the request's field",
          "[api][regress][errors]") {
    api::RegressRequest request;
    request.rtol = -1;
    try {
        (void)api::regress(request);
        FAIL("no InputError");
    } catch (const InputError& e) {
        CHECK(e.where().field == "rtol");
        CHECK(e.message() == "expected a number >= 0; got -1");
    }
}

TEST_CASE("regress of a folder without the glove-box cases skips the validation",
          "[api][regress]") {
    const fs::path dir = test::batch_dir("regress_empty");
    fs::create_directories(dir / "cases");
    api::RegressRequest request;
    request.cases_dir = dir / "cases";
    request.reports_dir = dir / "reports";
    std::vector<std::string> seen;
    request.on_entry = [&](const api::RegressEntry& e) { seen.push_back(e.name); };
    const api::RegressResult r = api::regress(request);
    REQUIRE(r.entries.size() == 1);
    CHECK(r.entries[0].status == api::RegressEntry::Status::skipped);
    CHECK(seen == std::vector<std::string>{"validation"});
    CHECK(r.all_ok());
    request.cases_dir = dir / "none";
    CHECK_THROWS_AS(api::regress(request), IoError);
    fs::remove_all(dir);
}

}  // namespace freestand_test_api_test_regress
