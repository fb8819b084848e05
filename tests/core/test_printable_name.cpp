// Names and text shown to a terminal or in a report (core/printable.hpp): line breaks, C1
// controls and bidirectional formatting characters are shown, not obeyed.
#include <catch2/catch.hpp>

#include <string>

#include "core/printable.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_core_test_printable_name {

using namespace freestand;

TEST_CASE("a name is shown on one line: CR, LF and tab escaped", "[core][printable]") {
    CHECK(core::printable_name("Glove box") == "Glove box");
    CHECK(core::printable_name("box\rPASS\nnext\tcol") == "box\\rPASS\\nnext\\tcol");
    CHECK(core::printable_name(std::string("a\x1b[2Jb\0c\x7f", 9)) == "a\\x1B[2Jb\\x00c\\x7F");
    // Text of several lines (an error message) keeps its line feeds and tabs.
    CHECK(core::printable("line 1\nline 2\tx\ry") == "line 1\nline 2\tx\\x0Dy");
}

TEST_CASE("bidirectional formatting characters and C1 controls show as their code points",
          "[core][printable]") {
    // U+202E RIGHT-TO-LEFT OVERRIDE, U+2066 LEFT-TO-RIGHT ISOLATE, U+2069 POP DIRECTIONAL
    // ISOLATE, U+200F RIGHT-TO-LEFT MARK, U+061C ARABIC LETTER MARK, U+0085 NEXT LINE,
    // U+009B CONTROL SEQUENCE INTRODUCER, U+2028 LINE SEPARATOR.
    const std::string hostile = "box \xE2\x80\xAE" "SSAP \xE2\x81\xA6x\xE2\x81\xA9 \xE2\x80\x8F"
                                "\xD8\x9C \xC2\x85 \xC2\x9B" "31m \xE2\x80\xA8";
    const std::string shown =
        "box \\u202ESSAP \\u2066x\\u2069 \\u200F\\u061C \\u0085 \\u009B31m \\u2028";
    CHECK(core::visible_unicode_controls(hostile) == shown);
    CHECK(core::printable(hostile) == shown);
    CHECK(core::printable_name(hostile) == shown);
    // The embeddings and overrides U+202A-U+202E: E2 80 AA-AE.
    const char* const overrides[] = {"\\u202A", "\\u202B", "\\u202C", "\\u202D", "\\u202E"};
    for (int k = 0; k < 5; ++k) {
        const std::string utf8{'\xE2', '\x80', static_cast<char>(0xAA + k)};
        CHECK(core::printable_name(utf8) == overrides[k]);
    }
    // Other characters, the neighbours of those ranges and a lone lead byte pass unchanged.
    const std::string kept = "\xC3\xA9 \xC2\xA0 \xE2\x80\x94 \xE2\x80\xAF \xE2\x81\xA5 \xE2\x81\xAA "
                             "\xCE\xBC_s \xE2";
    CHECK(core::printable_name(kept) == kept);
}

}  // namespace freestand_test_core_test_printable_name
