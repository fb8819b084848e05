#include "block/mode.hpp"

#include <array>

namespace freestand::block {

namespace mode_detail {

struct Spelling {
    const char* name;
    const char* word;
};

// One row per Mode, in the enumeration's order.
constexpr std::array<Spelling, mode_count> spellings{{
    {"rest", "rest"},
    {"slide", "slide"},
    {"rock", "rock"},
    {"slide_rock", "slide-rock"},
    {"flight", "flight"},
}};

const Spelling* spelling(Mode mode) {
    const auto i = static_cast<std::size_t>(mode);
    return i < spellings.size() ? &spellings[i] : nullptr;
}

}  // namespace mode_detail

const char* mode_name(Mode mode) {
    const auto* s = mode_detail::spelling(mode);
    return s ? s->name : "?";
}

std::string to_string(Mode mode) {
    const auto* s = mode_detail::spelling(mode);
    return s ? s->word : "unknown";
}

}  // namespace freestand::block
