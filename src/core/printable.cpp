#include "core/printable.hpp"

#include <fmt/format.h>

namespace freestand::core {

bool is_control(char c) {
    const auto u = static_cast<unsigned char>(c);
    return u < 0x20 || u == 0x7F;
}

std::string visible_control(char c) {
    return fmt::format("\\x{:02X}", static_cast<unsigned>(static_cast<unsigned char>(c)));
}

std::string printable(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        if (is_control(c) && c != '\n' && c != '\t') {
            out += visible_control(c);
        } else {
            out += c;
        }
    }
    return out;
}

}  // namespace freestand::core
