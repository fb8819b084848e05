// A case file's bytes as every text reader takes them: a UTF-8 BOM dropped, UTF-16 refused
// with a message saying so rather than a TOML syntax error.
#include <catch2/catch.hpp>

#include <string>

#include "assess/case.hpp"
#include "core/errors.hpp"
#include "support/case_text.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_assess_test_case_text {

using namespace freestand;

namespace {
const std::string kCase = test::box_component + test::box_site;
}  // namespace

TEST_CASE("a case file with a UTF-8 BOM reads as without it", "[assess][case]") {
    CHECK(assess::parse_case("\xEF\xBB\xBF" + kCase, "bom.toml").component.name == "Box");
}

TEST_CASE("a UTF-16 case file is refused as UTF-16", "[assess][case]") {
    std::string utf16 = "\xFF\xFE";
    for (char c : kCase) utf16 += std::string{c, '\0'};
    CHECK_THROWS_WITH(assess::parse_case(utf16, "w.toml"),
                      "w.toml:1: UTF-16 text; save it as UTF-8 (the encoding freestand reads)");
}

}  // namespace freestand_test_assess_test_case_text
