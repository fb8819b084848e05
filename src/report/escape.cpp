#include "report/escape.hpp"

#include <string_view>

#include "core/printable.hpp"

namespace freestand::report {

namespace escape_detail {

/// text with each character replaced as `entity` says (nullptr: no entity for it). The
/// reordering Unicode characters are shown first; a control character without an entity shows
/// as \xNN unless `kept` lists it.
template <typename Entity>
std::string escape_each(const std::string& text_given, Entity entity, std::string_view kept) {
    // Bidirectional overrides in case text would reorder the report around them.
    const std::string text = core::visible_unicode_controls(text_given);
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        if (const char* e = entity(c))
            out += e;
        else if (core::is_control(c) && kept.find(c) == std::string_view::npos)
            out += core::visible_control(c);
        else
            out += c;
    }
    return out;
}

/// Markdown's punctuation that would start emphasis, code, links, tables or headings.
const char* markdown_entity(char c) {
    switch (c) {
        case '&': return "&amp;";
        case '<': return "&lt;";
        case '\n':
        case '\r': return " ";
        case '\\': return "\\\\";
        case '`': return "\\`";
        case '*': return "\\*";
        case '_': return "\\_";
        case '[': return "\\[";
        case ']': return "\\]";
        case '|': return "\\|";
        case '#': return "\\#";
        case '!': return "\\!";
        default: return nullptr;
    }
}

const char* html_entity(char c) {
    switch (c) {
        case '&': return "&amp;";
        case '<': return "&lt;";
        case '>': return "&gt;";
        case '"': return "&quot;";
        case '\'': return "&#39;";
        default: return nullptr;
    }
}

}  // namespace escape_detail

std::string markdown_escape(const std::string& text) {
    return escape_detail::escape_each(text, escape_detail::markdown_entity, "");
}

std::string html_escape(const std::string& text) {
    return escape_detail::escape_each(text, escape_detail::html_entity, "\n\r\t");
}

}  // namespace freestand::report
