#include "block/mode.hpp"

#include <array>

namespace freestand::block {

namespace mode_detail {

// One word per Mode, in the enumeration's order.
constexpr std::array<const char*, mode_count> words{"rest", "slide", "rock", "slide-rock", "flight"};

}  // namespace mode_detail

const char* to_string(Mode mode) {
    const auto i = static_cast<std::size_t>(mode);
    return i < mode_detail::words.size() ? mode_detail::words[i] : "unknown";
}

}  // namespace freestand::block
