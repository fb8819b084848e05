// The performance goal in the outputs (docs/methods.md s.6 step 5): result.json's
// "performance_goal" object and its consistency with the headline, the same bytes at 1 and 2
// threads, and the reports' section.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "api/assess.hpp"
#include "report/render.hpp"
#include "support/goal_cases.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_api_test_goal_report {

using namespace freestand;

namespace {

api::AssessResult assessed(const char* toml, const char* file, int threads) {
    api::AssessRequest request;
    request.case_file = file;
    request.case_bytes = toml;
    request.commit = "abc";
    request.run = assess::RunSettings(threads);
    request.run.cache = test::test_cache();
    return api::assess(request);
}

std::string json_text(const api::AssessResult& a) { return api::to_json(a).dump(2) + "\n"; }

void check_consistent(const nlohmann::json& g) {
    for (const char* key :
         {"dbe_pga_g", "configuration", "limit_state", "p_dbe",        "p_dbe_ci95",
          "p_150",     "p_150_ci95",    "passes",      "margin",       "margin_basis",
          "theta_m_g", "beta",          "targets",     "levels_g",     "samples_per_level",
          "pool",      "seed",          "models",      "limit_states", "levels",
          "notes"}) {
        INFO(key);
        CHECK(g.contains(key));
    }
    const auto within = [](const nlohmann::json& s, const char* p, const char* ci) {
        INFO(p);
        CHECK(s.at(ci).at(0).get<double>() <= s.at(p).get<double>());
        CHECK(s.at(p).get<double>() <= s.at(ci).at(1).get<double>());
    };
    within(g, "p_dbe", "p_dbe_ci95");
    within(g, "p_150", "p_150_ci95");
    const bool under = g.at("p_dbe").get<double>() <= 0.01 && g.at("p_150").get<double>() <= 0.10;
    CHECK(g.at("passes").get<bool>() == under);
    CHECK(g.at("targets").at("p_dbe") == 0.01);
    CHECK(g.at("targets").at("p_150") == 0.1);
    CHECK(g.at("samples_per_level") == 30);
    for (const char* e : {"overturn", "slide", "rock", "any"}) {
        const nlohmann::json& s = g.at("limit_states").at(e);
        within(s, "p_dbe", "p_dbe_ci95");
        within(s, "p_150", "p_150_ci95");
    }
    // The top level is the governing limit state's.
    const nlohmann::json& gov = g.at("limit_states").at(g.at("limit_state").get<std::string>());
    CHECK(gov.at("p_dbe") == g.at("p_dbe"));
    CHECK(gov.at("p_150_ci95") == g.at("p_150_ci95"));
}

// result.json of a case with a DBE, its performance_goal checked for consistency.
nlohmann::json consistent_result(const char* toml, const char* file) {
    nlohmann::json j = nlohmann::json::parse(json_text(assessed(toml, file, 2)));
    check_consistent(j.at("performance_goal"));
    return j;
}

}  // namespace

TEST_CASE("result.json: a failed goal is the headline, its fields consistent",
          "[report][json][goal]") {
    const nlohmann::json j = consistent_result(test::slender_goal_toml, "slender.toml");
    const nlohmann::json& g = j.at("performance_goal");
    CHECK(g.at("passes") == false);
    CHECK(g.at("dbe_pga_g") == 0.33);
    CHECK(g.at("p_dbe").get<double>() > 0.01);
    CHECK(g.at("configuration") == "the case's own base, steel (mu_s 0.7-0.8)");
    // The levels pass (at rest), the goal does not: the verdict is the goal's.
    CHECK(j.at("own").at("kind") == "acceptable");
    CHECK(j.at("verdict") == "anchor");
    CHECK(j.at("overall").at("failure") == "performance goal not met (ASCE 43-05 s.1.3)");
    CHECK(j.at("overall").at("decided_by") == to_string(assess::Model::fragility_goal));
    CHECK(j.at("overall").at("margin_basis") == g.at("margin_basis"));
    CHECK(j.at("overall").at("margin") == g.at("margin"));
    CHECK(j.at("overall").at("margin").get<double>() < 1.0);
}

TEST_CASE("result.json: a met goal leaves the headline, and no DBE writes no goal",
          "[report][json][goal]") {
    const nlohmann::json j = consistent_result(test::squat_goal_toml, "squat.toml");
    const nlohmann::json& g = j.at("performance_goal");
    CHECK(g.at("passes") == true);
    CHECK(g.at("limit_state") == "any");
    CHECK(g.at("margin").is_null());
    CHECK(j.at("overall") == j.at("own"));
    CHECK(j.at("overall").at("kind") == "acceptable");
    std::string no_dbe = test::squat_goal_toml;
    no_dbe.erase(no_dbe.find("dbe_pga_g = 0.05\n"), 17);
    const api::AssessResult none = assessed(no_dbe.c_str(), "squat.toml", 2);
    CHECK_FALSE(none.goal.has_value());
    CHECK_FALSE(nlohmann::json::parse(json_text(none)).contains("performance_goal"));
}

TEST_CASE("the goal's outputs are the same bytes at 1 and 2 threads", "[report][goal]") {
    const std::string one = json_text(assessed(test::slender_goal_toml, "slender.toml", 1));
    const std::string two = json_text(assessed(test::slender_goal_toml, "slender.toml", 2));
    CHECK(one == two);
}

TEST_CASE("the reports carry the goal's section and a goal headline", "[report][goal]") {
    const api::AssessResult a = assessed(test::slender_goal_toml, "slender.toml", 2);
    const report::Rendered r = report::render(a.result, a.stamp, nullptr, &*a.goal);
    CHECK_THAT(r.markdown, Catch::Contains("## Performance goal (ASCE 43-05 s.1.3)") &&
                               Catch::Contains("**Not met: P(") &&
                               Catch::Contains("Governing level: performance goal at PGA 0.330 g"));
    CHECK_THAT(r.html, Catch::Contains("<h2>Performance goal (ASCE 43-05 s.1.3)</h2>"));
    const report::Rendered plain = report::render(a.result, a.stamp);
    CHECK_THAT(plain.markdown, !Catch::Contains("Performance goal (ASCE"));
}

}  // namespace freestand_test_api_test_goal_report
