#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <regex>

#include "assess/verdict.hpp"
#include "core/errors.hpp"
#include "report/json.hpp"
#include "report/regress.hpp"
#include "report/render.hpp"
#include "report/sha256.hpp"
#include "report/svg.hpp"
#include "support/run_cli.hpp"

namespace fs = std::filesystem;
using namespace freestand;
using namespace freestand::report;

namespace {

const std::string hostile = "<script>alert('x')</script> & [link](javascript:alert(1)) | *b*";

// A hand-built result: the report must render it without running any physics.
assess::AssessmentResult hand_result() {
    assess::AssessmentResult r;
    r.input.component.name = hostile;
    r.input.component.description = hostile + "\nsecond line";
    r.input.component.footprint = hostile;
    r.input.component.mass_kg = 100.0;
    r.input.component.cg_height_m = 1.0;
    r.input.component.base.mu_s = 0.3;
    r.input.component.base.mu_k = 0.3;
    r.input.component.allowable_slide_m = 0.05;
    r.input.site.pga_g = {0.2};
    assess::LevelResult l;
    l.pga_g = 0.2;
    l.initiation.mode = assess::Mode::slide;
    l.sliding.slide_asce_m = 0.0123456;
    l.simulation_reason = hostile;
    l.verdict.kind = assess::VerdictKind::acceptable_with_clearance;
    l.verdict.clearance_m = 0.0123456;
    l.verdict.margin = 4.05;
    l.verdict.decided_by = assess::Model::asce4_sliding;
    r.levels.push_back(l);
    r.overall = l.verdict;
    r.assumptions = {hostile};
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
    CHECK(sha256_hex("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    CHECK(sha256_hex("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    // Two-block message (56 bytes forces a second padding block).
    CHECK(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
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

TEST_CASE("numbers are formatted with fixed precision and the stamp is present", "[report][json]") {
    const Rendered out = render(hand_result(), stamp());
    CHECK(out.markdown.find("| 12.3 |") != std::string::npos);  // ASCE 4 slide in mm, 1 decimal
    const auto j = nlohmann::ordered_json::parse(out.json);
    CHECK(j.at("verdict") == "acceptable with clearance >= 13 mm");
    CHECK(j.at("levels").at(0).at("slide_asce_m") == 0.0123456);
    CHECK(j.at("levels").at(0).at("slide_energy_m").is_null());
    CHECK(j.at("stamp").at("input_sha256") == sha256_hex("case bytes"));
    CHECK(j.at("stamp").at("commit") == "abc123");
    CHECK(j.at("stamp").at("seed") == 7);
    for (const char* key :
         {"pga_g", "direction", "mode", "slide_asce_m", "slide_energy_m", "slide_sim_max_m",
          "rock_max_over_alpha", "overturned_fraction", "verdict", "decided_by"}) {
        CHECK(j.at("levels").at(0).contains(key));
    }
    CHECK(j.contains("upgrade"));
}

TEST_CASE("rendering twice gives identical bytes", "[report][determinism]") {
    const Rendered a = render(hand_result(), stamp());
    const Rendered b = render(hand_result(), stamp());
    CHECK(a.markdown == b.markdown);
    CHECK(a.html == b.html);
    CHECK(a.json == b.json);
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

TEST_CASE("regress comparison: tolerance, verdict change, stamp ignored", "[report][regress]") {
    auto golden = nlohmann::ordered_json::parse(
        R"({"verdict": "anchor", "levels": [{"x": 1.0}], "stamp": {"commit": "a"}})");
    auto fresh = golden;
    fresh["stamp"]["commit"] = "b";
    fresh["levels"][0]["x"] = 1.0 + 5e-7;
    CHECK(compare_results(golden, fresh, 1e-6).empty());
    fresh["levels"][0]["x"] = 1.0 + 2e-6;
    auto d = compare_results(golden, fresh, 1e-6);
    REQUIRE(d.size() == 1);
    CHECK(d[0].path == "/levels/0/x");
    fresh = golden;
    fresh["verdict"] = "free-standing acceptable";
    d = compare_results(golden, fresh, 1e-6);
    REQUIRE(d.size() == 1);
    CHECK(d[0].path == "/verdict");
    fresh = golden;
    fresh["levels"].push_back(nlohmann::ordered_json::object());
    CHECK(compare_results(golden, fresh, 1e-6).at(0).path == "/levels/length");
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
