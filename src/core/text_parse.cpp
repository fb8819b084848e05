#include "core/text_parse.hpp"

#include <algorithm>
#include <cctype>
#include <climits>
#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace freestand::core::text {

namespace text_parse_detail {

// The whole of [first, last) as one std::from_chars double; false for an empty range or
// trailing text.
bool whole_double(const char* first, const char* last, double& value) {
    const auto [ptr, ec] = std::from_chars(first, last, value);
    return first != last && ec == std::errc() && ptr == last;
}

}  // namespace text_parse_detail

bool parse_double(std::string_view token, double& value) {
    const char* first = token.data();
    const char* last = token.data() + token.size();
    if (first != last && *first == '+') ++first;
    return text_parse_detail::whole_double(first, last, value);
}

std::optional<double> parse_number(std::string_view token) {
    double value = 0.0;
    if (!text_parse_detail::whole_double(token.data(), token.data() + token.size(), value) ||
        !std::isfinite(value))
        return std::nullopt;
    return value;
}

std::vector<std::string> split(std::string_view text, char separator) {
    std::vector<std::string> items;
    std::size_t start = 0;
    while (true) {
        const std::size_t end = text.find(separator, start);
        items.emplace_back(text.substr(start, end == std::string_view::npos ? end : end - start));
        if (end == std::string_view::npos) return items;
        start = end + 1;
    }
}

std::string_view trim(std::string_view s) {
    const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    while (!s.empty() && blank(s.front())) s.remove_prefix(1);
    while (!s.empty() && blank(s.back())) s.remove_suffix(1);
    return s;
}

std::string lower(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

std::string_view strip_bom(std::string_view text) {
    constexpr std::string_view bom = "\xEF\xBB\xBF";
    return text.substr(0, bom.size()) == bom ? text.substr(bom.size()) : text;
}

std::string_view utf8_text(std::string_view text, const std::string& file) {
    const bool utf16_bom = text.substr(0, 2) == "\xFF\xFE" || text.substr(0, 2) == "\xFE\xFF";
    const bool utf16_ascii = text.size() >= 2 && (text[0] == '\0') != (text[1] == '\0');
    if (utf16_bom || utf16_ascii)
        throw InputError(SourceLocation{file, 1, ""},
                         "UTF-16 text; save it as UTF-8 (the encoding freestand reads)");
    return strip_bom(text);
}

std::vector<std::string> split_lines(const std::string& whole, const std::string& file,
                                     std::size_t max_lines) {
    const std::string_view text = utf8_text(whole, file);
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        if (lines.size() == max_lines)
            throw InputError({file, static_cast<int>(std::min<std::size_t>(max_lines + 1, INT_MAX)), ""},
                             fmt::format("more than {} lines; a record this reader accepts has "
                                         "fewer",
                                         max_lines));
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string line(text.substr(start, end - start));
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(std::move(line));
        start = end + 1;
    }
    return lines;
}

void check_record_line_length(const std::string& line, const std::string& file, int line_no) {
    if (line.size() <= max_record_line_chars) return;
    throw InputError({file, line_no, ""},
                     fmt::format("line is {} characters long; this record format has lines of "
                                 "about 80 characters, and at most {} are accepted",
                                 line.size(), max_record_line_chars));
}

bool istarts_with(std::string_view s, std::string_view prefix) {
    return s.size() >= prefix.size() && lower(s.substr(0, prefix.size())) == lower(prefix);
}

bool icontains(std::string_view s, std::string_view needle) {
    return lower(s).find(lower(needle)) != std::string::npos;
}

}  // namespace freestand::core::text
