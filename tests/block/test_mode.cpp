#include <catch2/catch.hpp>
#include <string>

#include "block/mode.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_block_test_mode {

using freestand::block::Mode;

TEST_CASE("each mode has one spelling, the same in every output", "[block]") {
    // The simulator's time-in-mode keys and mode column, the reports and classify all print it.
    const Mode modes[] = {Mode::rest, Mode::slide, Mode::rock, Mode::slide_rock, Mode::flight};
    const char* words[] = {"rest", "slide", "rock", "slide-rock", "flight"};
    REQUIRE(std::size(modes) == freestand::block::mode_count);
    for (std::size_t i = 0; i < std::size(modes); ++i) {
        CHECK(std::string(freestand::block::to_string(modes[i])) == words[i]);
        CHECK(static_cast<std::size_t>(modes[i]) == i);
    }
}

}  // namespace freestand_test_block_test_mode
