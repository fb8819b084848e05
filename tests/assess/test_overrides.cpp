// Overrides (batch lists, README "Batch"): an overridden case reads exactly as a case file carrying
// the values, and every bad value is an InputError naming the key.
#include <catch2/catch.hpp>

#include <algorithm>

#include "assess/case.hpp"
#include "assess/overrides.hpp"
#include "core/errors.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_assess_test_overrides {

using namespace freestand;
using namespace freestand::assess;

namespace {

const std::string own_base = R"([component]
name = "Box"
mass_kg = 100.0
cg_height_m = 1.0
cg_to_edge_x_m = [0.4, 0.5]
cg_to_edge_y_m = [0.3, 0.3]
mu_s = 0.3
mu_k = 0.25
mu_s_range = [0.2, 0.4]
restitution = 0.9
allowable_slide_m = 0.05

[site]
pga_g = [0.1, 0.2]
)";

// The same case as its author would write it with the overridden values.
const std::string edited = R"([component]
name = "Box"
mass_kg = 100.0
cg_height_m = 1.0
cg_to_edge_x_m = [0.4, 0.5]
cg_to_edge_y_m = [0.3, 0.3]
base_material = "steel"
allowable_slide_m = 0.05

[site]
pga_g = [0.15, 0.3, 0.45]

[options]
seed = 42
histories_per_level = 2
)";

CaseOverrides all_overrides() {
    CaseOverrides o;
    o.pga_g = std::vector<double>{0.15, 0.3, 0.45};
    o.base_material = "steel";
    o.seed = 42;
    o.histories_per_level = 2;
    return o;
}

SourceLocation at(const std::string& key) { return SourceLocation{"list.csv", 4, key}; }

std::string check_error(const CaseOverrides& o) {
    try {
        check_overrides(o, at);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace

TEST_CASE("an overridden case reads as the case file carrying the values", "[assess][overrides]") {
    const Case over = parse_case(own_base, "case.toml", all_overrides());
    const Case file = parse_case(edited, "case.toml");
    CHECK(over.site.pga_g == file.site.pga_g);
    CHECK(over.options.seed == 42);
    CHECK(over.options.histories_per_level == 2);
    CHECK(over.options.seed == file.options.seed);
    const BaseContact& a = over.component.base;
    const BaseContact& b = file.component.base;
    CHECK(a.material == "steel");
    CHECK(a.material == b.material);
    CHECK(a.mu_s == b.mu_s);
    CHECK(a.mu_k == b.mu_k);
    CHECK(a.restitution == b.restitution);
    CHECK(a.source == b.source);
    CHECK(a.mu_s_range == b.mu_s_range);
    CHECK(a.mu_s_range_source == b.mu_s_range_source);
    CHECK_FALSE(a.restitution_range.has_value());
    // The echoed assumptions are the edited file's, not the own base's (mu_k given, range given).
    CHECK(over.assumptions == file.assumptions);
    CHECK(std::find(over.assumptions.begin(), over.assumptions.end(),
                    "mu_k not given: taken equal to mu_s.") != over.assumptions.end());
}

TEST_CASE("no overrides read the file as it is", "[assess][overrides]") {
    const Case plain = parse_case(own_base, "case.toml");
    const Case none = parse_case(own_base, "case.toml", CaseOverrides{});
    CHECK(CaseOverrides{}.empty());
    CHECK(none.assumptions == plain.assumptions);
    CHECK(none.component.base.mu_k == 0.25);
    CHECK(none.options.seed == 1);
    CHECK(describe(CaseOverrides{}).empty());
    CHECK(describe(all_overrides()) ==
          "pga_g = [0.15, 0.3, 0.45]; base_material = \"steel\"; seed = 42; "
          "histories_per_level = 2");
}

TEST_CASE("override checks name the key and the allowed values", "[assess][overrides]") {
    CHECK(check_error(all_overrides()) == "no error");
    CaseOverrides o;
    o.pga_g = std::vector<double>{};
    CHECK(check_error(o) == "list.csv:4: pga_g: expected at least one PGA level");
    o.pga_g = std::vector<double>{0.0};
    CHECK(check_error(o) == "list.csv:4: pga_g: value 0 is out of range; expected [0.001, 3]");
    o.pga_g = std::vector<double>{0.3, 3.5};
    CHECK(check_error(o) == "list.csv:4: pga_g: value 3.5 is out of range; expected [0.001, 3]");
    o.pga_g = std::vector<double>{0.3, 0.2};
    CHECK(check_error(o) ==
          "list.csv:4: pga_g: levels must be strictly increasing; 0.2 follows 0.3");
    o = CaseOverrides{};
    o.base_material = "granite";
    CHECK_THROWS_AS(check_overrides(o, at), InputError);
    CHECK(check_error(o) == "list.csv:4: base_material: unknown material \"granite\"; expected "
                            "one of \"plywood\", \"PVC sheet on concrete\", \"HDPE\", "
                            "\"aluminium\", \"steel\"");
    o = CaseOverrides{};
    o.seed = -1;
    CHECK(check_error(o) == "list.csv:4: seed: value -1 is out of range; expected an integer in "
                            "[0, 9007199254740991]");
    o = CaseOverrides{};
    o.histories_per_level = 0;
    CHECK(check_error(o) == "list.csv:4: histories_per_level: value 0 is out of range; expected "
                            "an integer in [1, 1000]");
    o.histories_per_level = 1001;
    CHECK(check_error(o) == "list.csv:4: histories_per_level: value 1001 is out of range; "
                            "expected an integer in [1, 1000]");
}

TEST_CASE("what depends on the case is checked when the case is read", "[assess][overrides]") {
    CaseOverrides o;
    o.pga_g = std::vector<double>{1.6};  // 1.6 x 2/3 >= 1 g vertical: weightless
    CHECK_THROWS_AS(parse_case(own_base, "case.toml", o), InputError);
    try {
        parse_case(own_base, "case.toml", o);
    } catch (const InputError& e) {
        CHECK(e.where().file == "case.toml");
        CHECK(e.where().line == 0);  // the value is not in the file
        CHECK(e.where().field == "site.pga_g");
        CHECK_THAT(e.message(), Catch::StartsWith("PGA 1.6 g with a vertical/horizontal ratio"));
    }
    // A case without [options] gets the table.
    CaseOverrides s;
    s.seed = 5;
    CHECK(parse_case(own_base, "case.toml", s).options.seed == 5);
}

}  // namespace freestand_test_assess_test_overrides
