#include <catch2/catch.hpp>
#include <string>

#include "block/mode.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_block_test_mode {

using freestand::block::Mode;

TEST_CASE("each mode has one identifier and one word, the shipped spellings", "[block]") {
    // The simulator's JSON keys use the identifier, the reports and classify the word.
    const Mode modes[] = {Mode::rest, Mode::slide, Mode::rock, Mode::slide_rock, Mode::flight};
    const char* names[] = {"rest", "slide", "rock", "slide_rock", "flight"};
    const char* words[] = {"rest", "slide", "rock", "slide-rock", "flight"};
    REQUIRE(std::size(modes) == freestand::block::mode_count);
    for (std::size_t i = 0; i < std::size(modes); ++i) {
        CHECK(std::string(freestand::block::mode_name(modes[i])) == names[i]);
        CHECK(freestand::block::to_string(modes[i]) == words[i]);
        CHECK(static_cast<std::size_t>(modes[i]) == i);
    }
}

}  // namespace freestand_test_block_test_mode
