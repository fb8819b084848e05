// The thesis values validate uses: each quote stands on its line (docs/methods.md s.13).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/paths.hpp"
#include "validate/thesis.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_validate_test_thesis {

namespace fs = std::filesystem;
using namespace freestand::validate;

namespace {

const fs::path data_dir = fs::path(freestand::test::data_dir()) / "thesis";

std::vector<std::string> split_tabs(const std::string& line) {
    std::vector<std::string> out;
    std::stringstream in(line);
    std::string cell;
    while (std::getline(in, cell, '\t')) out.push_back(cell);
    if (!line.empty() && line.back() == '\t') out.emplace_back();
    return out;
}

// excerpt.txt: "<line number>\t<the thesis's line>" for every cited line.
std::map<int, std::string> excerpt() {
    std::ifstream in(data_dir / "excerpt.txt");
    REQUIRE(in);
    std::map<int, std::string> out;
    std::string line;
    while (std::getline(in, line)) {
        const auto tab = line.find('\t');
        REQUIRE(tab != std::string::npos);
        out[std::stoi(line.substr(0, tab))] = line.substr(tab + 1);
    }
    return out;
}

std::vector<std::string> thesis_lines(const fs::path& file) {
    std::ifstream in(file);
    REQUIRE(in);
    std::vector<std::string> out;
    std::string line;
    while (std::getline(in, line)) out.push_back(line);
    return out;
}

}  // namespace

TEST_CASE("every thesis fact's quote stands on its line of the excerpt", "[validate][thesis]") {
    const auto lines = excerpt();
    std::set<std::string> keys;
    for (const Fact& f : facts()) {
        INFO(f.key);
        CHECK(keys.insert(f.key).second);
        CHECK(!f.cite.quote.empty());
        CHECK(f.cite.quote.find('\t') == std::string::npos);
        REQUIRE(lines.count(f.cite.line) == 1);
        CHECK(lines.at(f.cite.line).find(f.cite.quote) != std::string::npos);
    }
}

TEST_CASE("tests/data/thesis/values.tsv is the table of thesis.cpp", "[validate][thesis]") {
    std::ifstream in(data_dir / "values.tsv");
    REQUIRE(in);
    std::string line;
    std::vector<std::vector<std::string>> rows;
    bool header = false;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        if (!header) {
            CHECK(line == "key\tvalue\tunit\twhere\tline\tquote");
            header = true;
            continue;
        }
        rows.push_back(split_tabs(line));
    }
    REQUIRE(rows.size() == facts().size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const Fact& f = facts()[i];
        const auto& r = rows[i];
        INFO(f.key);
        REQUIRE(r.size() == 6);
        CHECK(r[0] == f.key);
        if (f.value) {
            CHECK(std::stod(r[1]) == Approx(*f.value).epsilon(1e-12));
        } else {
            CHECK(r[1].empty());
        }
        CHECK(r[2] == f.unit);
        CHECK(r[3] == f.cite.where);
        CHECK(std::stoi(r[4]) == f.cite.line);
        CHECK(r[5] == f.cite.quote);
    }
}

TEST_CASE("fact lookups: value, missing key, observation without value", "[validate][thesis]") {
    CHECK(value("ts1.alpha_rad") == 0.245);
    CHECK(value("gb.asce_0.2g_mm") == 47.0);
    CHECK_THROWS_WITH(fact("no.such"), "validate: no thesis fact 'no.such'");
    CHECK_THROWS_WITH(value("ts.overturn_2hz"),
                      "validate: thesis fact 'ts.overturn_2hz' has no value");
    CHECK(cite_text(fact("ts3.vpeak_mps").cite) == "thesis s.3.3.4.1, Table 3-6, line 999");
}

// Hidden: registered by tests/CMakeLists.txt only where the shared thesis folder is present.
TEST_CASE("the excerpt is the shared thesis's own text", "[.shared]") {
    const fs::path file = fs::path(freestand::test::shared_dir()) / "thesis" / thesis_text_file;
    REQUIRE(fs::exists(file));
    const auto thesis = thesis_lines(file);
    for (const auto& [number, text] : excerpt()) {
        INFO("line " << number);
        REQUIRE(number >= 1);
        REQUIRE(static_cast<std::size_t>(number) <= thesis.size());
        CHECK(thesis[static_cast<std::size_t>(number) - 1] == text);
    }
}

}  // namespace freestand_test_validate_test_thesis
