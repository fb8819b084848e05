// Consistency checks on every shipped case: a material trial is the assessment of
// the case edited to name that material, and the verdict does not depend on simulate = "auto"
// or "always" (docs/methods.md s.6 steps 4 and 7).
#include <catch2/catch.hpp>

#include <filesystem>
#include <sstream>
#include <toml++/toml.h>

#include "support/paths.hpp"
#include "assess/joined.hpp"
#include "assess/materials.hpp"
#include "assess/pipeline.hpp"
#include "assess/verdict.hpp"
#include "core/file_io.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_assess_test_policy {

namespace fs = std::filesystem;
using namespace freestand;
using namespace freestand::assess;

namespace {

std::vector<fs::path> shipped_cases() {
    std::vector<fs::path> out;
    for (const auto& e : fs::directory_iterator(fs::path(freestand::test::source_dir()) / "cases")) {
        if (e.path().extension() == ".toml") out.push_back(e.path());
    }
    std::sort(out.begin(), out.end());
    return out;
}

// The case file's text with its base replaced by `base_material = material` alone, as a user
// would edit it.
std::string edited_case_text(const fs::path& file, const std::string& material) {
    toml::table root = toml::parse(core::read_text_file(file), file.string());
    toml::table& comp = *root["component"].as_table();
    for (const char* key :
         {"base_material", "mu_s", "mu_k", "restitution", "mu_s_range", "restitution_range"}) {
        comp.erase(key);
    }
    comp.insert("base_material", material);
    std::ostringstream text;
    text << root;
    return text.str();
}

void check_same_verdict(const Governing& direct, const Governing& trial) {
    CHECK(passes(direct.verdict) == passes(trial.verdict));
    CHECK(direct.verdict.failure == trial.verdict.failure);
    CHECK(direct.verdict.kind == trial.verdict.kind);
    CHECK(direct.verdict.decided_by == trial.verdict.decided_by);
    CHECK(direct.verdict.no_motion == trial.verdict.no_motion);
    CHECK(direct.level == trial.level);
    CHECK(direct.pga_g == trial.pga_g);
    CHECK(direct.direction == trial.direction);
    REQUIRE(direct.verdict.margin.has_value() == trial.verdict.margin.has_value());
    if (direct.verdict.margin) {
        CHECK(*direct.verdict.margin == Approx(*trial.verdict.margin).epsilon(1e-9).margin(1e-12));
    }
}

// Each shipped case is its own test (ctest runs them in parallel and times each alone: one test
// over every case took 100-200 s, several times that under the sanitizers).
const std::vector<std::string> kShippedCases{"block-ts1",          "block-ts2",
                                             "block-ts3",          "cabinet-user-target",
                                             "glovebox-pair-unbraced",
                                             "glovebox-pair",      "glovebox-single",
                                             "glovebox-steel-pads"};

void check_material_trials(const std::string& name) {
    const fs::path file = fs::path(freestand::test::source_dir()) / "cases" / (name + ".toml");
    // Trial and direct assessment must agree for any number of histories: 3 keep it quick.
    Case c = read_case(file);
    c.options.histories_per_level = 3;
    c.options.max_histories_per_level = c.options.histories_per_level;
    c.options.step_check = false;  // it only reports, at half these tests' time
    const Upgrade search = search_materials(c);
    for (const Material& m : materials()) {
        INFO(file.filename().string() << " with " << m.name);
        Case edited = parse_case(edited_case_text(file, m.name), file.string());
        edited.options.histories_per_level = 3;
        edited.options.max_histories_per_level = edited.options.histories_per_level;
        edited.options.step_check = false;
        const AssessmentResult direct = assess::assess(edited);
        const auto trial =
            std::find_if(search.trials.begin(), search.trials.end(),
                         [&](const MaterialTrial& t) { return t.material == m.name; });
        REQUIRE(trial != search.trials.end());
        check_same_verdict(direct.own, trial->governing);
        CHECK(trial->mu_s_range == edited.component.base.mu_s_range);
    }
}

}  // namespace

TEST_CASE("the per-case policy tests below cover every shipped case", "[assess][policy]") {
    std::vector<std::string> names;
    for (const fs::path& file : shipped_cases()) names.push_back(file.stem().string());
    CHECK(names == kShippedCases);
}

#define FREESTAND_MATERIAL_TRIAL_TEST(NAME)                                                   \
    TEST_CASE("every material trial equals a direct assessment of the edited case: " NAME,  \
              "[assess][policy][materials]") {                                               \
        check_material_trials(NAME);                                                         \
    }
FREESTAND_MATERIAL_TRIAL_TEST("block-ts1")
FREESTAND_MATERIAL_TRIAL_TEST("block-ts2")
FREESTAND_MATERIAL_TRIAL_TEST("block-ts3")
FREESTAND_MATERIAL_TRIAL_TEST("cabinet-user-target")
FREESTAND_MATERIAL_TRIAL_TEST("glovebox-pair")
FREESTAND_MATERIAL_TRIAL_TEST("glovebox-single")
FREESTAND_MATERIAL_TRIAL_TEST("glovebox-steel-pads")
#undef FREESTAND_MATERIAL_TRIAL_TEST

// Two joined units: each unit's material trials are its own case with the material's whole
// property set (the per-unit case assess_joined assesses).
TEST_CASE("every material trial equals a direct assessment: each unit of glovebox-pair-unbraced",
          "[assess][policy][materials][joined]") {
    const Case pair =
        read_case(fs::path(freestand::test::source_dir()) / "cases" / "glovebox-pair-unbraced.toml");
    REQUIRE(pair.units.size() == 2);
    for (std::size_t i = 0; i < 2; ++i) {
        Case c = unit_case(pair, i);
        c.options.histories_per_level = 3;  // any number must agree: 3 keep it quick
        c.options.max_histories_per_level = c.options.histories_per_level;
        c.options.step_check = false;
        const Upgrade search = search_materials(c);
        REQUIRE(search.trials.size() == materials().size());
        for (const MaterialTrial& t : search.trials) {
            INFO("unit " << i + 1 << " with " << t.material);
            const AssessmentResult direct = assess::assess(with_base_material(c, t.material));
            check_same_verdict(direct.own, t.governing);
        }
    }
}

namespace {

void check_auto_equals_always(const std::string& name) {
    Case c = read_case(fs::path(freestand::test::source_dir()) / "cases" / (name + ".toml"));
    // The rule holds for any number of sets: 7, without growth, keep it quick.
    c.options.histories_per_level = 7;
    c.options.max_histories_per_level = c.options.histories_per_level;
    c.options.step_check = false;  // it only reports, at half these tests' time
    c.options.simulate = SimulatePolicy::automatic;
    const AssessmentResult automatic = assess::assess(c);
    c.options.simulate = SimulatePolicy::always;
    const AssessmentResult always = assess::assess(c);
    CHECK(verdict_text(automatic.overall.verdict) == verdict_text(always.overall.verdict));
    check_same_verdict(automatic.overall, always.overall);
    check_same_verdict(automatic.own, always.own);
    REQUIRE(automatic.levels.size() == always.levels.size());
    for (std::size_t i = 0; i < automatic.levels.size(); ++i) {
        CHECK(verdict_text(automatic.levels[i].verdict) == verdict_text(always.levels[i].verdict));
        CHECK(margin_text(automatic.levels[i].verdict) == margin_text(always.levels[i].verdict));
    }
}

}  // namespace

TEST_CASE("simulate = \"auto\" and \"always\" give the same verdict: glovebox-pair-unbraced",
          "[assess][policy][simulate][joined]") {
    Case c = read_case(fs::path(freestand::test::source_dir()) / "cases" / "glovebox-pair-unbraced.toml");
    // As check_auto_equals_always: any number of sets, 7 without growth.
    c.options.histories_per_level = 7;
    c.options.max_histories_per_level = c.options.histories_per_level;
    c.options.step_check = false;  // it only reports, at half these tests' time
    c.options.simulate = SimulatePolicy::automatic;
    const AssessmentResult automatic = assess::assess(c);
    c.options.simulate = SimulatePolicy::always;
    const AssessmentResult always = assess::assess(c);
    REQUIRE(automatic.joined);
    REQUIRE(always.joined);
    CHECK(automatic.joined->verdict == always.joined->verdict);
    for (std::size_t i = 0; i < 2; ++i)
        check_same_verdict(automatic.joined->units[i].overall, always.joined->units[i].overall);
}

#define FREESTAND_SIMULATE_POLICY_TEST(NAME)                                                  \
    TEST_CASE("simulate = \"auto\" and \"always\" give the same verdict: " NAME,             \
              "[assess][policy][simulate]") {                                                \
        check_auto_equals_always(NAME);                                                      \
    }
FREESTAND_SIMULATE_POLICY_TEST("block-ts1")
FREESTAND_SIMULATE_POLICY_TEST("block-ts2")
FREESTAND_SIMULATE_POLICY_TEST("block-ts3")
FREESTAND_SIMULATE_POLICY_TEST("cabinet-user-target")
FREESTAND_SIMULATE_POLICY_TEST("glovebox-pair")
FREESTAND_SIMULATE_POLICY_TEST("glovebox-single")
FREESTAND_SIMULATE_POLICY_TEST("glovebox-steel-pads")
#undef FREESTAND_SIMULATE_POLICY_TEST

}  // namespace freestand_test_assess_test_policy
