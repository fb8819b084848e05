#include "core/printable.hpp"

#include <fmt/format.h>

namespace freestand::core {

namespace {

// The code point of the UTF-8 sequence at text[i] when it is one that visible_unicode_controls
// shows, with its length in bytes; {0, 0} otherwise. C1 controls are C2 80-C2 9F; U+061C is
// D8 9C; U+200E-U+200F, U+2028-U+202E and U+2066-U+2069 are E2 80 8E-8F, E2 80 A8-AE and
// E2 81 A6-A9 (RFC 3629).
struct Hidden {
    unsigned code_point;
    std::size_t bytes;
};

Hidden hidden_at(std::string_view text, std::size_t i) {
    const auto byte = [&text](std::size_t k) {
        return k < text.size() ? static_cast<unsigned char>(text[k]) : 0u;
    };
    const unsigned b0 = byte(i);
    const unsigned b1 = byte(i + 1);
    if (b0 == 0xC2 && b1 >= 0x80 && b1 <= 0x9F) return {b1, 2};
    if (b0 == 0xD8 && b1 == 0x9C) return {0x061C, 2};
    if (b0 != 0xE2) return {0, 0};
    const unsigned b2 = byte(i + 2);
    const unsigned code_point = 0x2000 + ((b1 & 0x3Fu) << 6) + (b2 & 0x3Fu);
    const bool shown = (b1 == 0x80 && ((b2 >= 0x8E && b2 <= 0x8F) || (b2 >= 0xA8 && b2 <= 0xAE))) ||
                       (b1 == 0x81 && b2 >= 0xA6 && b2 <= 0xA9);
    return shown ? Hidden{code_point, 3} : Hidden{0, 0};
}

// text with the characters of visible_unicode_controls as \uXXXX and each ASCII control for
// which show_control is true as its escape.
template <typename ShowControl>
std::string escaped(std::string_view text, ShowControl show_control) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const Hidden h = hidden_at(text, i);
        if (h.bytes > 0) {
            out += fmt::format("\\u{:04X}", h.code_point);
            i += h.bytes;
            continue;
        }
        const char c = text[i++];
        if (is_control(c)) {
            out += show_control(c);
        } else {
            out += c;
        }
    }
    return out;
}

}  // namespace

bool is_control(char c) {
    const auto u = static_cast<unsigned char>(c);
    return u < 0x20 || u == 0x7F;
}

std::string visible_control(char c) {
    return fmt::format("\\x{:02X}", static_cast<unsigned>(static_cast<unsigned char>(c)));
}

std::string visible_unicode_controls(std::string_view text) {
    return escaped(text, [](char c) { return std::string(1, c); });
}

std::string printable(std::string_view text) {
    return escaped(text, [](char c) {
        return c == '\n' || c == '\t' ? std::string(1, c) : visible_control(c);
    });
}

std::string printable_name(std::string_view name) {
    return escaped(name, [](char c) {
        switch (c) {
            case '\n':
                return std::string("\\n");
            case '\r':
                return std::string("\\r");
            case '\t':
                return std::string("\\t");
            default:
                return visible_control(c);
        }
    });
}

}  // namespace freestand::core
