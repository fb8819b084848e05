#pragma once
/// Contact modes of a block on its base (docs/methods.md s.2, s.3): the closed-form initiation
/// checks name the first four, the simulator all five.
#include <cstddef>
#include <string>

namespace freestand::block {

/// Contact state of the block. Rock and slide-rock carry an active edge; the static initiation
/// checks never return flight.
enum class Mode { rest = 0, slide = 1, rock = 2, slide_rock = 3, flight = 4 };
inline constexpr std::size_t mode_count = 5;

/// The mode as an identifier: "rest", "slide", "rock", "slide_rock", "flight". The keys of the
/// simulator's time-in-mode tables and its per-sample mode column.
const char* mode_name(Mode mode);

/// The mode as a word of prose: "rest", "slide", "rock", "slide-rock", "flight". What the
/// initiation checks and the reports print. Both spellings are shipped output (the simulator's
/// JSON keys and the reports' mode fields), so each keeps its own.
std::string to_string(Mode mode);

}  // namespace freestand::block
