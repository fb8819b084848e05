// The methods document ships with the project: every "docs/methods.md s.N"
// citation in the sources names a section (and a step of s.6) that exists, nothing cites the
// former methods note outside the repository, and the committed reports cite docs/methods.md
// and the standards and end with the references list.
#include <catch2/catch.hpp>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/paths.hpp"
#include "report/references.hpp"
#include "report/render.hpp"
#include "support/run_cli.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_report_test_citations {

namespace fs = std::filesystem;
using namespace freestand;

namespace {

const fs::path source_dir{freestand::test::source_dir()};

// Section ids of docs/methods.md ("1", "5a", ...) from its "## N. Title" headings, and the
// numbered steps of each section (top-level "K. " list items).
struct MethodsOutline {
    std::set<std::string> sections;
    std::map<std::string, std::set<int>> steps;
    bool has_conventions = false;
    bool has_sources = false;
};

MethodsOutline outline(const std::string& text) {
    MethodsOutline out;
    const std::regex heading(R"(^## (\d+[a-z]?)\. \S)");
    const std::regex step(R"(^(\d+)\. \S)");
    std::istringstream in(text);
    std::string line;
    std::string current;
    while (std::getline(in, line)) {
        std::smatch m;
        if (std::regex_search(line, m, heading)) {
            current = m[1];
            INFO(line);
            CHECK(out.sections.insert(current).second);  // no section id twice
        } else if (line.rfind("## ", 0) == 0) {
            current.clear();
            if (line == "## Conventions and units") out.has_conventions = true;
            if (line == "## Sources") out.has_sources = true;
        } else if (!current.empty() && std::regex_search(line, m, step)) {
            out.steps[current].insert(std::stoi(m[1]));
        }
    }
    return out;
}

struct Citation {
    std::string file;
    std::string text;     // the citation as written, for messages
    std::string section;  // "" for "docs/methods.md, Conventions"
    std::vector<int> steps;
};

// Joins wrapped comments and split string literals, so a citation broken over two lines reads
// as one.
std::string unwrap(const std::string& text) {
    static const std::regex literal_break(R"(\"\s*\n\s*\")");
    static const std::regex comment_break(R"(\n\s*//[/!]?\s*)");
    return std::regex_replace(std::regex_replace(text, literal_break, ""), comment_break, " ");
}

// Every "docs/methods.md s.N[ step K | steps K-L | steps K and L][, s.M ...]" in text.
std::vector<Citation> citations(const std::string& file, const std::string& raw) {
    static const std::regex cite(
        R"(docs/methods\.md((?:(?:,|;| and)? ?s\.\d+[a-z]?(?: steps? \d+(?:(?:-| and )\d+)?)?)*))");
    static const std::regex one(R"(s\.(\d+[a-z]?)(?: steps? (\d+)(?:(?:-| and )(\d+))?)?)");
    std::vector<Citation> out;
    const std::string text = unwrap(raw);
    for (auto it = std::sregex_iterator(text.begin(), text.end(), cite);
         it != std::sregex_iterator(); ++it) {
        const std::string list = (*it)[1];
        for (auto jt = std::sregex_iterator(list.begin(), list.end(), one);
             jt != std::sregex_iterator(); ++jt) {
            Citation c{file, (*it)[0], (*jt)[1], {}};
            if ((*jt)[2].matched) c.steps.push_back(std::stoi((*jt)[2]));
            if ((*jt)[3].matched) c.steps.push_back(std::stoi((*jt)[3]));
            out.push_back(c);
        }
    }
    return out;
}

bool cited_file(const fs::path& p) {
    static const std::set<std::string> ext{".cpp", ".hpp", ".h",    ".mustache", ".md",
                                           ".toml", ".txt", ".cmake", ".sh",      ".csv"};
    return ext.count(p.extension().string()) > 0;
}

// The project's own text: sources, templates, tests, benchmarks, fuzz targets and their
// corpora, shipped cases and spectra, scripts and the README.
std::vector<fs::path> project_text_files() {
    std::vector<fs::path> out{source_dir / "README.md"};
    for (const char* dir : {"src", "templates", "tests", "bench", "fuzz", "cases", "spectra",
                            "scripts"}) {
        for (const auto& e : fs::recursive_directory_iterator(source_dir / dir)) {
            if (e.is_regular_file() && cited_file(e.path())) out.push_back(e.path());
        }
    }
    return out;
}

// "METHODS" "." "md", written so that this file does not contain the name it looks for.
const std::string old_name = std::string("METHODS") + ".md";

}  // namespace

TEST_CASE("docs/methods.md keeps the section numbering the code cites", "[report][methods]") {
    const MethodsOutline o = outline(test::slurp(source_dir / "docs" / "methods.md"));
    CHECK(o.has_conventions);
    CHECK(o.has_sources);
    const std::set<std::string> expected{"1", "2", "3", "4",  "5",  "5a", "6",
                                         "7", "8", "9", "10", "11", "12", "13"};
    CHECK(o.sections == expected);
    // The decision policy's steps, cited as "s.6 step K".
    CHECK(o.steps.at("6") == std::set<int>{1, 2, 3, 4, 5, 6, 7, 8});
}

TEST_CASE("the outline and citation parsers read what they are given", "[report][methods]") {
    const MethodsOutline o = outline(
        "# t\n## Conventions and units\n## 1. One\n1. a\n## 5a. Five a\n2. b\n"
        "## Sources\n3. not a step\n");
    CHECK(o.sections == std::set<std::string>{"1", "5a"});
    CHECK(o.steps.at("1") == std::set<int>{1});
    CHECK(o.steps.at("5a") == std::set<int>{2});
    CHECK(o.steps.count("Sources") == 0);
    const auto c = citations("f", "x (docs/methods.md s.3, s.6 step 5; y) \"docs/methods.md \"\n"
                                  "    \"s.6 steps 4 and 7\" // docs/methods.md s.2,\n"
                                  "// s.5a docs/methods.md s.N docs/methods.md, Conventions");
    REQUIRE(c.size() == 5);
    CHECK(c[0].section == "3");
    CHECK(c[1].section == "6");
    CHECK(c[1].steps == std::vector<int>{5});
    CHECK(c[2].section == "6");
    CHECK(c[2].steps == std::vector<int>{4, 7});
    CHECK(c[3].section == "2");
    CHECK(c[4].section == "5a");
}

TEST_CASE("every docs/methods.md citation names a section and step that exist",
          "[report][methods]") {
    const MethodsOutline o = outline(test::slurp(source_dir / "docs" / "methods.md"));
    // Only the canonical form is checked, so the other forms are refused.
    const std::regex loose(R"(docs/methods\.md,? (?:section|sec\.))");
    std::size_t checked = 0;
    for (const fs::path& p : project_text_files()) {
        const std::string text = test::slurp(p);
        const std::string file = fs::relative(p, source_dir).string();
        INFO(file);
        CHECK_FALSE(std::regex_search(text, loose));
        for (const Citation& c : citations(file, text)) {
            INFO(c.text);
            CHECK(o.sections.count(c.section) == 1);
            for (int step : c.steps) {
                INFO("step " << step);
                const auto steps = o.steps.find(c.section);
                CHECK((steps != o.steps.end() && steps->second.count(step) == 1));
            }
            ++checked;
        }
    }
    CHECK(checked > 100);
}

TEST_CASE("nothing in the project cites the out-of-tree methods note", "[report][methods]") {
    for (const fs::path& p : project_text_files()) {
        INFO(fs::relative(p, source_dir).string());
        CHECK(test::slurp(p).find(old_name) == std::string::npos);
    }
}

TEST_CASE("the committed reports cite docs/methods.md and the standards and list the references",
          "[report][methods][references]") {
    std::size_t cases = 0;
    for (const auto& e : fs::directory_iterator(source_dir / "reports")) {
        // reports/validation is the thesis comparison, with its own list (test below).
        if (!e.is_directory() || e.path().filename() == "validation") continue;
        ++cases;
        for (const char* name : {"report.md", "report.html", "result.json"}) {
            const fs::path p = e.path() / name;
            INFO(fs::relative(p, source_dir).string());
            const std::string text = test::slurp(p);
            REQUIRE_FALSE(text.empty());
            CHECK(text.find(old_name) == std::string::npos);
            const bool html = std::string(name) == "report.html";
            const bool markdown = std::string(name) == "report.md";
            // The reference list: every key, escaped as the report escapes text.
            for (const report::Reference& r : report::references()) {
                const std::string key = html       ? report::html_escape(r.key)
                                        : markdown ? report::markdown_escape(r.key)
                                                   : r.key;
                INFO(key);
                CHECK(text.find(key) != std::string::npos);
            }
            if (std::string(name) == "result.json") continue;
            const std::size_t refs =
                text.find(html ? "<h2>References</h2>" : "\n## References\n");
            REQUIRE(refs != std::string::npos);
            const std::string body = text.substr(0, refs);
            // Cited where the methods are used, before the list.
            for (const char* key : {"docs/methods.md s.2", "docs/methods.md s.4",
                                    "docs/methods.md s.6", "ASCE 4-16", "ASCE 43-05",
                                    "Shenton 1996", "Clopper &", "SRP 3.7.1"}) {
                INFO(key);
                CHECK(body.find(key) != std::string::npos);
            }
        }
    }
    CHECK(cases >= 7);
}

TEST_CASE("the validation report cites docs/methods.md and the thesis and lists its references",
          "[report][methods][references]") {
    for (const char* name : {"report.md", "report.html"}) {
        const fs::path p = source_dir / "reports" / "validation" / name;
        INFO(fs::relative(p, source_dir).string());
        const std::string text = test::slurp(p);
        CHECK(text.find(old_name) == std::string::npos);
        const std::size_t refs = text.find(std::string(name) == "report.html"
                                               ? "<h2>References</h2>"
                                               : "\n## References\n");
        REQUIRE(refs != std::string::npos);
        const std::string body = text.substr(0, refs), list = text.substr(refs);
        for (const char* key : {"docs/methods.md s.", "Saraswat 2017"}) {
            INFO(key);
            CHECK(body.find(key) != std::string::npos);
            CHECK(list.find(key == std::string("Saraswat 2017") ? key : "docs/methods.md") !=
                  std::string::npos);
        }
    }
}

}  // namespace freestand_test_report_test_citations
