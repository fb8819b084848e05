#include <algorithm>
#include <atomic>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <thread>

#include "support/paths.hpp"
#include "assess/verdict.hpp"
#include "core/errors.hpp"
#include "report/json.hpp"
#include "report/plots.hpp"
#include "report/references.hpp"
#include "report/render.hpp"
#include "report/verdict_line.hpp"
#include "core/sha256.hpp"
#include "report/svg.hpp"
#include "support/run_cli.hpp"
#include "support/special_files.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_report_test_report {

namespace fs = std::filesystem;
using namespace freestand;
using namespace freestand::report;

namespace {

const std::string hostile = "<script>alert('x')</script> & [link](javascript:alert(1)) | *b*";

// A hand-built result: the report must render it without running any physics.
// Level 0 (x) rests (no motion); level 1 (y) slides, was simulated and governs.
assess::AssessmentResult hand_result() {
    assess::AssessmentResult r;
    r.input.component.name = hostile;
    r.input.component.description = hostile + "\nsecond line";
    r.input.component.footprint = hostile;
    r.input.component.mass_kg = 100.0;
    r.input.component.cg_height_m = 1.0;
    r.input.component.base.mu_s = 0.3;
    r.input.component.base.mu_k = 0.3;
    r.input.component.base.mu_s_range = {0.24, 0.36};
    r.input.component.allowable_slide_m = 0.05;
    r.input.site.pga_g = {0.2};
    assess::LevelResult rest;
    rest.pga_g = 0.2;
    rest.direction = assess::Direction::x;
    rest.verdict.no_motion = true;
    rest.verdict.margin_basis = "no horizontal acceleration";
    rest.trail = {"screen passed: at rest", "not simulated: the screen passed"};
    r.levels.push_back(rest);
    assess::LevelResult l;
    l.pga_g = 0.2;
    l.direction = assess::Direction::y;
    l.initiation.mode = assess::Mode::slide;
    l.sliding.slide_asce_m = 0.0123456;
    l.sliding.slide_energy_m = 0.02;
    l.simulation_reason = hostile;
    l.screen.passed = false;
    assess::Simulation sim;
    sim.histories = 7;
    sim.slide_m = {0.010, 0.011, 0.012};
    sim.rock_over_alpha = {0.1, 0.2, 0.3};
    sim.overturn_ci = {0.0, 0.41};
    l.simulation = sim;
    l.verdict.kind = assess::VerdictKind::acceptable_with_clearance;
    l.verdict.clearance_m = 0.0123456;
    l.verdict.margin = 4.05;
    l.verdict.margin_basis = "allowable / simulated peak slip";
    l.verdict.decided_by = assess::Model::simulation_slide;
    l.trail = {"screen failed: ASCE 4 12.3 mm", "simulated: the screen failed",
               "governed by the simulation"};
    r.levels.push_back(l);
    r.own = assess::Governing{1, l.pga_g, l.direction, l.verdict};
    r.overall = r.own;
    r.assumptions = {hostile};
    return r;
}

// A case whose own base fails, with the headline from the recommended material's trial.
assess::AssessmentResult changed_material_result() {
    assess::AssessmentResult r = hand_result();
    r.input.component.name = "Box";
    r.input.component.base.material = "steel";
    assess::Verdict own = r.levels[1].verdict;
    own.kind = assess::VerdictKind::change_material;
    own.failure = assess::Failure::overturns;
    own.material = "aluminium";
    own.margin = 0.0;
    own.decided_by = assess::Model::simulation_rocking;
    r.levels[1].verdict = own;
    r.own = assess::Governing{1, 0.2, assess::Direction::y, own};
    assess::Verdict trial;
    trial.kind = assess::VerdictKind::acceptable_with_clearance;
    trial.clearance_m = 0.02;
    trial.margin = 2.46;
    trial.decided_by = assess::Model::simulation_slide;
    r.overall = assess::Governing{3, 0.4, assess::Direction::x, trial};
    r.overall.verdict.kind = assess::VerdictKind::change_material;
    r.overall.verdict.material = "aluminium";
    r.overall.verdict.mechanism = "lower friction: it slides instead of rocking over";
    r.overall_from_trial = true;
    r.upgrade.needed = true;
    r.upgrade.recommended = "aluminium";
    assess::MaterialTrial plywood;
    plywood.material = "plywood";
    plywood.mu_s_range = {0.12, 0.18};
    plywood.restitution = 0.94;
    plywood.governing = assess::Governing{1, 0.2, assess::Direction::y, own};
    plywood.governing.verdict.kind = assess::VerdictKind::anchor;
    plywood.governing.verdict.failure = assess::Failure::slides_beyond_allowable;
    assess::MaterialTrial alu;
    alu.material = "aluminium";
    alu.mu_s_range = {0.384, 0.576};
    alu.passes = true;
    alu.governing = assess::Governing{3, 0.4, assess::Direction::x, trial};
    r.upgrade.trials = {plywood, alu};
    return r;
}

// A result whose headline is "no motion": no ratio may be printed for it.
assess::AssessmentResult no_motion_result() {
    assess::AssessmentResult r = hand_result();
    r.overall = assess::Governing{0, 0.2, assess::Direction::x, r.levels[0].verdict};
    r.own = r.overall;
    return r;
}

Stamp stamp() { return make_stamp("case bytes", "case.toml", 7, "abc123"); }

fs::path temp_dir(const std::string& name) {
    const fs::path d =
        fs::temp_directory_path() / ("freestand_report_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

// A small case for end-to-end runs: one level, one history, so the test stays fast.
fs::path small_case(const fs::path& dir, const std::string& name) {
    fs::create_directories(dir);
    const fs::path p = dir / (name + ".toml");
    std::ofstream(p) << R"([component]
name = "Small box"
mass_kg = 382.0
cg_height_m = 1.22
cg_to_edge_x_m = [0.526, 0.526]
cg_to_edge_y_m = [0.526, 0.526]
p_radps = 1.97
base_material = "PVC sheet on concrete"
allowable_slide_m = 0.050

[site]
pga_g = [0.2]

[options]
histories_per_level = 1
seed = 3
)";
    return p;
}

}  // namespace

TEST_CASE("SHA-256 matches the FIPS 180-4 test vectors", "[report][sha256]") {
    CHECK(core::sha256_hex("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    CHECK(core::sha256_hex("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    // Two-block message (56 bytes forces a second padding block).
    CHECK(core::sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
          "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

TEST_CASE("a hostile component name is escaped in HTML and Markdown", "[report][escape]") {
    const Rendered out = render(hand_result(), stamp());
    CHECK(out.html.find("<script>") == std::string::npos);
    CHECK(out.html.find("&lt;script&gt;") != std::string::npos);
    CHECK(out.markdown.find("<script>") == std::string::npos);
    CHECK(out.markdown.find("&lt;script>") != std::string::npos);
    // No live Markdown link or table-breaking pipe from case text.
    CHECK(out.markdown.find("[link](javascript") == std::string::npos);
    CHECK(out.markdown.find("\\[link\\](javascript:alert(1)) \\| \\*b\\*") != std::string::npos);
    // The description's newline is folded so it cannot start a Markdown block.
    CHECK(out.markdown.find(
              "&lt;/script> &amp; \\[link\\](javascript:alert(1)) \\| \\*b\\* second line") !=
          std::string::npos);
    // The JSON keeps the text verbatim (JSON escaping is the consumer's business).
    CHECK(out.json.find("\"name\": \"<script>alert('x')</script>") != std::string::npos);
}

TEST_CASE("the HTML report is self-contained", "[report][html]") {
    const Rendered out = render(hand_result(), stamp());
    CHECK(out.html.find("http://") == out.html.find("http://www.w3.org/2000/svg"));
    CHECK(out.html.find("https://") == std::string::npos);
    CHECK(out.html.find("<link") == std::string::npos);
    CHECK(out.html.find("<script") == std::string::npos);
    CHECK(out.html.find("<style>") != std::string::npos);
    // Verdict first: the verdict block precedes the inputs.
    CHECK(out.html.find("acceptable with clearance &gt;= 13 mm") <
          out.html.find("<h2>Inputs</h2>"));
}

TEST_CASE("both reports end with the references, methods document and thesis included",
          "[report][references]") {
    const Rendered out = render(hand_result(), stamp());
    for (const std::string* text : {&out.markdown, &out.html}) {
        const auto refs = text->find("References");
        REQUIRE(refs != std::string::npos);
        CHECK(refs < text->find("Reproducibility"));
        for (const char* key : {"docs/methods.md", "ASCE 4-16", "SRP 3.7.1", "RG 1.60",
                                "Housner 1963", "Shenton 1996", "Ishiyama 1982",
                                "Saraswat 2017"}) {
            INFO(key);
            CHECK(text->find(key, refs) != std::string::npos);
        }
    }
    // result.json carries the same list.
    const auto j = nlohmann::ordered_json::parse(out.json);
    REQUIRE(j.at("references").size() == references().size());
    CHECK(j["references"][0]["key"] == "docs/methods.md");
}

TEST_CASE("no report cites the methods note outside the repository, and the model names cite "
          "docs/methods.md and their standard",
          "[report][references]") {
    const std::string old_name = std::string("METHODS") + ".md";
    for (const auto& r : {hand_result(), changed_material_result(), no_motion_result()}) {
        const Rendered out = render(r, stamp());
        for (const std::string* text : {&out.markdown, &out.html, &out.json})
            CHECK(text->find(old_name) == std::string::npos);
    }
    using assess::Model;
    const std::vector<std::pair<Model, std::string>> cited{
        {Model::static_initiation, "(docs/methods.md s.2; Shenton 1996)"},
        {Model::asce4_sliding, "(docs/methods.md s.4; ASCE 4-16)"},
        {Model::equivalent_linear_rocking, "(docs/methods.md s.5a; ASCE 43-05 App. A approach)"},
        {Model::simulation_slide, "(docs/methods.md s.3)"},
        {Model::simulation_rocking, "(docs/methods.md s.3)"},
        {Model::simulation_biaxial_slide, "(docs/methods.md s.10)"}};
    for (const auto& [model, citation] : cited) {
        const std::string name = assess::to_string(model);
        INFO(name);
        CHECK(name.size() > citation.size());
        CHECK(name.substr(name.size() - citation.size()) == citation);
    }
}

TEST_CASE("numbers are formatted with fixed precision and the stamp is present", "[report][json]") {
    const Rendered out = render(hand_result(), stamp());
    CHECK(out.markdown.find("| 12.3 |") != std::string::npos);  // ASCE 4 slide in mm, 1 decimal
    CHECK(out.markdown.find("| 10.0 / 11.0 / 12.0 |") != std::string::npos);  // simulated, mm
    CHECK(out.markdown.find("| 0/7 \\[0%, 41%\\] |") != std::string::npos);
    const auto j = nlohmann::ordered_json::parse(out.json);
    CHECK(j.at("verdict") == "acceptable with clearance >= 13 mm");
    const auto& level = j.at("levels").at(1);
    CHECK(level.at("slide_asce_m") == 0.0123456);
    CHECK(level.at("slide_energy_m") == 0.02);
    CHECK(j.at("levels").at(0).at("slide_energy_m").is_null());
    CHECK(j.at("stamp").at("input_sha256") == core::sha256_hex("case bytes"));
    CHECK(j.at("stamp").at("commit") == "abc123");
    CHECK(j.at("stamp").at("seed") == 7);
    for (const char* key :
         {"pga_g", "direction", "bounds", "mode", "mode_lower_friction", "slide_asce_m",
          "slide_energy_m", "screen", "simulation", "verdict", "trail"}) {
        CHECK(level.contains(key));
    }
    const auto& sim = level.at("simulation");
    CHECK(sim.at("histories") == 7);
    CHECK(sim.at("governing_statistic") == "p84");
    CHECK(sim.at("slide_m").at("p84") == 0.011);
    CHECK(sim.at("rock_over_alpha").at("max") == 0.3);
    CHECK(sim.at("overturn_ci") == nlohmann::ordered_json::array({0.0, 0.41}));
    CHECK(j.at("levels").at(0).at("simulation").is_null());
    CHECK(level.at("verdict").at("decided_by") ==
          assess::to_string(assess::Model::simulation_slide));
    CHECK(level.at("trail").size() == 3);
    CHECK(j.at("upgrade").at("trials").empty());
    CHECK(j.at("case").at("component").at("mu_s_range") ==
          nlohmann::ordered_json::array({0.24, 0.36}));
    CHECK(j.at("case").at("component").at("restitution_range").is_null());
    CHECK(j.at("case").at("component").at("allowable_relative_m").is_null());
}

TEST_CASE("JSON: overall and own name their one governing level", "[report][json]") {
    const auto j = nlohmann::ordered_json::parse(render(changed_material_result(), stamp()).json);
    const auto& overall = j.at("overall");
    CHECK(overall.at("kind") == "change_material");
    CHECK(overall.at("material") == "aluminium");
    CHECK(overall.at("mechanism") == "lower friction: it slides instead of rocking over");
    CHECK(overall.at("margin") == 2.46);
    CHECK(overall.at("no_motion") == false);
    CHECK(overall.at("failure") == "none");
    CHECK(overall.at("conditions").empty());
    CHECK(overall.at("governing").at("pga_g") == 0.4);
    CHECK(overall.at("governing").at("direction") == "x");
    CHECK(overall.at("governing").at("level_index") == 3);
    CHECK(overall.at("governing").at("from_material_trial") == "aluminium");
    const auto& own = j.at("own");
    CHECK(own.at("failure") == assess::to_string(assess::Failure::overturns));
    CHECK(own.at("margin") == 0.0);
    CHECK(own.at("governing").at("pga_g") == 0.2);
    CHECK(own.at("governing").at("direction") == "y");
    CHECK(own.at("governing").at("level_index") == 1);
    CHECK(own.at("governing").at("from_material_trial").is_null());
    const auto& up = j.at("upgrade");
    CHECK(up.at("recommended") == "aluminium");
    REQUIRE(up.at("trials").size() == 2);
    const auto& ply = up.at("trials").at(0);
    CHECK(ply.at("material") == "plywood");
    CHECK(ply.at("mu_s_range") == nlohmann::ordered_json::array({0.12, 0.18}));
    CHECK(ply.at("restitution") == 0.94);
    CHECK(ply.at("passes") == false);
    CHECK(ply.at("governing").at("level_index") == 1);
    CHECK(ply.at("verdict").at("kind") == "anchor");
    CHECK(up.at("trials").at(1).at("restitution").is_null());  // Housner's
}

TEST_CASE("the headline comes from one level, with the own base beside a material change",
          "[report][headline]") {
    const auto r = changed_material_result();
    const Rendered out = render(r, stamp());
    CHECK(out.markdown.find("- Governing level: PGA 0.400 g, direction x with aluminium\n") !=
          std::string::npos);
    CHECK(out.markdown.find("- Margin: 2.46\n") != std::string::npos);
    CHECK(out.markdown.find("- Case's own base (steel): fails at PGA 0.200 g, direction y: "
                            "overturns, decided by time-history simulation, rocking") !=
          std::string::npos);
    CHECK(out.markdown.find("margin 0.00\n") != std::string::npos);
    // The search table and its conclusion.
    CHECK(out.markdown.find("| plywood | \\[0.120, 0.180\\] | 0.940 | no | 0.200 g, y | anchor | "
                            "slides beyond the allowable |") != std::string::npos);
    CHECK(out.markdown.find("| aluminium | \\[0.384, 0.576\\] | Housner | yes | 0.400 g, x |") !=
          std::string::npos);
    CHECK(out.markdown.find("aluminium is recommended") != std::string::npos);
    CHECK(out.html.find("Case&#39;s own base (steel)") != std::string::npos);
    CHECK(verdict_line(r) ==
          "Box: change base material to aluminium (lower friction: it slides instead of rocking "
          "over) (governing PGA 0.400 g, direction x with aluminium, margin 2.46, decided by " +
              std::string(assess::to_string(assess::Model::simulation_slide)) + ")");
    // A passing own base has no "own base" line.
    CHECK(render(hand_result(), stamp()).markdown.find("Case's own base") == std::string::npos);
}

TEST_CASE("a negligible demand reads \"no motion\", never a ratio", "[report][headline]") {
    auto r = no_motion_result();
    r.overall.verdict.conditions = {"flexible-body flag " + hostile};
    const Rendered out = render(r, stamp());
    CHECK(out.markdown.find("- Margin: no motion (no horizontal acceleration)\n") !=
          std::string::npos);
    CHECK(out.markdown.find("| free-standing acceptable | no motion |") != std::string::npos);
    CHECK(out.markdown.find("- Open condition: flexible-body flag &lt;script>") !=
          std::string::npos);
    CHECK(out.html.find("<li>Open condition: flexible-body flag &lt;script&gt;") !=
          std::string::npos);
    const auto j = nlohmann::ordered_json::parse(out.json);
    CHECK(j.at("overall").at("no_motion") == true);
    CHECK(j.at("overall").at("margin").is_null());
    CHECK(j.at("overall").at("conditions").size() == 1);
    CHECK(j.at("levels").at(0).at("verdict").at("no_motion") == true);
    CHECK(j.at("levels").at(0).at("verdict").at("margin").is_null());
    const std::string line = verdict_line(r);
    CHECK(line.find("margin no motion,") != std::string::npos);
    CHECK(line.find("; open condition: flexible-body flag") != std::string::npos);
}

TEST_CASE("the decision trail lists each level's lines", "[report][trail]") {
    const Rendered out = render(hand_result(), stamp());
    const auto section = out.markdown.find("## Decision trail");
    REQUIRE(section != std::string::npos);
    CHECK(out.markdown.find("- PGA 0.200 g, y:\n"
                            "  - screen failed: ASCE 4 12.3 mm\n"
                            "  - simulated: the screen failed\n"
                            "  - governed by the simulation\n",
                            section) != std::string::npos);
    CHECK(out.markdown.find("- PGA 0.200 g, x:\n  - screen passed: at rest\n", section) !=
          std::string::npos);
    CHECK(out.html.find("<li>governed by the simulation</li>") != std::string::npos);
}

TEST_CASE("demand figures are drawn from the levels", "[report][figures]") {
    const auto find = [](const std::vector<Figure>& figs, const std::string& file) {
        return std::find_if(figs.begin(), figs.end(),
                            [&](const Figure& f) { return f.file == file; });
    };
    auto r = hand_result();
    r.levels[1].simulation->overturned = 2;
    const std::vector<Figure> figs = figures(r);
    const auto slide = find(figs, "demand-slide-y.svg");
    REQUIRE(slide != figs.end());
    CHECK(slide->svg.find("allowable slide 50.0 mm (clearance)") != std::string::npos);
    CHECK(slide->svg.find("planar rigid block, 84th percentile") != std::string::npos);
    // The hand result's level 1 fails its screen: its simulation decides, drawn in black.
    CHECK(slide->svg.find("decides: 84th percentile of the deciding model") !=
          std::string::npos);
    CHECK(slide->svg.find("energy conservation (informational)") != std::string::npos);
    const auto rock = find(figs, "demand-rock-y.svg");
    REQUIRE(rock != figs.end());
    CHECK(rock->svg.find("1 / FS required = 1 / 1.50 = 0.667") != std::string::npos);
    CHECK(rock->svg.find("2/7 overturned") != std::string::npos);
    // Direction x has no slide, rotation or simulation data: no figure for it.
    CHECK(find(figs, "demand-slide-x.svg") == figs.end());
    CHECK(find(figs, "demand-rock-x.svg") == figs.end());
    // The Markdown report links the figure written next to it.
    CHECK(render(r, stamp()).markdown.find("(demand-slide-y.svg)") != std::string::npos);
}

TEST_CASE("How sure: N, the settled share and the sets beyond each limit by the deciding model",
          "[report][settle]") {
    auto r = hand_result();
    CHECK(render(r, stamp()).markdown.find("No level was decided by simulation") !=
          std::string::npos);
    assess::LevelResult& l = r.levels[1];
    l.settling = assess::Settling{3, 2000, 0.973, true, 2, std::nullopt};
    l.simulation->histories = 3;
    l.simulation->slide_m = assess::stats_of({0.010, 0.011, 0.012});
    l.simulation->rock_over_alpha = assess::stats_of({0.1, 0.2, 0.3});
    l.simulation->slide_exceed = assess::exceedance(l.simulation->slide_m.values, 0.05);
    l.simulation->rock_exceed = assess::exceedance(l.simulation->rock_over_alpha.values, 1.0 / 1.5);
    l.simulation->overturn_ci = {0.0, 0.71};
    // The biaxial |u| decides the slide: two of its three sets pass 50 mm, none of the planar.
    assess::BiaxialSlide b;
    b.ran = true;
    b.slide_m = assess::stats_of({0.01, 0.06, 0.07});
    l.biaxial = b;
    const std::string md = render(r, stamp()).markdown;
    const auto section = md.find("## How sure is this verdict");
    REQUIRE(section != std::string::npos);
    INFO(md.substr(section, 1500));
    const auto row = md.find("| 0.200 | y | 3 | 97.3% | 2/3 (95% 9-99%) | 0/3 (95% 0-71%) | "
                             "0/3 (95% 0-71%) | passes |",
                             section);
    CHECK(row != std::string::npos);
    CHECK(row < md.find("## Results per PGA level"));
    // Unsettled at the cap, the row says so.
    l.settling->settled = false;
    l.settling->settled_fraction = 0.71;
    CHECK(render(r, stamp()).markdown.find("| 71.0% (not settled) |") != std::string::npos);
}

TEST_CASE("rendering twice gives identical bytes", "[report][determinism]") {
    const Rendered a = render(hand_result(), stamp());
    const Rendered b = render(hand_result(), stamp());
    CHECK(a.markdown == b.markdown);
    CHECK(a.html == b.html);
    CHECK(a.json == b.json);
}

TEST_CASE("renders on several threads at once give the bytes of a render alone",
          "[report][determinism][threads]") {
    // mstch's escape function is process-wide: without EscapeGuard's lock one thread's HTML
    // escaping leaks into another's Markdown.
    const Rendered alone = render(hand_result(), stamp());
    std::atomic<int> mismatches{0};
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t) {
        threads.emplace_back([&] {
            for (int i = 0; i < 10; ++i) {
                const Rendered r = render(hand_result(), stamp());
                if (r.markdown != alone.markdown || r.html != alone.html) ++mismatches;
            }
        });
    }
    for (auto& t : threads) t.join();
    CHECK(mismatches == 0);
}

TEST_CASE("an SVG plot escapes its text and skips non-positive values on log axes",
          "[report][svg]") {
    Plot p;
    p.title = "a < b & c";
    p.x = Axis{"f (Hz)", true, {}, {}};
    p.y = Axis{"psa", true, {}, {}};
    p.lines.push_back(Line{"l", {0.0, 1.0, 10.0}, {1.0, 2.0, 3.0}});
    const std::string svg = render_svg(p);
    CHECK(svg.find("a &lt; b &amp; c") != std::string::npos);
    CHECK(svg.find("nan") == std::string::npos);
    CHECK(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0) == 0);
    // Two finite positive points survive on the line.
    const std::regex polyline("<polyline points=\"([0-9.]+,[0-9.]+) ([0-9.]+,[0-9.]+)\"");
    CHECK(std::regex_search(svg, polyline));
}

TEST_CASE("a failed write leaves no half file behind", "[report][atomic]") {
    const fs::path dir = temp_dir("atomic");
    fs::create_directories(dir / "report.html");  // a folder where the file should go
    const Rendered out = render(hand_result(), stamp());
    CHECK_THROWS_AS(write_report(dir, out), IoError);
    for (const auto& e : fs::directory_iterator(dir)) {
        CHECK(e.path().extension() != ".tmp");
    }
    CHECK_FALSE(fs::exists(dir / "result.json"));
    fs::remove_all(dir);
}

TEST_CASE("assess CLI: two runs give byte-identical files", "[report][cli][determinism]") {
    const fs::path dir = temp_dir("determinism");
    const fs::path c = small_case(dir, "small");
    const auto a =
        test::run_cli("assess '" + c.string() + "' --out '" + (dir / "a").string() + "'");
    REQUIRE(a.exit_code == 0);
    CHECK(a.out.rfind("Small box: ", 0) == 0);
    const auto b =
        test::run_cli("assess '" + c.string() + "' --out '" + (dir / "b").string() + "'");
    REQUIRE(b.exit_code == 0);
    std::size_t files = 0;
    for (const auto& e : fs::directory_iterator(dir / "a")) {
        ++files;
        INFO(e.path().filename());
        CHECK(test::slurp(e.path()) == test::slurp(dir / "b" / e.path().filename()));
    }
    CHECK(files >= 6);  // report.md, report.html, result.json and the figures
    fs::remove_all(dir);
}

TEST_CASE("assess CLI: the default output folder is out/<case stem>/ of the working directory",
          "[report][cli]") {
    const fs::path dir = temp_dir("default_out");
    small_case(dir, "small");
    // run_cli works in the source tree; this run must work in its own folder.
    const std::string cmd = "cd '" + dir.string() + "' && '" + freestand::test::exe() +
                            "' assess small.toml >'" + (dir / "stdout.txt").string() + "' 2>&1";
    REQUIRE(std::system(cmd.c_str()) == 0);
    CHECK(fs::exists(dir / "out" / "small" / "report.md"));
    CHECK(fs::exists(dir / "out" / "small" / "result.json"));
    CHECK_FALSE(fs::exists(dir / "reports"));
    CHECK(test::slurp(dir / "stdout.txt").find("wrote out/small") != std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("assess CLI errors", "[report][cli]") {
    const auto missing = test::run_cli("assess /nonexistent/case.toml");
    CHECK(missing.exit_code == 5);
    CHECK(missing.err.find("/nonexistent/case.toml: cannot open file for reading") !=
          std::string::npos);
    const fs::path dir = temp_dir("errors");
    const fs::path c = small_case(dir, "small");
    const auto bad =
        test::run_cli("assess '" + c.string() + "' --pga 0.3,0.2 --out '" + dir.string() + "/o'");
    CHECK(bad.exit_code == 3);
    CHECK(bad.err.find("--pga: levels must be strictly increasing; 0.2 follows 0.3") !=
          std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("regress passes on unchanged goldens and detects a drift", "[report][cli][regress]") {
    const fs::path dir = temp_dir("regress");
    small_case(dir / "cases", "small");
    const std::string args =
        "'" + (dir / "reports").string() + "' --cases '" + (dir / "cases").string() + "'";
    const auto missing = test::run_cli("regress " + args);
    CHECK(missing.exit_code == 1);
    CHECK(missing.out.find("MISSING small") != std::string::npos);
    REQUIRE(test::run_cli("regress " + args + " --update").exit_code == 0);
    const auto same = test::run_cli("regress " + args);
    CHECK(same.exit_code == 0);
    CHECK(same.out.rfind("ok      small: ", 0) == 0);
    // Drift one number in a copy of the golden by 1%.
    const fs::path golden = dir / "reports" / "small" / "result.json";
    auto j = nlohmann::ordered_json::parse(test::slurp(golden));
    j["levels"][0]["a_ratio"] = j["levels"][0]["a_ratio"].get<double>() * 1.01;
    std::ofstream(golden) << j.dump(2);
    const auto drift = test::run_cli("regress " + args);
    CHECK(drift.exit_code == 1);
    CHECK(drift.out.find("CHANGED small: 1 difference(s)") != std::string::npos);
    CHECK(drift.out.find("/levels/0/a_ratio") != std::string::npos);
    // A looser tolerance accepts it.
    CHECK(test::run_cli("regress " + args + " --rtol 0.02").exit_code == 0);
    fs::remove_all(dir);
}

TEST_CASE("regress CLI errors", "[report][cli][regress]") {
    const fs::path dir = temp_dir("regress_errors");
    const auto no_cases =
        test::run_cli("regress '" + dir.string() + "' --cases '" + (dir / "none").string() + "'");
    CHECK(no_cases.exit_code == 5);
    CHECK(no_cases.err.find((dir / "none").string() + ": not a folder of case files") !=
          std::string::npos);
    const auto bad_rtol = test::run_cli("regress --rtol -1");
    CHECK(bad_rtol.exit_code == 2);
    CHECK(bad_rtol.err.find("--rtol: expected a number >= 0; got -1") != std::string::npos);
    small_case(dir / "cases", "small");
    fs::create_directories(dir / "reports" / "small");
    std::ofstream(dir / "reports" / "small" / "result.json") << "{not json";
    const auto bad_golden = test::run_cli("regress '" + (dir / "reports").string() + "' --cases '" +
                                          (dir / "cases").string() + "'");
    CHECK(bad_golden.exit_code == 3);
    CHECK(bad_golden.err.find("result.json: not valid JSON") != std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("assess refuses outputs that would replace an input or a special file, before "
          "writing anything",
          "[report][cli][hardening]") {
    const fs::path dir = temp_dir("refuse_outputs");
    const fs::path c = small_case(dir, "small");
    // The case file is named like an output of the run, in the output folder: it is an input,
    // so the run must refuse to replace it.
    REQUIRE(test::run_cli("assess '" + c.string() + "' --out '" + (dir / "out").string() + "'")
                .exit_code == 0);
    fs::copy_file(c, dir / "out" / "report.md", fs::copy_options::overwrite_existing);
    fs::remove(dir / "out" / "result.json");
    std::map<std::string, std::string> before;
    for (const auto& e : fs::directory_iterator(dir / "out"))
        before[e.path().filename().string()] = test::slurp(e.path());
    REQUIRE(before.count("spectra.svg") == 1);
    // At another PGA every figure would differ: one written before the refusal shows. The
    // figures, written file by file, would go first and report.md be refused after them (9 SVGs
    // replaced, exit 5).
    const auto self = test::run_cli("assess '" + (dir / "out" / "report.md").string() +
                                    "' --pga 0.3 --out '" + (dir / "out").string() + "'");
    CHECK(self.exit_code == 5);
    CHECK(self.err.find("refusing to overwrite an input file of this run") != std::string::npos);
    std::map<std::string, std::string> after;
    for (const auto& e : fs::directory_iterator(dir / "out"))
        after[e.path().filename().string()] = test::slurp(e.path());
    CHECK(after.size() == before.size());
    for (const auto& [name, text] : before) {
        INFO(name);
        CHECK(after[name] == text);  // nothing was written
    }
    // A device, a symlink are never replaced.
    if (const auto dev = test::make_null_device(dir)) {
        const auto device = test::run_cli("assess '" + c.string() + "' --out '" + dev->string() + "'");
        CHECK(device.exit_code == 5);
        CHECK(device.err.find("exists and is not a folder") != std::string::npos);
        CHECK(fs::is_character_file(*dev));
    } else {
        WARN("not root: mknod refused, the device case is not run");
    }
    fs::create_directory_symlink(dir / "out", dir / "link");
    const auto link =
        test::run_cli("assess '" + c.string() + "' --out '" + (dir / "link").string() + "'");
    CHECK(link.exit_code == 5);
    CHECK(link.err.find("is a symbolic link") != std::string::npos);
    CHECK(fs::is_symlink(dir / "link"));
    fs::remove_all(dir);
}

TEST_CASE("control characters show as hexadecimal escapes in Markdown and HTML", "[report][escape][hardening]") {
    CHECK(markdown_escape("a\x1b[31mb\x07") == "a\\x1B\\[31mb\\x07");
    CHECK(html_escape(std::string("a\x1b<b>\0c", 7)) == "a\\x1B&lt;b&gt;\\x00c");
    CHECK(html_escape("line\nbreak") == "line\nbreak");
}

TEST_CASE("the stamp hashes every input file, not only the case", "[report][cli][stamp]") {
    // Target spectra and seed records change a result as much as the case does.
    const fs::path dir = temp_dir("stamp_inputs");
    const auto r =
        test::run_cli("assess cases/cabinet-user-target.toml --pga 0.1 --out '" + dir.string() + "'");
    REQUIRE(r.exit_code == 0);
    const auto j = nlohmann::json::parse(test::slurp(dir / "result.json"));
    const auto& inputs = j.at("stamp").at("inputs");
    REQUIRE(inputs.size() >= 1);
    for (const auto& i : inputs) {
        const fs::path file = fs::path(freestand::test::source_dir()) / "cases" / i.at("file").get<std::string>();
        INFO(file);
        CHECK(i.at("sha256") == core::sha256_hex(test::slurp(file)));
    }
    fs::remove_all(dir);
}

namespace {

// A fragility result from made-up samples: 2 levels x 4 samples, overturning at the second.
fragility::Result hand_fragility() {
    fragility::Meta meta;
    meta.case_name = hostile;
    meta.config.pga_g = {0.2, 0.4};
    meta.config.samples = 4;
    meta.allowable_slide_m = 0.05;
    meta.mu_s_law = "uniform [0.2, 0.3]";
    meta.restitution_law = "uniform [0.7, 0.9]";
    meta.motion_source = "made up";
    std::vector<fragility::SampleResult> samples;
    for (int level = 0; level < 2; ++level)
        for (int i = 0; i < 4; ++i)
            samples.push_back({level, i, "set 1", 0.25, 0.8, 0.8, 0.01 * (1 + level),
                               level == 1 && i < 3 ? 2.0 : 0.1, level == 1 && i < 3});
    return fragility::aggregate(meta, samples);
}

}  // namespace

TEST_CASE("an assessment with a fragility result carries its section, figure and JSON",
          "[report][fragility]") {
    const fragility::Result f = hand_fragility();
    const Rendered with = render(hand_result(), stamp(), &f);
    const Rendered without = render(hand_result(), stamp());
    CHECK(without.markdown.find("## Fragility") == std::string::npos);
    CHECK(without.html.find(">Fragility</h2>") == std::string::npos);
    CHECK(without.extra_files.empty());
    CHECK_FALSE(nlohmann::json::parse(without.json).contains("fragility"));
    // The section comes before the assumptions, in both reports.
    const auto md_at = with.markdown.find("## Fragility");
    REQUIRE(md_at != std::string::npos);
    CHECK(md_at < with.markdown.find("## Assumptions"));
    CHECK(with.markdown.find("| 0.400 | 4 | 3 / 4 \\[") != std::string::npos);
    CHECK(with.markdown.find("](fragility.svg)") != std::string::npos);
    const auto html_at = with.html.find(">Fragility</h2>");
    REQUIRE(html_at != std::string::npos);
    CHECK(html_at < with.html.find(">Assumptions</h2>"));
    CHECK(with.html.find("<svg", html_at) < with.html.find(">Assumptions</h2>"));
    REQUIRE(with.extra_files.size() == 1);
    CHECK(with.extra_files[0].name == "fragility.svg");
    const auto j = nlohmann::json::parse(with.json);
    REQUIRE(j.contains("fragility"));
    CHECK(j["fragility"]["levels"][1]["events"]["overturn"]["k"] == 3);
    CHECK_FALSE(j["fragility"].contains("stamp"));
    // The rest of the report is untouched.
    CHECK(with.markdown.substr(0, md_at) == without.markdown.substr(0, md_at));
}

TEST_CASE("the HTML report carries the print CSS, and every table's header row is a <thead>",
          "[report][html][pdf]") {
    const fragility::Result f = hand_fragility();
    const Rendered out = render(hand_result(), stamp(), &f);
    // templates/print_style.html.mustache, inside the report's one <style>.
    const auto style_end = out.html.find("</style>");
    CHECK(out.html.find("@page") < style_end);
    CHECK(out.html.find("content: \"page \" counter(page) \" of \" counter(pages)") < style_end);
    CHECK(out.html.find("thead { display: table-header-group; }") < style_end);
    CHECK(out.html.find("{{") == std::string::npos);
    // A table opens with its header row in a <thead>, or is the stamp (one header per row).
    std::size_t tables = 0;
    for (auto at = out.html.find("<table"); at != std::string::npos;
         at = out.html.find("<table", at + 1)) {
        ++tables;
        const std::string head = out.html.substr(at, 40);
        INFO(head);
        CHECK((head.rfind("<table>\n<thead><tr><th>", 0) == 0 ||
               head.rfind("<table class=\"stamp\">", 0) == 0));
    }
    CHECK(tables >= 7);
    CHECK(out.html.find("<h2 class=\"new-page\">Figures</h2>") != std::string::npos);
}

TEST_CASE("report_files lists every file of the folder, the fragility figure included",
          "[report][fragility][batch]") {
    // A batch writes a component's folder from report_files: a file missing here would be
    // missing there and the folder would differ from `assess --out`'s.
    const fragility::Result f = hand_fragility();
    const Rendered with = render(hand_result(), stamp(), &f);
    std::vector<std::string> names;
    for (const core::OutputFile& file : report_files(with)) names.push_back(file.name);
    std::vector<std::string> expected;
    for (const Figure& fig : with.figures) expected.push_back(fig.file);
    for (const char* n : {"fragility.svg", "report.md", "report.html", "result.json"})
        expected.push_back(n);
    CHECK(names == expected);
}

TEST_CASE("a flexible-body simulation appears in result.json and beside the rigid one in the "
          "reports", "[report][flexible]") {
    assess::AssessmentResult r = hand_result();
    const auto plain = nlohmann::ordered_json::parse(render(r, stamp()).json);
    CHECK(plain.at("levels").at(1).at("flexible_simulation").is_null());
    assess::LevelResult& l = r.levels.at(1);
    l.flexible.raised = true;
    assess::FlexibleSimulation f;
    f.sim = *l.simulation;
    f.sim.rock_over_alpha = {0.01, 0.02, 0.03};
    f.uplifted = 5;
    f.frequency_hz = 7.5;
    f.damping = 0.02;
    f.mass_fraction = 0.613;
    f.height_m = 1.77;
    f.modal_m = {0.002, 0.003, 0.004};
    l.flexible_simulation = f;
    l.verdict.decided_by = assess::Model::simulation_flexible;
    r.own.verdict = l.verdict;
    r.overall = r.own;
    const Rendered out = render(r, stamp());
    const auto j = nlohmann::ordered_json::parse(out.json);
    const auto& fj = j.at("levels").at(1).at("flexible_simulation");
    CHECK(fj.at("frequency_hz") == 7.5);
    CHECK(fj.at("uplifted") == 5);
    CHECK(fj.at("modal_m").at("max") == 0.004);
    CHECK(fj.at("rock_over_alpha").at("max") == 0.03);
    CHECK_FALSE(fj.contains("amplification"));
    CHECK(out.markdown.find("Rigid and flexible side by side") != std::string::npos);
    CHECK(out.markdown.find("| 0.200 | y | rigid planar block (beside) |") != std::string::npos);
    CHECK(out.markdown.find("| 0.200 | y | flexible body, 7.5 Hz (decides) |") != std::string::npos);
    CHECK(out.html.find("flexible body, 7.5 Hz (decides)") != std::string::npos);
}

}  // namespace freestand_test_report_test_report
