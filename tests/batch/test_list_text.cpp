// A batch list's bytes as every text reader takes them: UTF-16 refused with a message saying
// so, in either list format.
#include <catch2/catch.hpp>

#include <string>

#include "batch/list.hpp"
#include "core/errors.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_batch_test_list_text {

using namespace freestand;

namespace {
std::string utf16le(const std::string& ascii) {
    std::string out = "\xFF\xFE";
    for (char c : ascii) out += std::string{c, '\0'};
    return out;
}
}  // namespace

TEST_CASE("a UTF-16 batch list is refused as UTF-16", "[batch][list]") {
    const std::string expected = ":1: UTF-16 text; save it as UTF-8 (the encoding freestand reads)";
    CHECK_THROWS_WITH(batch::parse_csv_list(utf16le("file\na.toml\n"), "l.csv"), "l.csv" + expected);
    CHECK_THROWS_WITH(batch::parse_toml_list(utf16le("[[case]]\nfile = \"a.toml\"\n"), "l.toml"),
                      "l.toml" + expected);
}

TEST_CASE("a batch list with a UTF-8 BOM reads as without it", "[batch][list]") {
    CHECK(batch::parse_csv_list("\xEF\xBB\xBF" "file\na.toml\n", "l.csv").entries.size() == 1);
    CHECK(batch::parse_toml_list("\xEF\xBB\xBF[[case]]\nfile = \"a.toml\"\n", "l.toml")
              .entries.size() == 1);
}

}  // namespace freestand_test_batch_test_list_text
