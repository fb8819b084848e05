// A list's name that cannot name a report folder is quoted in the error on one line: its line
// breaks and bidirectional overrides are shown, not sent to the terminal.
#include <catch2/catch.hpp>

#include "batch/list.hpp"
#include "core/errors.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_batch_test_list_names {

using namespace freestand;

TEST_CASE("a bad name is quoted with its CR, LF and U+202E shown", "[batch][list][escape]") {
    // name = "pump", CR, LF, U+202E, "x" (TOML escapes).
    const std::string text = "[[case]]\nfile = \"a.toml\"\nname = \"pump\\r\\n\\u202Ex\"\n";
    std::string message = "no error";
    try {
        batch::parse_toml_list(text, "plant/list.toml");
    } catch (const InputError& e) {
        message = e.what();
    }
    CHECK(message == "plant/list.toml:3: case.name: \"pump\\r\\n\\u202Ex\" cannot name a report "
                     "folder: use 1-100 letters, digits, '.', '_', '-' or '+', starting with a "
                     "letter or digit");
}

}  // namespace freestand_test_batch_test_list_names
