// A component's name and an output path reach the terminal and the reports' titles on one line:
// CR, LF and the bidirectional overrides are shown as \r, \n and \uXXXX, never obeyed (a CR in
// the headline let the name overwrite the verdict; a U+202E showed it backwards).
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/paths.hpp"
#include "support/run_cli.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_report_test_printable_names {

namespace fs = std::filesystem;
using Catch::Contains;

namespace {

fs::path scratch(const std::string& name) {
    const fs::path d = fs::temp_directory_path() /
                       ("freestand_names_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

// A small case (one level, one history) named name, a TOML basic string's text.
fs::path named_case(const fs::path& dir, const std::string& toml_name) {
    const fs::path p = dir / "named.toml";
    std::ofstream(p) << "[component]\nname = \"" << toml_name << "\"\n" << R"(mass_kg = 382.0
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

// The raw characters that must not appear: CR, LF inside a line, U+202E.
bool has_raw_line_control(const std::string& line) {
    return line.find('\r') != std::string::npos || line.find("\xE2\x80\xAE") != std::string::npos;
}

}  // namespace

TEST_CASE("a name's CR, LF and bidirectional override are shown in the headline, the HTML title "
          "and heading and the Markdown title",
          "[report][cli][escape]") {
    const fs::path dir = scratch("headline");
    // "Box", CR, "anchor: FAIL", LF, U+202E and "SSAP".
    const fs::path c = named_case(dir, "Box\\ranchor: FAIL\\n\\u202ESSAP");
    const fs::path out = dir / "out\rput";
    const auto r = freestand::test::run_cli("assess '" + c.string() + "' --out '" + out.string() + "'");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const std::string shown = "Box\\ranchor: FAIL\\n\\u202ESSAP";
    const std::string headline = r.out.substr(0, r.out.find('\n'));
    CHECK(headline.rfind(shown + ": ", 0) == 0);
    CHECK_FALSE(has_raw_line_control(r.out));
    CHECK_THAT(r.out, Contains("wrote " + dir.string() + "/out\\rput ("));
    const std::string html = freestand::test::slurp(out / "report.html");
    CHECK_THAT(html, Contains("<title>Anchoring assessment: " + shown + "</title>"));
    CHECK_THAT(html, Contains("<h1>Anchoring assessment: " + shown + "</h1>"));
    CHECK(html.find("\xE2\x80\xAE") == std::string::npos);
    const std::string md = freestand::test::slurp(out / "report.md");
    // Markdown shows a backslash escaped.
    CHECK(md.rfind("# Anchoring assessment: Box\\\\ranchor: FAIL\\\\n\\\\u202ESSAP\n", 0) == 0);
    CHECK(md.find("\xE2\x80\xAE") == std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("an output folder's CR is shown in the line naming it", "[report][cli][escape]") {
    const fs::path dir = scratch("generate");
    const fs::path out = dir / "sets\rDONE";
    const auto r = freestand::test::run_cli("generate --target rg1.60 --pga 0.2 --out '" +
                                            out.string() + "'");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Contains("written to " + dir.string() + "/sets\\rDONE: "));
    CHECK_FALSE(has_raw_line_control(r.out));
    fs::remove_all(dir);
}

TEST_CASE("assess --out . publishes into the working folder, --out DIR/ into DIR",
          "[report][cli][publish]") {
    const fs::path dir = scratch("dot");
    const fs::path c = named_case(dir, "Small box");
    fs::create_directories(dir / "here");
    const std::string exe = freestand::test::exe();
    const std::string in_here = "cd '" + (dir / "here").string() + "' && '" + exe + "' assess '" +
                                c.string() + "' --out ";
    REQUIRE(std::system((in_here + ". >/dev/null").c_str()) == 0);
    CHECK(fs::exists(dir / "here" / "report.md"));
    CHECK(fs::exists(dir / "here" / ".freestand-run"));
    REQUIRE(std::system((in_here + "./ >/dev/null").c_str()) == 0);  // again: replaced
    REQUIRE(std::system((in_here + "new/ >/dev/null").c_str()) == 0);
    CHECK(fs::exists(dir / "here" / "new" / "report.md"));
    // Nothing beside the folders: no staging or renamed-aside folder left.
    std::size_t entries = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
        INFO(e.path().filename());
        CHECK(e.path().filename().string().find(".freestand-") == std::string::npos);
        ++entries;
    }
    CHECK(entries == 2);  // named.toml and here/
    fs::remove_all(dir);
}

}  // namespace freestand_test_report_test_printable_names
