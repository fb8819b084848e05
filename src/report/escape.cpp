#include "report/escape.hpp"

#include "core/printable.hpp"

namespace freestand::report {

std::string markdown_escape(const std::string& text_given) {
    // Bidirectional overrides in case text would reorder the report around them.
    const std::string text = core::visible_unicode_controls(text_given);
    std::string out;
    for (char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '\n':
            case '\r':
                out += ' ';
                break;
            case '\\':
            case '`':
            case '*':
            case '_':
            case '[':
            case ']':
            case '|':
            case '#':
            case '!':
                out += '\\';
                out += c;
                break;
            default:
                if (core::is_control(c)) {
                    out += core::visible_control(c);
                } else {
                    out += c;
                }
        }
    }
    return out;
}

std::string html_escape(const std::string& text_given) {
    // Bidirectional overrides in case text would reorder the report around them.
    const std::string text = core::visible_unicode_controls(text_given);
    std::string out;
    for (char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&#39;";
                break;
            default:
                if (core::is_control(c) && c != '\n' && c != '\r' && c != '\t') {
                    out += core::visible_control(c);
                } else {
                    out += c;
                }
        }
    }
    return out;
}

}  // namespace freestand::report
