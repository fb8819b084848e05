#include <catch2/catch.hpp>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <unistd.h>
#include <string>

#include "support/case_text.hpp"
#include "support/paths.hpp"
#include "assess/case.hpp"
#include "core/errors.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_assess_test_case {

namespace fs = std::filesystem;
using namespace freestand;
using namespace freestand::assess;

namespace {

const std::string& base_component = test::box_component;
const std::string& base_site = test::box_site;

std::string error_of(const std::string& text) { return test::case_error(text); }

}  // namespace

TEST_CASE("the shipped cases parse", "[assess][case]") {
    for (const char* name : {"glovebox-single", "glovebox-steel-pads", "glovebox-pair", "block-ts1",
                             "block-ts2", "block-ts3"}) {
        INFO(name);
        const Case c =
            read_case(fs::path(freestand::test::source_dir()) / "cases" / (std::string(name) + ".toml"));
        CHECK(c.site.pga_g == std::vector<double>{0.1, 0.2, 0.3, 0.4});
        CHECK(c.options.histories_per_level == 30);
        CHECK(c.options.max_histories_per_level == 120);  // docs/methods.md s.6 step 4
    }
}

TEST_CASE("glove box inertia derived from p reproduces p", "[assess][case]") {
    const Case c = read_case(fs::path(freestand::test::source_dir()) / "cases" / "glovebox-single.toml");
    const block::Block b = c.component.block(Direction::x);
    // p = 1.97 rad/s is the published value the inertia is derived from (the case file).
    CHECK(b.p_radps(block::Edge::right) == Approx(1.97).epsilon(1e-12));
    // Hand calculation: R = sqrt(0.526^2 + 1.22^2) = 1.32856 m, I_O = 382 * 9.81 * R / 1.97^2
    // = 1282.9 kg m^2, I_c = I_O - M R^2 = 608.6 kg m^2.
    CHECK(c.component.x.inertia_cg_kgm2 == Approx(608.6).epsilon(1e-3));
    CHECK(c.component.base.mu_s == 0.15);
    CHECK(c.component.base.material == "PVC sheet on concrete");
    CHECK_FALSE(c.component.base.restitution.has_value());
    CHECK(c.component.x.free_rocking_band_hz.has_value());
}

TEST_CASE("the case's own assumptions are kept for the report, first", "[assess][case]") {
    const Case c = read_case(fs::path(freestand::test::source_dir()) / "cases" / "glovebox-pair.toml");
    REQUIRE(c.assumptions.size() >= 4);
    CHECK(c.assumptions.front().rfind("Case: boxes side by side along x", 0) == 0);
    CHECK(
        error_of(base_component + "assumptions = [1]\n" + base_site) ==
        "case.toml:9: component.assumptions: expected an array of strings, got an integer element");
}

TEST_CASE("a uniform block from its box and a material from the table", "[assess][case]") {
    const Case c = read_case(fs::path(freestand::test::source_dir()) / "cases" / "block-ts1.toml");
    CHECK(c.component.uniform_block);
    CHECK(c.component.cg_height_m == Approx(0.6));
    CHECK(c.component.x.b_left_m == Approx(0.15));
    // I_c = M (b^2 + h^2) / 3 = 38 (0.0225 + 0.36) / 3 = 4.845 kg m^2 (docs/methods.md s.1).
    CHECK(c.component.x.inertia_cg_kgm2 == Approx(4.845).epsilon(1e-12));
    CHECK(c.component.base.mu_s == 0.72);
    CHECK(c.component.base.restitution.value() == 0.98);
}

TEST_CASE("defaults are applied and stated", "[assess][case]") {
    const Case c = parse_case(base_component + base_site, "case.toml");
    CHECK(c.component.base.mu_k == 0.3);
    CHECK(c.component.required_overturn_fs == 1.5);
    CHECK(c.site.vertical_ratio == 1.0);  // RG 1.60's vertical ZPA is the horizontal PGA
    CHECK(c.site.sliding_damping == 0.10);
    CHECK(c.options.simulate == SimulatePolicy::automatic);
    CHECK(c.options.seed == 1);
    CHECK(c.options.histories_per_level == 30);
    CHECK(c.options.max_histories_per_level == 120);
    // height, friction bounds, mu_k, inertia, restitution, vertical ratio, energy high-pass corner
    CHECK(c.assumptions.size() == 7);
    CHECK(c.assumptions.front() ==
          "height_m not given: the body's top taken at twice the CG height, 2.000 m (the point of "
          "the simulated top acceleration; docs/methods.md s.1).");
    CHECK(c.component.base.mu_s_range == std::array<double, 2>{0.8 * 0.3, 1.2 * 0.3});
    CHECK(c.component.base.mu_s_range_source == "default 0.8-1.2 x mu_s (docs/methods.md s.7)");
    CHECK(std::any_of(c.assumptions.begin(), c.assumptions.end(), [](const std::string& a) {
        return a.rfind("Friction bounds not given: mu_s in [0.24, 0.36]", 0) == 0;
    }));
    CHECK_FALSE(c.component.base.restitution_range.has_value());
    CHECK_FALSE(c.component.allowable_relative_m.has_value());
}

TEST_CASE("friction and restitution bounds from the case", "[assess][case][bounds]") {
    const std::string with_ranges = base_component +
                                    "mu_s_range = [0.25, 0.4]\nrestitution = 0.9\n"
                                    "restitution_range = [0.85, 0.95]\n"
                                    "allowable_relative_m = 0.025\n" +
                                    base_site;
    const Case c = parse_case(with_ranges, "case.toml");
    CHECK(c.component.base.mu_s == 0.3);
    CHECK(c.component.base.mu_s_range == std::array<double, 2>{0.25, 0.4});
    CHECK(c.component.base.mu_s_range_source == "case file (mu_s_range)");
    CHECK(c.component.base.restitution_range == std::array<double, 2>{0.85, 0.95});
    CHECK(*c.component.allowable_relative_m == 0.025);
    // A range alone gives the nominal value as its middle.
    std::string only_range = base_component;
    only_range.replace(only_range.find("mu_s = 0.3"), 10, "mu_s_range = [0.2, 0.4]");
    const Case r = parse_case(only_range + base_site, "case.toml");
    CHECK(r.component.base.mu_s == Approx(0.3));
    CHECK(r.component.base.mu_k == Approx(0.3));
}

TEST_CASE("bound errors name the key and the reason", "[assess][case][bounds]") {
    CHECK(error_of(base_component + "mu_s_range = [0.4, 0.2]\n" + base_site) ==
          "case.toml:9: component.mu_s_range: expected [lower, upper] with lower <= upper, got "
          "[0.4, 0.2]");
    CHECK(error_of(base_component + "mu_s_range = [0.1, 0.2]\n" + base_site) ==
          "case.toml:9: component.mu_s_range: mu_s = 0.3 lies outside [0.1, 0.2]");
    CHECK(error_of(base_component + "restitution_range = [0.5, 1.2]\n" + base_site)
              .find("component.restitution_range") != std::string::npos);
    CHECK(error_of(base_component + "restitution = 0.9\nrestitution_range = [0.5, 0.8]\n" +
                   base_site) ==
          "case.toml:10: component.restitution_range: restitution = 0.9 lies outside [0.5, 0.8]");
}

TEST_CASE("a material trial case reads as a case naming only that material",
          "[assess][case][bounds]") {
    std::string named = base_component;
    named.replace(named.find("mu_s = 0.3"), 10, "base_material = \"aluminium\"");
    const Case direct = parse_case(named + base_site, "case.toml");
    const Case trial = with_base_material(parse_case(base_component + base_site, "case.toml"),
                                          "aluminium");
    const BaseContact& a = direct.component.base;
    const BaseContact& b = trial.component.base;
    CHECK(a.material == b.material);
    CHECK(a.mu_s == b.mu_s);
    CHECK(a.mu_k == b.mu_k);
    CHECK(a.restitution == b.restitution);
    CHECK(*b.restitution == 0.97);
    CHECK(a.mu_s_range == b.mu_s_range);
    CHECK(b.mu_s_range == std::array<double, 2>{0.3, 0.5});  // the literature range
    CHECK(a.restitution_range == b.restitution_range);
}

TEST_CASE("materials take the literature friction range, a case's own bounds for its own base stay",
          "[assess][case][bounds]") {
    std::string named = base_component;
    named.replace(named.find("mu_s = 0.3"), 10, "base_material = \"HDPE\"");
    const Case c = parse_case(named + base_site, "case.toml");
    CHECK(c.component.base.mu_s_range == std::array<double, 2>{0.2, 0.4});
    CHECK(std::any_of(c.assumptions.begin(), c.assumptions.end(), [](const std::string& a) {
        return a.rfind("Friction bounds of HDPE: mu_s in [0.2, 0.4] (literature range", 0) == 0;
    }));
    std::string own = base_component;
    own.replace(own.find("mu_s = 0.3"), 10,
                "base_material = \"HDPE\"\nmu_s_range = [0.3, 0.34]");
    const Case with_own = parse_case(own + base_site, "case.toml");
    CHECK(with_own.component.base.mu_s_range == std::array<double, 2>{0.3, 0.34});
    // The trial of its own material keeps the case's bounds; another material brings its own.
    CHECK(with_base_material(with_own, "hdpe").component.base.mu_s_range ==
          std::array<double, 2>{0.3, 0.34});
    CHECK(with_base_material(with_own, "steel").component.base.mu_s_range ==
          std::array<double, 2>{0.7, 0.8});
    CHECK(with_base_material(with_own, "PVC sheet on concrete").component.base.mu_s_range ==
          std::array<double, 2>{0.12, 0.18});
}

TEST_CASE("case errors name file, line, key and the allowed range", "[assess][case]") {
    SECTION("TOML syntax") {
        CHECK(error_of("[component\nname = 1").rfind("case.toml:1: TOML syntax error: ", 0) == 0);
    }
    SECTION("unknown key") {
        const std::string e = error_of(base_component + "mass_lb = 3\n" + base_site);
        CHECK(e.rfind("case.toml:9: component.mass_lb: unknown key; allowed keys: name, ", 0) == 0);
    }
    SECTION("unknown table") {
        CHECK(error_of(base_component + base_site + "[extra]\n") ==
              "case.toml:11: extra: unknown table; allowed tables: [component] (or two [[unit]] and a "
              "[tunnel]), [site], [options], [uncertainty]");
    }
    SECTION("missing table") {
        CHECK(error_of(base_component) == "case.toml: site: missing required table [site]");
    }
    SECTION("missing key") {
        CHECK(error_of("[component]\nname = \"a\"\n" + base_site) ==
              "case.toml:1: component.mass_kg: missing required key (a number in [0.001, 100000000])");
    }
    SECTION("wrong type") {
        CHECK(error_of(base_component + base_site + "vertical_ratio = \"high\"\n") ==
              "case.toml:11: site.vertical_ratio: expected a number in (0, 1.5], got a string");
    }
    SECTION("out of range") {
        CHECK(
            error_of(base_component + base_site + "sliding_damping = 0.2\n") ==
            "case.toml:11: site.sliding_damping: value 0.2 is out of range; expected [0.005, 0.1]");
    }
    SECTION("array of the wrong size") {
        std::string text = base_component + base_site;
        text.replace(text.find("[0.4, 0.5]"), 10, "[0.4]");
        CHECK(error_of(text) ==
              "case.toml:5: component.cg_to_edge_x_m: expected an array of 2 "
              "numbers in (0, 100], got 1 element(s)");
    }
    SECTION("levels not increasing") {
        std::string text = base_component + base_site;
        text.replace(text.find("[0.1, 0.2]"), 10, "[0.2, 0.1]");
        CHECK(error_of(text) ==
              "case.toml:10: site.pga_g: levels must be strictly increasing; 0.1 "
              "follows 0.2");
    }
    SECTION("unknown material") {
        std::string text = base_component + base_site;
        text.replace(text.find("mu_s = 0.3"), 10, "base_material = \"rubber\"");
        CHECK(error_of(text).rfind("case.toml:7: component.base_material: unknown material "
                                   "\"rubber\"; expected one of \"plywood\", ",
                                   0) == 0);
    }
    SECTION("mu_k above mu_s") {
        CHECK(error_of(base_component + "mu_k = 0.4\n" + base_site) ==
              "case.toml:9: component.mu_k: value 0.4 is out of range; expected [0, 0.3]");
    }
    SECTION("conflicting geometry") {
        CHECK(error_of(base_component + "width_m = 1.0\n" + base_site) ==
              "case.toml:9: component.width_m: give either width_m/depth_m/height_m (uniform "
              "block) or cg_height_m with cg_to_edge_x_m/cg_to_edge_y_m (and optional "
              "height_m), not both");
    }
    SECTION("p too large for a positive I_c") {
        const std::string e = error_of(base_component + "p_radps = 5.0\n" + base_site);
        // p < sqrt(g / R), R the larger critical-edge R: sqrt(0.4^2 + 1) = 1.0770 m -> 3.0180
        // rad/s.
        CHECK(e.rfind("case.toml:9: component.p_radps: value 5 is out of range; expected (0, 3.018",
                      0) == 0);
    }
    SECTION("free-rocking band reversed") {
        CHECK(error_of(base_component + "free_rocking_band_hz = [4.0, 2.0]\n" + base_site) ==
              "case.toml:9: component.free_rocking_band_hz: expected [lo, hi] with lo < hi, got "
              "[4, 2]");
    }
    SECTION("bad simulate option") {
        CHECK(error_of(base_component + base_site + "[options]\nsimulate = \"sometimes\"\n") ==
              "case.toml:12: options.simulate: unknown value \"sometimes\"; expected \"auto\", "
              "\"always\" or \"never\"");
    }
    SECTION("integer option out of range and wrong type") {
        CHECK(error_of(base_component + base_site + "[options]\nhistories_per_level = 0\n") ==
              "case.toml:12: options.histories_per_level: value 0 is out of range; expected an "
              "integer in [1, 1000]");
        CHECK(error_of(base_component + base_site + "[options]\nhistories_per_level = 2.5\n") ==
              "case.toml:12: options.histories_per_level: expected an integer in [1, 1000], got a "
              "number");
    }
    SECTION("the cap on grown levels: from histories_per_level to 1000") {
        const std::string options = base_component + base_site + "[options]\n";
        CHECK(error_of(options + "histories_per_level = 40\nmax_histories_per_level = 39\n") ==
              "case.toml:13: options.max_histories_per_level: value 39 is out of range; expected "
              "an integer in [40, 1000]");
        CHECK(error_of(options + "max_histories_per_level = 1001\n") ==
              "case.toml:12: options.max_histories_per_level: value 1001 is out of range; "
              "expected an integer in [30, 1000]");
        CHECK(error_of(options + "max_histories_per_level = \"many\"\n") ==
              "case.toml:12: options.max_histories_per_level: expected an integer in [30, 1000], "
              "got a string");
        // Without a cap, a level never holds fewer sets than it starts with.
        const Case big = parse_case(options + "histories_per_level = 200\n", "case.toml");
        CHECK(big.options.max_histories_per_level == 200);
    }
    SECTION("unknown design") {
        CHECK(error_of(base_component + base_site + "design = \"asce7\"\n") ==
              "case.toml:11: site.design: unknown design spectrum \"asce7\"; expected \"rg1.60\"");
    }
    SECTION("no friction at all") {
        std::string text = base_component + base_site;
        text.erase(text.find("mu_s = 0.3\n"), 11);
        CHECK(error_of(text).rfind("case.toml:1: component.mu_s: missing required key (give "
                                   "base_material, one of \"plywood\"",
                                   0) == 0);
    }
    SECTION("a body's height at or below its CG") {
        CHECK(error_of(base_component + "height_m = 1.0\n" + base_site) ==
              "case.toml:9: component.height_m: value 1 is out of range; expected (1, 100]");
    }
}

TEST_CASE("a missing case file is an IoError", "[assess][case]") {
    CHECK_THROWS_AS(read_case("/nonexistent/case.toml"), IoError);
}

TEST_CASE("energy DeltaD keys: a corner or a table with one value per level",
          "[assess][case][energy]") {
    const Case d = parse_case(base_component + base_site, "case.toml");
    CHECK(d.site.energy_highpass_hz == 0.5);
    CHECK_FALSE(d.site.energy_table_displacement_m.has_value());
    const Case corner = parse_case(base_component + base_site + "energy_highpass_hz = 0.3\n",
                                   "case.toml");
    CHECK(corner.site.energy_highpass_hz == 0.3);
    const Case table = parse_case(
        base_component + base_site + "energy_table_displacement_m = [0.02, 0.04]\n", "case.toml");
    CHECK(*table.site.energy_table_displacement_m == std::vector<double>{0.02, 0.04});
    CHECK(error_of(base_component + base_site + "energy_table_displacement_m = [0.02]\n") ==
          "case.toml:11: site.energy_table_displacement_m: expected one displacement per PGA "
          "level (2), got 1");
    CHECK(error_of(base_component + base_site +
                   "energy_highpass_hz = 0.5\nenergy_table_displacement_m = [0.02, 0.04]\n")
              .find("site.energy_highpass_hz: energy_highpass_hz and energy_table_displacement_m "
                    "are not used together") != std::string::npos);
    CHECK(error_of(base_component + base_site + "energy_highpass_hz = 0\n")
              .find("site.energy_highpass_hz") != std::string::npos);
}

TEST_CASE("a level the vertical PGA makes weightless, a zero vertical ratio: refused at the key",
          "[assess][case][hardening]") {
    // Read without these checks, pga_g = [1.5, 3.0] is refused later by the pipeline as
    // "peak_v_g: value 1 is out of range; expected [0, 1)", and vertical_ratio = 0 (read as
    // [0, 1.5]) as "vertical_ratio: value 0 is out of range; expected (0, 2]", both without
    // file:line.
    CHECK(error_of(base_component +
                   "[site]\npga_g = [1.5, 3.0]\nvertical_ratio = 0.6666666666666666\n") ==
          "case.toml:10: site.pga_g: PGA 1.5 g with a vertical/horizontal ratio of 0.6667 gives a "
          "vertical PGA of 1 g; at 1 g or more, taken downward as the static checks take it, the "
          "block is weightless: each level needs pga_g x ratio < 1");
    // The documented range [0.001, 3] holds with a smaller ratio.
    const Case c = parse_case(base_component + "[site]\npga_g = [1.5, 3.0]\nvertical_ratio = 0.3\n",
                              "case.toml");
    CHECK(c.site.pga_g == std::vector<double>{1.5, 3.0});
    CHECK(error_of(base_component + base_site + "vertical_ratio = 0\n") ==
          "case.toml:11: site.vertical_ratio: value 0 is out of range; expected (0, 1.5]");
}

TEST_CASE("control characters in case text are refused at their key", "[assess][case][hardening]") {
    // ESC and BEL in a name would otherwise pass raw into stdout and the reports.
    std::string with_esc = base_component;
    with_esc.replace(with_esc.find("\"Box\""), 5, "\"Box\\u001b[31m\"");
    CHECK(error_of(with_esc + base_site) ==
          "case.toml:2: component.name: contains the control character U+001B at byte 4; "
          "expected printable text");
    CHECK(error_of(base_component + "assumptions = [\"ring\\u0007\"]\n" + base_site)
              .find("component.assumptions: contains the control character U+0007") !=
          std::string::npos);
    CHECK(error_of(base_component + "description = \"nul\\u0000\"\n" + base_site) ==
          "case.toml:9: component.description: contains the control character U+0000 at byte 4; "
          "expected printable text");
    // Line breaks and tabs in free text stay allowed.
    CHECK_NOTHROW(parse_case(base_component + "description = \"two\\nlines\\tand a tab\"\n" +
                                 base_site,
                             "case.toml"));
}

TEST_CASE("realism ranges: RG 1.60's by default, set or refused at their keys",
          "[assess][case][realism]") {
    const Case d = parse_case(base_component + base_site, "case.toml");
    REQUIRE(d.site.realism.va_mps_per_g.has_value());
    CHECK(d.site.realism.va_mps_per_g->min == 0.8);
    CHECK(d.site.realism.va_mps_per_g->max == 2.0);
    CHECK(d.site.realism.adv2->max == 8.0);
    CHECK(*d.site.realism.da_max_m_per_g == 1.3);
    CHECK(d.site.realism.pga_over_zpa.max == 1.1);
    const Case set = parse_case(base_component + base_site +
                                    "va_range_mps_per_g = [0.5, 1.5]\nadv2_range = [3, 9]\n"
                                    "da_max_m_per_g = 1.0\n",
                                "case.toml");
    CHECK(set.site.realism.va_mps_per_g->min == 0.5);
    CHECK(set.site.realism.adv2->max == 9.0);
    CHECK(*set.site.realism.da_max_m_per_g == 1.0);
    CHECK(error_of(base_component + base_site + "va_range_mps_per_g = [2.0, 0.8]\n") ==
          "case.toml:11: site.va_range_mps_per_g: [2, 0.8]: expected [min, max] with min < max");
    CHECK(error_of(base_component + base_site + "adv2_range = [2]\n")
              .find("site.adv2_range") != std::string::npos);
    CHECK(error_of(base_component + base_site + "da_max_m_per_g = 0\n")
              .find("site.da_max_m_per_g") != std::string::npos);
}

TEST_CASE("target files carry no V/A, AD/V^2, D/A range unless the case gives one",
          "[assess][case][realism]") {
    const fs::path dir = fs::temp_directory_path() / ("freestand_realism_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    {
        std::ofstream(dir / "h.csv") << "# damping: 0.05\nfrequency_hz,psa_g\n0.05,0.05\n1,0.6\n"
                                        "10,0.5\n100,0.25\n";
    }
    const std::string site = "[site]\npga_g = [0.1]\ntarget_h_file = \"h.csv\"\n";
    std::ofstream(dir / "a.toml") << base_component << site;
    const Case none = read_case(dir / "a.toml");
    CHECK_FALSE(none.site.realism.va_mps_per_g.has_value());
    CHECK_FALSE(none.site.realism.da_max_m_per_g.has_value());
    CHECK(std::any_of(none.assumptions.begin(), none.assumptions.end(), [](const std::string& a) {
        return a.find("reported, not checked") != std::string::npos;
    }));
    std::ofstream(dir / "b.toml") << base_component << site << "da_max_m_per_g = 1.2\n";
    const Case given = read_case(dir / "b.toml");
    CHECK(*given.site.realism.da_max_m_per_g == 1.2);
    CHECK_FALSE(given.site.realism.va_mps_per_g.has_value());
    fs::remove_all(dir);
}

TEST_CASE("a case line beyond 4096 characters is refused before the TOML parser sees it",
          "[assess][case][limits][hardening]") {
    // A dotted key of 100,000 parts (a.a.a...) overflows toml++'s recursion (exit 139); the
    // fuzzer's 16 KiB inputs cannot reach that depth.
    std::string deep = "a";
    for (int i = 0; i < 100000; ++i) deep += ".a";
    CHECK(error_of(base_component + base_site + deep + " = 1\n") ==
          "case.toml:11: line is 200005 characters long; a case file's lines are limited to 4096 "
          "(README, Limits)");
    // 4096 characters are still read (and then refused as TOML names no such key).
    const std::string longest = "x = \"" + std::string(4090, 'y') + "\"\n";
    CHECK(error_of(base_component + base_site + longest).find("site.x: unknown key") !=
          std::string::npos);
}

TEST_CASE("[uncertainty] laws are read or refused at their key", "[assess][case][fragility]") {
    const Case none = parse_case(base_component + base_site, "case.toml");
    CHECK_FALSE(none.uncertainty.mu_s.has_value());
    CHECK_FALSE(none.uncertainty.restitution.has_value());
    const Case c = parse_case(base_component + base_site +
                                  "[uncertainty]\n"
                                  "mu_s = { dist = \"uniform\", lo = 0.12, hi = 0.18 }\n"
                                  "restitution = { dist = \"lognormal\", median = 0.9, beta = 0.1 }\n",
                              "case.toml");
    REQUIRE(c.uncertainty.mu_s.has_value());
    CHECK(c.uncertainty.mu_s->kind == core::Distribution::Kind::uniform);
    CHECK(c.uncertainty.mu_s->a == 0.12);
    CHECK(c.uncertainty.mu_s->b == 0.18);
    REQUIRE(c.uncertainty.restitution.has_value());
    CHECK(c.uncertainty.restitution->kind == core::Distribution::Kind::lognormal);
    CHECK(c.uncertainty.restitution->a == 0.9);
    CHECK(c.uncertainty.restitution->upper == 1.0);  // a restitution above 1 is never drawn
    const std::string u = base_component + base_site + "[uncertainty]\n";
    CHECK(error_of(u + "mu_s = { dist = \"uniform\", lo = nan, hi = 0.2 }\n") ==
          "case.toml:12: uncertainty.mu_s.lo: value nan is out of range; expected [0, 2]");
    CHECK(error_of(u + "mu_s = { dist = \"uniform\", lo = 0.3, hi = 0.2 }\n") ==
          "case.toml:12: uncertainty.mu_s.hi: 0.2 is below lo = 0.3; expected lo <= hi");
    CHECK(error_of(u + "mu_s = { lo = 0.1, hi = 0.2 }\n") ==
          "case.toml:12: uncertainty.mu_s.dist: missing required key (a string)");
    CHECK(error_of(u + "mu_s = { dist = \"lognormal\", median = 0.2, beta = 0 }\n") ==
          "case.toml:12: uncertainty.mu_s.beta: value 0 is out of range; expected (0, 2]");
    CHECK(error_of(u + "mu_s = { dist = \"weibull\" }\n") ==
          "case.toml:12: uncertainty.mu_s.dist: \"weibull\"; expected \"uniform\" or \"lognormal\"");
    CHECK(error_of(u + "restitution = { dist = \"uniform\", lo = 0.5, hi = 1.5 }\n") ==
          "case.toml:12: uncertainty.restitution.hi: value 1.5 is out of range; expected [0, 1]");
    CHECK(error_of(u + "mu_s = 0.2\n") ==
          "case.toml:12: uncertainty.mu_s: expected a table, got a number");
    CHECK(error_of(u + "mu_s = { dist = \"uniform\", lo = 0.1, hi = 0.2, x = 1 }\n") ==
          "case.toml:12: uncertainty.mu_s.x: unknown key; allowed keys: dist, lo, hi");
    CHECK(error_of(u + "mu_k = { dist = \"uniform\", lo = 0.1, hi = 0.2 }\n")
              .find("uncertainty.mu_k: unknown key") != std::string::npos);
}

TEST_CASE("[options] fragility keys: defaults, values and errors", "[assess][case][fragility]") {
    const Case off = parse_case(base_component + base_site, "case.toml");
    CHECK_FALSE(off.options.fragility.enabled);
    const std::string o = base_component + base_site + "[options]\n";
    const Case on = parse_case(o + "fragility = true\n", "case.toml");
    CHECK(on.options.fragility.enabled);
    CHECK(on.options.fragility.samples == 100);
    CHECK(on.options.fragility.pga_g.size() == 10);
    const Case set = parse_case(
        o + "fragility = true\nfragility_pga_g = [0.2, 0.4]\nfragility_samples = 30\n", "case.toml");
    CHECK(set.options.fragility.pga_g == std::vector<double>{0.2, 0.4});
    CHECK(set.options.fragility.samples == 30);
    CHECK(error_of(o + "fragility = true\nfragility_pga_g = [0.4, 0.2]\n")
              .find("options.fragility_pga_g: levels must be strictly increasing") !=
          std::string::npos);
    CHECK(error_of(o + "fragility = true\nfragility_pga_g = [0.2, 4]\n")
              .find("options.fragility_pga_g") != std::string::npos);
    CHECK(error_of(o + "fragility = true\nfragility_samples = 0\n")
              .find("options.fragility_samples") != std::string::npos);
    CHECK(error_of(o + "fragility_samples = 30\n")
              .find("options.fragility_samples: applies only with fragility = true") !=
          std::string::npos);
    CHECK(error_of(o + "fragility = \"yes\"\n").find("options.fragility") != std::string::npos);
}

TEST_CASE("flexible-body mode keys: defaults stated, values read, errors at their key",
          "[assess][case][flexible]") {
    const std::string f = base_component + "fixed_base_frequency_hz = 7.5\n";
    const Case d = parse_case(f + base_site, "case.toml");
    CHECK_FALSE(d.component.modal_damping);
    const auto flex_note = std::find_if(d.assumptions.begin(), d.assumptions.end(), [](const auto& a) {
        return a.rfind("Flexible-body model", 0) == 0;
    });
    REQUIRE(flex_note != d.assumptions.end());
    CHECK(*flex_note ==
          "Flexible-body model (run where a flexible-body flag is raised): modal damping 0.02; "
          "modal mass 0.613 M (uniform cantilever, first mode); modal height 0.726 x the body's "
          "height, taken as 2 x the CG height = 1.452 m (uniform cantilever).");
    const Case set = parse_case(f + "modal_damping = 0.05\nmodal_mass_fraction = 0.7\n"
                                    "modal_height_m = 1.2\n" + base_site, "case.toml");
    CHECK(*set.component.modal_damping == 0.05);
    CHECK(*set.component.modal_mass_fraction == 0.7);
    CHECK(*set.component.modal_height_m == 1.2);
    CHECK(std::none_of(set.assumptions.begin(), set.assumptions.end(), [](const auto& a) {
        return a.rfind("Flexible-body model", 0) == 0;
    }));
    CHECK(error_of(f + "modal_damping = 1.0\n" + base_site) ==
          "case.toml:10: component.modal_damping: value 1 is out of range; expected [0, 1)");
    CHECK(error_of(f + "modal_mass_fraction = 0\n" + base_site) ==
          "case.toml:10: component.modal_mass_fraction: value 0 is out of range; expected (0, 1)");
    CHECK(error_of(f + "modal_height_m = -1\n" + base_site) ==
          "case.toml:10: component.modal_height_m: value -1 is out of range; expected (0, 100]");
    CHECK(error_of(base_component + "modal_damping = 0.05\n" + base_site) ==
          "case.toml:9: component.modal_damping: needs fixed_base_frequency_hz (the mode it "
          "describes)");
    CHECK(error_of(f + "modal_mass_fraction = 0.95\nmodal_height_m = 1.9\n" + base_site)
              .rfind("case.toml:11: component.modal_height_m: in the x direction: a modal mass of "
                     "0.95 M at 1.9 m carries more second moment than the body has",
                     0) == 0);
}

TEST_CASE("site.dbe_pga_g: absent by default, read and echoed, refused outside 0 < DBE <= 3 g",
          "[assess][case][goal]") {
    CHECK_FALSE(parse_case(base_component + base_site, "case.toml").site.dbe_pga_g.has_value());
    const Case c = parse_case(base_component + base_site + "dbe_pga_g = 0.3\n", "case.toml");
    REQUIRE(c.site.dbe_pga_g.has_value());
    CHECK(*c.site.dbe_pga_g == 0.3);
    CHECK(std::any_of(c.assumptions.begin(), c.assumptions.end(), [](const std::string& a) {
        return a.find("(DBE) PGA 0.3 g (site.dbe_pga_g)") != std::string::npos;
    }));
    CHECK(parse_case(base_component + base_site + "dbe_pga_g = 3\n", "case.toml").site.dbe_pga_g ==
          3.0);
    CHECK(error_of(base_component + base_site + "dbe_pga_g = 0\n") ==
          "case.toml:11: site.dbe_pga_g: value 0 is out of range; expected [0.001, 3]");
    CHECK(error_of(base_component + base_site + "dbe_pga_g = -0.2\n") ==
          "case.toml:11: site.dbe_pga_g: value -0.2 is out of range; expected [0.001, 3]");
    CHECK(error_of(base_component + base_site + "dbe_pga_g = 3.5\n") ==
          "case.toml:11: site.dbe_pga_g: value 3.5 is out of range; expected [0.001, 3]");
    CHECK(error_of(base_component + base_site + "dbe_pga_g = \"0.3 g\"\n") ==
          "case.toml:11: site.dbe_pga_g: expected a number in [0.001, 3], got a string");
}

}  // namespace freestand_test_assess_test_case
