// The project's token parsers (core/text_parse.hpp).
#include <catch2/catch.hpp>
#include <cstddef>

#include "core/text_parse.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_core_test_text_parse {

namespace text = freestand::core::text;

TEST_CASE("parse_integer takes a whole token of digits in the type's range", "[core][text]") {
    std::size_t n = 0;
    CHECK(text::parse_integer("4001", n));
    CHECK(n == 4001);
    CHECK_FALSE(text::parse_integer("", n));
    CHECK_FALSE(text::parse_integer("12x", n));
    CHECK_FALSE(text::parse_integer(" 12", n));
    CHECK_FALSE(text::parse_integer("+12", n));
    CHECK_FALSE(text::parse_integer("-1", n));
    CHECK_FALSE(text::parse_integer("99999999999999999999999", n));
    long s = 0;
    CHECK(text::parse_integer("-7", s));
    CHECK(s == -7);
}

TEST_CASE("parse_double takes a whole token, a leading plus allowed", "[core][text]") {
    double v = 0.0;
    CHECK(text::parse_double("+0.25", v));
    CHECK(v == 0.25);
    CHECK_FALSE(text::parse_double("0.3x", v));
    CHECK_FALSE(text::parse_double("", v));
    CHECK(text::trim(" \t0.1\r") == "0.1");
}

}  // namespace freestand_test_core_test_text_parse
