// Three inputs of a component and a site: the body's height beside its CG height, p and the
// free-rocking band per direction, and RG 1.60's own vertical spectrum for the vertical histories.
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include "assess/case.hpp"
#include "assess/flexible_level.hpp"
#include "assess/histories.hpp"
#include "assess/level.hpp"
#include "core/errors.hpp"
#include "dynamics/flexible.hpp"
#include "spectra/design.hpp"
#include "spectra/response.hpp"
#include "support/case_text.hpp"
#include "support/paths.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_assess_test_case_inputs {

namespace fs = std::filesystem;
using namespace freestand;
using namespace freestand::assess;

namespace {

using test::box_component;
using test::box_site;

Case parse(const std::string& component_lines, const std::string& site_lines = "") {
    return parse_case(box_component + component_lines + box_site + site_lines, "case.toml");
}

std::string error_of(const std::string& component_lines, const std::string& site_lines = "") {
    return test::case_error(box_component + component_lines + box_site + site_lines);
}

bool has_assumption(const Case& c, const std::string& start) {
    return std::any_of(c.assumptions.begin(), c.assumptions.end(),
                       [&](const std::string& a) { return a.rfind(start, 0) == 0; });
}

const ContactBound contact{0.3, 0.3, 0.5, false, "test"};

}  // namespace

TEST_CASE("height_m: the top point, the default inertia and the modal height follow it",
          "[assess][case][height]") {
    // A body with a heavy top: CG 1.0 m up a 1.8 m body.
    const Case c = parse("height_m = 1.8\nfixed_base_frequency_hz = 8.0\n");
    REQUIRE(c.component.height_m == 1.8);
    CHECK(c.component.body_height_m() == 1.8);
    CHECK_FALSE(c.component.uniform_block);
    CHECK_FALSE(has_assumption(c, "height_m not given"));
    // Uniform block of the footprint and H = 1.8 m about its own centre (docs/methods.md s.1):
    // x, mean half-width 0.45 m: I_c = 100 (0.45^2 + 0.9^2) / 3 = 33.75 kg m^2; y: 30 kg m^2.
    CHECK(c.component.x.inertia_cg_kgm2 == Approx(33.75).epsilon(1e-14));
    CHECK(c.component.y.inertia_cg_kgm2 == Approx(30.0).epsilon(1e-14));
    CHECK(c.component.x.inertia_source ==
          "uniform block of the height given: I_c = M (b^2 + (H/2)^2) / 3");
    CHECK(has_assumption(c,
                         "No inertia or p given: I_c taken as that of a uniform block of the "
                         "same footprint and the body's height H = 1.800 m about its own "
                         "centre"));
    for (const Direction d : {Direction::x, Direction::y}) {
        CHECK(block_model(c.component, contact, d).top_height_m == 1.8);
        // The uniform cantilever's modal height, 0.726 of the body's height (flexible.hpp).
        const dynamics::FlexibleModel m = flexible_model(c.component, contact, d);
        CHECK(m.height_default);
        CHECK(m.height_m == Approx(0.726 * 1.8).epsilon(1e-15));
    }
    CHECK(has_assumption(c,
                         "Flexible-body model (run where a flexible-body flag is raised): "
                         "modal damping 0.02; modal mass 0.613 M (uniform cantilever, first "
                         "mode); modal height 0.726 x the body's height, 1.800 m = 1.307 m"));
    // A heavy base (CG 1.0 m up a 2.5 m body) cannot carry the uniform cantilever's mode,
    // 0.613 M at 1.815 m: refused, asking for the real mode.
    CHECK(error_of("height_m = 2.5\nfixed_base_frequency_hz = 8.0\n")
              .rfind("case.toml:1: component.modal_mass_fraction: in the x direction: a modal "
                     "mass of 0.613 M at 1.815 m carries more second moment than the body has",
                     0) == 0);
}

TEST_CASE("without height_m the body is twice its CG height, as before", "[assess][case][height]") {
    const Case c = parse("fixed_base_frequency_hz = 8.0\n");
    CHECK_FALSE(c.component.height_m.has_value());
    CHECK(c.component.body_height_m() == 2.0);
    CHECK(has_assumption(c,
                         "height_m not given: the body's top taken at twice the CG height, "
                         "2.000 m"));
    CHECK(c.component.x.inertia_cg_kgm2 == Approx(100.0 * (0.2025 + 1.0) / 3.0).epsilon(1e-14));
    CHECK(block_model(c.component, contact, Direction::x).top_height_m == 2.0);
    CHECK(flexible_model(c.component, contact, Direction::x).height_m ==
          Approx(0.726 * 2.0).epsilon(1e-15));
    // Given inertia is kept whatever the height.
    const Case given =
        parse("height_m = 3.0\ninertia_cg_x_kgm2 = 40.0\ninertia_cg_y_kgm2 = 30.0\n");
    CHECK(given.component.x.inertia_cg_kgm2 == 40.0);
    CHECK(block_model(given.component, contact, Direction::y).top_height_m == 3.0);
    // A uniform block's box keeps its meaning: height_m is the box's, the CG at half of it.
    const Case box = parse_case(
        "[component]\nname = \"B\"\nmass_kg = 10.0\nwidth_m = 0.3\n"
        "depth_m = 0.4\nheight_m = 1.2\nmu_s = 0.3\n"
        "allowable_slide_m = 0.05\n" +
            box_site,
        "case.toml");
    CHECK(box.component.uniform_block);
    CHECK(box.component.cg_height_m == 0.6);
    CHECK(box.component.body_height_m() == 1.2);
}

TEST_CASE("height_m errors name the key and the range", "[assess][case][height]") {
    CHECK(error_of("height_m = 0.8\n") ==
          "case.toml:9: component.height_m: value 0.8 is out of range; expected (1, 100]");
    CHECK(error_of("height_m = 101.0\n") ==
          "case.toml:9: component.height_m: value 101 is out of range; expected (1, 100]");
    CHECK(error_of("width_m = 1.0\nheight_m = 2.0\n") ==
          "case.toml:9: component.width_m: give either width_m/depth_m/height_m (uniform block) "
          "or cg_height_m with cg_to_edge_x_m/cg_to_edge_y_m (and optional height_m), not both");
}

TEST_CASE("p_radps per direction: [p_x, p_y], a single value meaning both", "[assess][case][p]") {
    // Saraswat 2017 Table 5-2's glove box: 1.97 and 1.85 rad/s (cases/glovebox-single.toml).
    const Case c =
        read_case(fs::path(freestand::test::source_dir()) / "cases" / "glovebox-single.toml");
    const block::Block bx = c.component.block(Direction::x);
    const block::Block by = c.component.block(Direction::y);
    CHECK(bx.p_radps(bx.critical_edge()) == Approx(1.97).epsilon(1e-12));
    CHECK(by.p_radps(by.critical_edge()) == Approx(1.85).epsilon(1e-12));
    // Hand calculation, y: I_O = 382 * 9.81 * 1.32856 / 1.85^2 = 1454.69 kg m^2, I_c = I_O - M R^2
    // = 780.43 kg m^2.
    CHECK(c.component.y.inertia_cg_kgm2 == Approx(780.43).epsilon(1e-5));
    CHECK(c.component.y.inertia_source == "from p = 1.85 rad/s: I_O = M g R / p^2");
    const Case one = parse("p_radps = 2.0\n");
    const Case two = parse("p_radps = [2.0, 2.0]\n");
    for (const Direction d : {Direction::x, Direction::y}) {
        const block::Block b = one.component.block(d);
        CHECK(b.p_radps(b.critical_edge()) == Approx(2.0).epsilon(1e-12));
        CHECK(two.component.plane(d).inertia_cg_kgm2 == one.component.plane(d).inertia_cg_kgm2);
    }
}

TEST_CASE("p_radps errors: each direction's p must leave I_c positive", "[assess][case][p]") {
    // x: R = sqrt(0.4^2 + 1) = 1.0770 m, p < sqrt(9.81 / R) = 3.0180 rad/s; y: R =
    // sqrt(0.3^2 + 1) = 1.0440 m, p < 3.0654 rad/s.
    CHECK(error_of("p_radps = [3.04, 3.0]\n") ==
          "case.toml:9: component.p_radps: p_x = 3.04 rad/s is out of range; expected (0, "
          "3.0180) (p < sqrt(g / R) of direction x's critical edge)");
    const Case ok = parse("p_radps = [3.0, 3.04]\n");  // y's limit is the larger
    const block::Block by = ok.component.block(Direction::y);
    CHECK(by.p_radps(by.critical_edge()) == Approx(3.04).epsilon(1e-12));
    CHECK(error_of("p_radps = [1.0, 3.07]\n")
              .rfind("case.toml:9: component.p_radps: value 3.07 is out of range; expected (0, "
                     "3.065",
                     0) == 0);
    CHECK(error_of("p_radps = [1.0, 2.0, 3.0]\n")
              .rfind("case.toml:9: component.p_radps: expected an array of 2 numbers in (0, "
                     "3.065",
                     0) == 0);
    CHECK(error_of("p_radps = \"fast\"\n")
              .rfind("case.toml:9: component.p_radps: expected a number in (0, 3.018", 0) == 0);
}

TEST_CASE("free-rocking bands: one for both directions or one per direction",
          "[assess][case][band]") {
    const Case both = parse("free_rocking_band_hz = [1.7, 4.9]\n");
    CHECK(both.component.x.free_rocking_band_hz == std::array<double, 2>{1.7, 4.9});
    CHECK(both.component.y.free_rocking_band_hz == std::array<double, 2>{1.7, 4.9});
    const Case each =
        parse("free_rocking_band_x_hz = [1.7, 4.9]\nfree_rocking_band_y_hz = [2.0, 4.7]\n");
    CHECK(each.component.x.free_rocking_band_hz == std::array<double, 2>{1.7, 4.9});
    CHECK(each.component.y.free_rocking_band_hz == std::array<double, 2>{2.0, 4.7});
    const Case only_y = parse("free_rocking_band_y_hz = [2.0, 4.7]\n");
    CHECK_FALSE(only_y.component.x.free_rocking_band_hz.has_value());
    CHECK(only_y.component.y.free_rocking_band_hz.has_value());
    CHECK(error_of("free_rocking_band_hz = [1.7, 4.9]\nfree_rocking_band_y_hz = [2.0, 4.7]\n") ==
          "case.toml:10: component.free_rocking_band_y_hz: give free_rocking_band_hz (both "
          "directions) or free_rocking_band_x_hz / free_rocking_band_y_hz (one per direction), "
          "not both");
    CHECK(error_of("free_rocking_band_y_hz = [4.7, 2.0]\n") ==
          "case.toml:9: component.free_rocking_band_y_hz: expected [lo, hi] with lo < hi, got "
          "[4.7, 2]");
}

TEST_CASE("the flexible-body screen reads the band of its own direction", "[assess][level][band]") {
    // At 0.2 g (vertical ratio 1: 0.2 g): uplift thresholds 0.4 x 0.8 = 0.32 g (x) and
    // 0.3 x 0.8 = 0.24 g (y). x's band 1.7-4.9 Hz holds RG 1.60's amplified PSA (about
    // 3.1 x 0.2 g): flag raised; y's band 40-50 Hz holds only the PGA, 0.2 g < 0.24 g: no strong
    // content.
    Case c = parse("free_rocking_band_x_hz = [1.7, 4.9]\nfree_rocking_band_y_hz = [40.0, 50.0]\n",
                   "vertical_ratio = 1.0\n[options]\nsimulate = \"never\"\n");
    const LevelDemand demand = level_demand(c.site, 0.2);
    HistoryBank bank(c);
    const LevelResult x = evaluate_level(c, Direction::x, demand, bank);
    const LevelResult y = evaluate_level(c, Direction::y, demand, bank);
    CHECK(x.flexible.raised);
    CHECK(x.flexible.basis == "free-rocking band 1.70-4.90 Hz");
    CHECK_FALSE(y.flexible.raised);
    CHECK(y.flexible.basis == "free-rocking band 40.00-50.00 Hz");
    CHECK(y.flexible.reason.find("no strong content") != std::string::npos);
    CHECK_FALSE(bank.generated());
    // Without a band in y, y is rigid for the screen.
    c.component.y.free_rocking_band_hz.reset();
    CHECK(evaluate_level(c, Direction::y, demand, bank).flexible.reason ==
          "no fixed-base frequency or free-rocking band given: treated as rigid");
}

TEST_CASE("RG 1.60's vertical: its ZPA is the horizontal PGA unless vertical_ratio scales it",
          "[assess][case][vertical]") {
    const Case d = parse("");
    CHECK(d.site.vertical_ratio == spectra::rg160_vertical_zpa_ratio);
    CHECK(has_assumption(d,
                         "vertical_ratio not given: vertical histories matched to RG 1.60's "
                         "vertical design spectrum"));
    const Case r = parse("", "vertical_ratio = 0.5\n");
    CHECK(r.site.vertical_ratio == 0.5);
    CHECK(has_assumption(r,
                         "Vertical histories matched to RG 1.60's vertical design spectrum "
                         "(2/3 of the horizontal below 0.25 Hz, equal to it above 3.5 Hz; RG "
                         "1.60 Rev. 2, docs/methods.md s.8) scaled to a zero-period "
                         "acceleration of vertical_ratio = 0.5000 x the horizontal PGA."));
    // A level of 1 g is weightless with RG 1.60's vertical, and the message says why.
    std::string text = box_component + "[site]\npga_g = [0.5, 1.0]\n";
    try {
        parse_case(text, "case.toml");
        FAIL("a level of 1 g was accepted with RG 1.60's vertical");
    } catch (const InputError& e) {
        CHECK(std::string(e.what()) ==
              "case.toml:10: site.pga_g: PGA 1 g with a vertical/horizontal ratio of 1 gives a "
              "vertical PGA of 1 g; at 1 g or more, taken downward as the static checks take it, "
              "the block is weightless: each level needs pga_g x ratio < 1 (RG 1.60's vertical "
              "ZPA equals the horizontal PGA; vertical_ratio scales its vertical spectrum)");
    }
    CHECK(parse_case(text + "vertical_ratio = 0.6\n", "case.toml").site.pga_g.size() == 2);
}

TEST_CASE("RG 1.60 histories: the vertical matches RG 1.60's vertical spectrum at the ratio",
          "[assess][histories][vertical]") {
    // One set at 1 g with vertical_ratio 0.5. At 0.3 Hz RG 1.60's vertical is 0.67 of its
    // horizontal (2/3 below 0.25 Hz, 1 above 3.5 Hz): the vertical record meets 0.5 x the
    // vertical spectrum there (SRP 3.7.1: 0.9 to 1.3 of the target), which is below 0.9 x 0.5 x
    // the horizontal spectrum, the target of a ratio times the horizontal.
    Case c = parse("", "vertical_ratio = 0.5\n[options]\nhistories_per_level = 1\n");
    HistoryBank bank(c);
    REQUIRE(bank.sets().size() == 1);
    const HistorySet& set = bank.sets().front();
    const std::vector<double> f{0.3, 1.0, 20.0};
    const std::vector<double> v = spectra::psa_g(set.v, 0.05, f);
    const spectra::Spectrum target_v = spectra::rg160(0.5, 0.05, true, f);
    const spectra::Spectrum target_h = spectra::rg160(1.0, 0.05, false, f);
    CHECK(target_v.psa_g[0] / target_h.psa_g[0] == Approx(0.5 * 0.672).epsilon(0.002));
    for (std::size_t i = 0; i < f.size(); ++i) {
        INFO(f[i] << " Hz");
        CHECK(v[i] / target_v.psa_g[i] >= 0.9);
        CHECK(v[i] / target_v.psa_g[i] <= 1.3);
    }
    CHECK(v[0] < 0.9 * 0.5 * target_h.psa_g[0]);
    CHECK(set.acceptance.at(2).zpa_g == Approx(0.5).epsilon(1e-12));
}

TEST_CASE("RG 1.60 levels: the equivalent-linear estimate reads RG 1.60's vertical spectrum",
          "[assess][level][vertical]") {
    // vertical_ratio 0.5: the vertical spectrum has RG 1.60's shape and a ZPA of 0.5 x PGA: 2/3
    // of the horizontal (factor D, 1.37 / 2.05) at low frequency, equal to it (A, B) above 9 Hz.
    // A large block (h 3 m, tan alpha 0.25) rocks at 0.3 g (A = 0.3 / 0.925 > 0.25 < mu_s 0.8).
    std::string component = box_component;
    component.replace(component.find("mu_s = 0.3"), 10, "mu_s = 0.8");
    component.replace(component.find("cg_height_m = 1.0"), 17, "cg_height_m = 3.0");
    component.replace(component.find("cg_to_edge_x_m = [0.4, 0.5]"), 27,
                      "cg_to_edge_x_m = [0.75, 0.9]");
    const Case c =
        parse_case(component + box_site + "vertical_ratio = 0.5\n[options]\nsimulate = \"never\"\n",
                   "case.toml");
    LevelDemand demand = level_demand(c.site, 0.3);
    REQUIRE(demand.sa_v_damped.has_value());
    CHECK(demand.sa_v_damped->zpa_g() == Approx(0.15).epsilon(1e-9));
    const spectra::Spectrum h = spectra::rg160(0.3, 0.05, false, {0.2, 20.0});
    const rocking::DampedDemand v = demand.sa_v_damped->at(0.05);
    CHECK(v.psa_g(0.2) / h.psa_g[0] == Approx(0.5 * 1.37 / 2.05).epsilon(1e-2));
    CHECK(v.psa_g(20.0) / h.psa_g[1] == Approx(0.5).epsilon(1e-2));
    // The level's estimate is the one with that vertical spectrum. Its effective frequency
    // shows it (gravity reduced by 0.4 SA_V(f_e)); theta itself does not move here, where the
    // demand is a constant displacement (below RG 1.60's 0.25 Hz).
    HistoryBank bank(c);
    const LevelResult level = evaluate_level(c, Direction::x, demand, bank);
    REQUIRE(level.rocking.theta_rad.has_value());
    REQUIRE(demand.el_cache.size() == 1);
    const rocking::ElResult& used = demand.el_cache.begin()->second.governing();
    const block::Block blk = c.component.block(Direction::x);
    rocking::ElOptions opt;
    opt.pga_h_g = 0.3;
    opt.pga_v_g = 0.15;
    rocking::VerticalDemand with_spectrum;
    with_spectrum.ratio = 0.5;
    with_spectrum.spectra = demand.sa_v_damped;
    rocking::VerticalDemand with_ratio;
    with_ratio.ratio = 0.5;
    const auto spectrum_f =
        rocking::equivalent_linear_rocking(blk, demand.sa_vh_damped, with_spectrum, opt)
            .governing()
            .f_e_hz;
    const auto ratio_f =
        rocking::equivalent_linear_rocking(blk, demand.sa_vh_damped, with_ratio, opt)
            .governing()
            .f_e_hz;
    REQUIRE(used.f_e_hz.has_value());
    REQUIRE(spectrum_f.has_value());
    REQUIRE(ratio_f.has_value());
    CHECK(*used.f_e_hz == *spectrum_f);
    // Less vertical demand at f_e, less gravity lost: a higher effective frequency.
    CHECK(*spectrum_f > *ratio_f);
    CHECK_FALSE(bank.generated());
}

}  // namespace freestand_test_assess_test_case_inputs
