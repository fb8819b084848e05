#pragma once
/// The one seed mixer of the project: every random stream (history sets, synthetic components
/// and their retries, and later fragility samples) is seeded from a splitmix64 mix of the
/// numbers that identify it, so a result depends on those numbers alone, never on threads,
/// order or machines (the reproducibility of fragility runs and shards, docs/methods.md s.9 and
/// s.12, rests on it).
#include <cstdint>

namespace freestand::core {

/// splitmix64's increment between successive states, the golden-ratio "gamma" (Steele, Lea &
/// Flood 2014).
inline constexpr std::uint64_t splitmix64_gamma = 0x9E3779B97F4A7C15ULL;

/// splitmix64's output function (Steele, Lea & Flood 2014): a bijective 64-bit mix.
constexpr std::uint64_t splitmix64(std::uint64_t z) {
    z += splitmix64_gamma;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

/// Uniform double in [0, 1) from the top 53 bits of one 64-bit draw (portable, unlike
/// std::uniform_real_distribution, whose algorithm the standard leaves open).
constexpr double uniform01(std::uint64_t draw) {
    return static_cast<double>(draw >> 11) * 0x1.0p-53;
}

/// The seed of one stream identified by a run seed and two indices (a fragility sample's level
/// and number): splitmix64 chained over them, so the stream depends on these three numbers only.
constexpr std::uint64_t stream_seed(std::uint64_t seed, std::uint64_t a, std::uint64_t b) {
    return splitmix64(splitmix64(splitmix64(seed) + a) + b);
}

/// The k-th output of splitmix64's sequence started at seed: one stream per index k of a run
/// (the history sets of a case).
constexpr std::uint64_t sequence_seed(std::uint64_t seed, std::uint64_t k) {
    return splitmix64(seed + splitmix64_gamma * k);
}

/// The seed of a synthetic motion's component and retry (docs/methods.md s.8): the two indices
/// are spread by two different odd 64-bit constants (splitmix64's gamma and 0xD1B54A32D192ED03)
/// before the mix, so nearby (component, attempt) pairs give unrelated seeds.
constexpr std::uint64_t component_seed(std::uint64_t seed, std::uint64_t component,
                                       std::uint64_t attempt) {
    return splitmix64(seed ^ (component * splitmix64_gamma) ^ (attempt * 0xD1B54A32D192ED03ULL));
}

}  // namespace freestand::core
