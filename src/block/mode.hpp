#pragma once
/// Contact modes of a block on its base (docs/methods.md s.2, s.3): the closed-form initiation
/// checks name the first four, the simulator all five.
#include <cstddef>

namespace freestand::block {

/// Contact state of the block. Rock and slide-rock carry an active edge; the static initiation
/// checks never return flight.
enum class Mode { rest = 0, slide = 1, rock = 2, slide_rock = 3, flight = 4 };
inline constexpr std::size_t mode_count = 5;

/// The mode's one spelling: "rest", "slide", "rock", "slide-rock", "flight" (Shenton's term for
/// the combined mode). What the initiation checks, the reports, the simulator's time-in-mode
/// tables and its per-sample mode column print.
const char* to_string(Mode mode);

}  // namespace freestand::block
