// Per-direction target files (README "Case files"): target_h_file is direction x (and y unless
// target_y_file is given); target_y_file / target_y10_file are direction y's 5% / 10% targets.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/paths.hpp"
#include "assess/level.hpp"
#include "assess/pipeline.hpp"
#include "core/errors.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_assess_test_targets_y {

namespace fs = std::filesystem;
using namespace freestand;
using namespace freestand::assess;

namespace {

const fs::path spectra_dir = fs::path(freestand::test::source_dir()) / "spectra";
const std::string label = (spectra_dir / "case.toml").string();

const std::string component = R"([component]
name = "Box"
mass_kg = 100.0
cg_height_m = 1.0
cg_to_edge_x_m = [0.4, 0.5]
cg_to_edge_y_m = [0.3, 0.3]
mu_s = 0.3
allowable_slide_m = 0.05
[site]
pga_g = [0.2]
target_h_file = "rg160-h-5pct-1g.csv"
)";

std::string error_of(const std::string& site_lines) {
    try {
        parse_case(component + site_lines, label);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

// The given file's rows with every PSA multiplied by factor (a uniformly scaled target).
fs::path scaled_file(const std::string& name, const fs::path& from, double factor) {
    const spectra::Spectrum s = spectra::read_spectrum_csv(from);
    const fs::path out = fs::temp_directory_path() / name;
    std::ofstream o(out);
    o << "# damping: " << s.damping << "\nfrequency_hz,psa_g\n";
    o.precision(17);
    for (std::size_t i = 0; i < s.frequency_hz.size(); ++i)
        o << s.frequency_hz[i] << "," << s.psa_g[i] * factor << "\n";
    return out;
}

// The glove box at 0.2 g with the [site] target lines of site_extra (after target_h_file).
Case glovebox(const std::string& site_extra) {
    Case c = read_case(fs::path(freestand::test::source_dir()) / "cases" / "glovebox-single.toml");
    c.options.histories_per_level = 1;
    c.options.max_histories_per_level = c.options.histories_per_level;
    c = with_pga_levels(c, {0.2});
    const Case files = parse_case(component + site_extra, label);
    c.site.targets = files.site.targets;
    c.site.design = files.site.design;
    c.site.vertical_ratio = files.site.vertical_ratio;
    return c;
}

const LevelResult& level_of(const AssessmentResult& r, Direction d) {
    for (const LevelResult& l : r.levels)
        if (l.direction == d) return l;
    FAIL("no level in the direction");
    return r.levels.front();
}

void check_same(const LevelResult& a, const LevelResult& b) {
    CHECK(a.initiation.mode == b.initiation.mode);
    CHECK(a.initiation.a_ratio == b.initiation.a_ratio);
    CHECK(a.flexible.peak_psa_in_band_g == b.flexible.peak_psa_in_band_g);
    CHECK(a.sliding.f_es_hz == b.sliding.f_es_hz);
    CHECK(a.sliding.slide_asce_m == b.sliding.slide_asce_m);
    CHECK(a.sliding.slide_energy_m == b.sliding.slide_energy_m);
    CHECK(a.rocking.theta_rad == b.rocking.theta_rad);
    CHECK(a.verdict.kind == b.verdict.kind);
    CHECK(a.verdict.margin == b.verdict.margin);
    CHECK(a.verdict.decided_by == b.verdict.decided_by);
}

}  // namespace

TEST_CASE("target_y_file parses with its 10% file", "[assess][targets][targets_y]") {
    const Case c = parse_case(component + "target_h10_file = \"rg160-h-10pct-1g.csv\"\n"
                                          "target_y_file = \"rg160-h-5pct-1g.csv\"\n"
                                          "target_y10_file = \"rg160-h-10pct-1g.csv\"\n",
                              label);
    REQUIRE(c.site.targets->y5);
    REQUIRE(c.site.targets->y10);
    CHECK(c.site.targets->y5->given == "rg160-h-5pct-1g.csv");
    CHECK(c.site.targets->y10->spectrum.damping == 0.10);
    const Case x_only = parse_case(component, label);
    CHECK_FALSE(x_only.site.targets->y5);
}

TEST_CASE("target_y_file errors name file, line and key", "[assess][targets][targets_y]") {
    SECTION("y file without target_h_file") {
        const std::string no_h = R"([component]
name = "Box"
mass_kg = 100.0
cg_height_m = 1.0
cg_to_edge_x_m = [0.4, 0.5]
cg_to_edge_y_m = [0.3, 0.3]
mu_s = 0.3
allowable_slide_m = 0.05
[site]
pga_g = [0.2]
target_y_file = "rg160-h-5pct-1g.csv"
)";
        std::string e = "no error";
        try {
            parse_case(no_h, label);
        } catch (const InputError& err) {
            e = err.what();
        }
        CHECK(e == label + ":9: site.target_h_file: missing required key: target_h10_file / "
                           "target_y_file / target_y10_file / target_v_file need the 5% "
                           "horizontal target_h_file");
    }
    SECTION("wrong damping") {
        CHECK(error_of("target_y_file = \"rg160-h-10pct-1g.csv\"\n") ==
              label + ":12: site.target_y_file: target file \"rg160-h-10pct-1g.csv\" has damping "
                      "0.1; expected 0.05");
        CHECK(error_of("target_h10_file = \"rg160-h-10pct-1g.csv\"\n"
                       "target_y_file = \"rg160-h-5pct-1g.csv\"\n"
                       "target_y10_file = \"rg160-h-7pct-1g.csv\"\n") ==
              label + ":14: site.target_y10_file: target file \"rg160-h-7pct-1g.csv\" has "
                      "damping 0.07; expected 0.1");
    }
    SECTION("missing file") {
        const std::string e = error_of("target_y_file = \"nope.csv\"\n");
        CHECK(e.rfind(label + ":12: site.target_y_file: cannot use target file \"nope.csv\": ",
                      0) == 0);
    }
    SECTION("10% files come for both directions or neither") {
        CHECK(error_of("target_h10_file = \"rg160-h-10pct-1g.csv\"\n"
                       "target_y_file = \"rg160-h-5pct-1g.csv\"\n") ==
              label + ":13: site.target_y_file: target_h10_file is given, so direction y needs "
                      "its 10% file target_y10_file too");
        CHECK(error_of("target_y_file = \"rg160-h-5pct-1g.csv\"\n"
                       "target_y10_file = \"rg160-h-10pct-1g.csv\"\n") ==
              label + ":13: site.target_y10_file: needs target_h10_file (the 10% target of "
                      "direction x)");
        CHECK(error_of("target_h10_file = \"rg160-h-10pct-1g.csv\"\n"
                       "target_y10_file = \"rg160-h-10pct-1g.csv\"\n") ==
              label + ":13: site.target_y10_file: needs target_y_file (the 5% target of "
                      "direction y)");
    }
}

TEST_CASE("direction y's file sets y's demand, SA_VH combines x and y",
          "[assess][targets][targets_y]") {
    const std::string h10 = "target_h10_file = \"rg160-h-10pct-1g.csv\"\n";
    const Case single = glovebox(h10);
    const Case same = glovebox(h10 + "target_y_file = \"rg160-h-5pct-1g.csv\"\n"
                                     "target_y10_file = \"rg160-h-10pct-1g.csv\"\n");
    // y = 1.5 x the RG 1.60 file everywhere (ZPA too): at the same factor y's PGA is 1.5 x 0.2 g.
    const fs::path y5 = scaled_file("freestand-y15-5.csv", spectra_dir / "rg160-h-5pct-1g.csv", 1.5);
    const fs::path y10 =
        scaled_file("freestand-y15-10.csv", spectra_dir / "rg160-h-10pct-1g.csv", 1.5);
    const Case stronger = glovebox(h10 + "target_y_file = \"" + y5.string() +
                                   "\"\ntarget_y10_file = \"" + y10.string() + "\"\n");

    const LevelDemand d1 = level_demand(single.site, 0.2);
    const LevelDemand d3 = level_demand(stronger.site, 0.2);
    CHECK(d3.pga_of(Direction::x) == 0.2);
    CHECK(d3.pga_of(Direction::y) == Approx(0.3).epsilon(1e-12));
    for (std::size_t i = 0; i < d1.h5.psa_g.size(); ++i) {
        CHECK(d3.h5_of(Direction::x).psa_g[i] == d1.h5.psa_g[i]);
        CHECK(d3.h5_of(Direction::y).psa_g[i] == Approx(1.5 * d1.h5.psa_g[i]).epsilon(1e-12));
        // SA_VH = sqrt(SA_H1^2 + 0.16 SA_H2^2), H1 = y (docs/methods.md s.4), at 5%:
        // sqrt(1.5^2 + 0.16) SA_x, against sqrt(1.16) SA_x for one file.
        const double x5 = d1.h5.psa_g[i];
        CHECK(d3.sa_vh_damped.at(0.05).psa_g(d1.h5.frequency_hz[i]) ==
              Approx(std::sqrt(1.5 * 1.5 + 0.16) * x5).epsilon(1e-9));
    }

    const AssessmentResult r1 = assess::assess(single);
    const AssessmentResult r2 = assess::assess(same);
    const AssessmentResult r3 = assess::assess(stronger);
    // Identical x and y files reproduce the single-file result.
    for (Direction d : {Direction::x, Direction::y}) {
        INFO("direction " << (d == Direction::x ? "x" : "y"));
        check_same(level_of(r1, d), level_of(r2, d));
    }
    // Direction x keeps its own PGA-based initiation and flexible screen; y's follow its file.
    const LevelResult& x1 = level_of(r1, Direction::x);
    const LevelResult& x3 = level_of(r3, Direction::x);
    const LevelResult& y1 = level_of(r1, Direction::y);
    const LevelResult& y3 = level_of(r3, Direction::y);
    CHECK(x3.initiation.a_ratio == x1.initiation.a_ratio);
    CHECK(x3.flexible.peak_psa_in_band_g == x1.flexible.peak_psa_in_band_g);
    CHECK(y3.initiation.a_ratio == Approx(1.5 * y1.initiation.a_ratio).epsilon(1e-12));
    CHECK(y3.flexible.peak_psa_in_band_g ==
          Approx(1.5 * y1.flexible.peak_psa_in_band_g).epsilon(1e-9));
    // History h2 is matched to y's file (h1 to x's): the energy method's DeltaD follows it.
    REQUIRE(x1.sliding.delta_d_m > 0.0);
    REQUIRE(y1.sliding.delta_d_m > 0.0);
    REQUIRE(y3.sliding.delta_d_m > 0.0);
    CHECK(x3.sliding.delta_d_m == x1.sliding.delta_d_m);
    CHECK(y3.sliding.delta_d_m == Approx(1.5 * y1.sliding.delta_d_m).epsilon(0.05));
    CHECK(y3.pga_g == 0.2);  // levels stay keyed by the level's (direction x's) PGA
}

}  // namespace freestand_test_assess_test_targets_y
