#pragma once
/// The text-parsing helpers of the project: numbers, blanks, case and lines of input text. Every
/// reader of a token (record files, batch lists, command-line values) parses through these.
#include <charconv>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace freestand::core::text {

/// Parses a whole token as a double (leading '+' allowed). std::from_chars rejects what strtod
/// would half-accept ("0.3x"); "nan" and "inf" parse, so callers check std::isfinite.
bool parse_double(std::string_view token, double& value);

/// The finite number a whole token spells in std::from_chars's syntax ("-0.25", ".5", "1e-3"),
/// as command-line values and batch-list cells are read; std::nullopt for anything else: a
/// leading '+' or blank, trailing text ("0.3x"), "nan", "inf", an empty token.
std::optional<double> parse_number(std::string_view token);

/// Parses a whole token as an integer of type Int (decimal digits, a leading '-' for signed
/// types; no '+', no blanks): false for anything else or a value out of Int's range.
template <class Int>
bool parse_integer(std::string_view token, Int& value) {
    const char* last = token.data() + token.size();
    const auto [ptr, ec] = std::from_chars(token.data(), last, value);
    return !token.empty() && ec == std::errc() && ptr == last;
}

/// Token without leading and trailing blanks (space, tab, CR).
std::string_view trim(std::string_view s);

/// "a,b,,c" split at ',' -> {"a", "b", "", "c"}: the items between separators, empty ones
/// kept so that each caller can name them in its error; "" gives {""}.
std::vector<std::string> split(std::string_view text, char separator);

/// ASCII lower-case copy.
std::string lower(std::string_view s);

/// Longest line the AT2 and COSMOS readers accept. Both formats write lines of about 80
/// characters; the cap bounds the header patterns' work (std::regex recurses per character, so
/// a 50,000-character line overflowed the stack).
inline constexpr std::size_t max_record_line_chars = 1024;

/// Throws InputError at file:line_no unless line has at most max_record_line_chars characters.
void check_record_line_length(const std::string& line, const std::string& file, int line_no);

/// text without a leading UTF-8 byte order mark (EF BB BF), which Windows editors write first.
std::string_view strip_bom(std::string_view text);

/// The text of a UTF-8 input file as its readers take it: without a leading BOM (strip_bom).
/// Throws InputError at file when the text is UTF-16 (a UTF-16 BOM, FF FE or FE FF, or a NUL
/// as the first or second byte: ASCII in UTF-16 is every other byte NUL), which no reader can
/// parse and whose NULs would otherwise reach the messages: "UTF-16 text; save it as UTF-8".
std::string_view utf8_text(std::string_view text, const std::string& file);

/// Splits utf8_text(text, file) into lines without their '\n' or "\r\n".
/// Line i of the result is line i + 1 of the file. Throws InputError at file:max_lines + 1 as
/// soon as the text holds more than max_lines lines: a file of empty lines would otherwise
/// cost a string per byte.
std::vector<std::string> split_lines(const std::string& text, const std::string& file,
                                     std::size_t max_lines);

/// True when s starts with prefix, ignoring ASCII case.
bool istarts_with(std::string_view s, std::string_view prefix);

/// True when s contains needle, ignoring ASCII case.
bool icontains(std::string_view s, std::string_view needle);

}  // namespace freestand::core::text
