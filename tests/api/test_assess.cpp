// api::assess: a request to an assessment, its result.json document and its report folder.
#include <catch2/catch.hpp>

#include <set>

#include "api/assess.hpp"
#include "assess/verdict.hpp"
#include "batch/helpers.hpp"
#include "core/errors.hpp"
#include "core/sha256.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_api_test_assess {

using namespace freestand;

namespace {

api::AssessRequest resting_request() {
    api::AssessRequest request;
    request.case_file = "plant/rest.toml";  // never read: the request carries the text
    request.case_bytes = test::resting_case("Rest");
    request.commit = "test";
    request.run = assess::RunSettings(1);
    return request;
}

std::string unit(const std::string& name, const std::string& mu) {
    return "[[unit]]\nname = \"" + name +
           "\"\nmass_kg = 400.0\ncg_height_m = 0.5\ncg_to_edge_x_m = [1.0, 1.0]\n"
           "cg_to_edge_y_m = [1.0, 1.0]\nmu_s = " + mu + "\nallowable_slide_m = 5.0\n";
}

const std::string pair_case = unit("A", "0.1") + unit("B", "0.3") +
                              "[tunnel]\nheight_m = 1.0\nallowable_relative_m = 0.001\n[site]\n"
                              "pga_g = [0.3]\n";

}  // namespace

TEST_CASE("assess: a squat box below its friction stays at rest at the requested levels",
          "[api][assess]") {
    // Steel on steel keeps mu_s well above 0.05 (base_material table) and the box's b/h = 0.75
    // is far above the PGA: neither slide nor rock initiates (docs/methods.md s.2), so the
    // closed forms settle it without a history.
    api::AssessRequest request = resting_request();
    request.pga_g = std::vector<double>{0.02, 0.04};
    const api::AssessResult r = api::assess(request);
    std::set<double> levels;
    for (const assess::LevelResult& l : r.result.levels) levels.insert(l.pga_g);
    CHECK(levels == std::set<double>{0.02, 0.04});
    CHECK(r.result.histories_generated == 0);
    CHECK(r.result.overall.verdict.kind == assess::VerdictKind::acceptable);
    const api::json j = api::to_json(r);
    CHECK(j.at("verdict") == assess::verdict_text(r.result.overall.verdict));
    CHECK(j.at("levels").size() == r.result.levels.size());
    CHECK_FALSE(j.contains("fragility"));
}

TEST_CASE("assess: case text given is hashed into the stamp and the file is not read",
          "[api][assess]") {
    const api::AssessRequest request = resting_request();
    const api::AssessResult r = api::assess(request);
    CHECK(r.stamp.input_sha256 == core::sha256_hex(*request.case_bytes));
    CHECK(r.stamp.case_file == "plant/rest.toml");
    CHECK(r.stamp.commit == "test");
    api::AssessRequest unread = request;
    unread.case_bytes.reset();
    CHECK_THROWS_AS(api::assess(unread), IoError);
}

TEST_CASE("assess: levels out of range name the request's levels", "[api][assess][errors]") {
    api::AssessRequest request = resting_request();
    request.pga_g = std::vector<double>{1e-310, 0.1};
    try {
        (void)api::assess(request);
        FAIL("no InputError");
    } catch (const InputError& e) {
        CHECK(e.where().field == "pga_levels");
        CHECK_THAT(e.message(), Catch::StartsWith("value 1e-310 is out of range"));
    }
}

TEST_CASE("assess_report: the report folder's files, result.json the document's text",
          "[api][assess]") {
    const api::AssessReport r = api::assess_report(resting_request());
    std::set<std::string> names;
    for (const core::OutputFile& f : r.files) names.insert(f.name);
    CHECK(names.count("report.md") == 1);
    CHECK(names.count("report.html") == 1);
    CHECK(names.count("report.pdf") == 0);
    CHECK_FALSE(r.pdf_converter.has_value());
    CHECK(r.rendered.json == api::to_json(r.assessed).dump(2) + "\n");
}

TEST_CASE("assess: two units are refused as one component and with a fragility analysis",
          "[api][assess][errors]") {
    api::AssessRequest request;
    request.case_file = "pair.toml";
    request.case_bytes = pair_case;
    request.single_component = true;
    request.run = assess::RunSettings(1);
    CHECK_THROWS_MATCHES(api::assess(request), InputError,
                         Catch::Matchers::Message(
                             "pair.toml: unit: two [[unit]] tables where one component is "
                             "expected (a batch's row is one component; assess the pair on its "
                             "own)"));
    request.single_component = false;
    request.case_bytes = pair_case + "[options]\nfragility = true\n";
    CHECK_THROWS_MATCHES(api::assess(request), InputError,
                         Catch::Matchers::Message(
                             "pair.toml: options.fragility: not available for two [[unit]] "
                             "tables (the fragility analysis takes one component)"));
}

}  // namespace freestand_test_api_test_assess
