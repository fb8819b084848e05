#pragma once
/// The one seed mixer of the project: every random stream (history sets, synthetic components
/// and their retries, and later fragility samples) is seeded from a splitmix64 mix of the
/// numbers that identify it, so a result depends on those numbers alone, never on threads,
/// order or machines (issue 14's reproducibility rests on it).
#include <cstdint>

namespace freestand::core {

/// splitmix64's output function (Steele, Lea & Flood 2014): a bijective 64-bit mix.
constexpr std::uint64_t splitmix64(std::uint64_t z) {
    z += 0x9E3779B97F4A7C15ULL;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

}  // namespace freestand::core
