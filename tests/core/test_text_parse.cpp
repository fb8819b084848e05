// The project's token parsers (core/text_parse.hpp).
#include <catch2/catch.hpp>
#include <cstddef>
#include <string>
#include <vector>

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

TEST_CASE("parse_number takes a whole finite token without a plus sign", "[core][text]") {
    CHECK(text::parse_number("-0.25") == -0.25);
    CHECK(text::parse_number(".5") == 0.5);
    CHECK(text::parse_number("1e-3") == 0.001);
    CHECK_FALSE(text::parse_number("+1").has_value());
    CHECK_FALSE(text::parse_number(" 1").has_value());
    CHECK_FALSE(text::parse_number("1 ").has_value());
    CHECK_FALSE(text::parse_number("0.3x").has_value());
    CHECK_FALSE(text::parse_number("").has_value());
    CHECK_FALSE(text::parse_number("nan").has_value());
    CHECK_FALSE(text::parse_number("inf").has_value());
    CHECK_FALSE(text::parse_number("1e400").has_value());
}

TEST_CASE("split keeps every item between separators, empty ones too", "[core][text]") {
    using Items = std::vector<std::string>;
    CHECK(text::split("a,b,,c", ',') == Items{"a", "b", "", "c"});
    CHECK(text::split("0.1:1:0.1", ':') == Items{"0.1", "1", "0.1"});
    CHECK(text::split("", ';') == Items{""});
    CHECK(text::split("x;", ';') == Items{"x", ""});
}

}  // namespace freestand_test_core_test_text_parse
