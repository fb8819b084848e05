#pragma once
/// Stage-internal entry points shared between the motion sources.
#include <cstdint>

#include "motion/motion.hpp"

namespace freestand::motion {

/// Wavelet matching of a record already near the target (no scaling): the loop of
/// match_record, ending with the exact baseline step and the full acceptance check.
MatchResult match_in_place(core::Record record, const Target& target, const MatchOptions& options);

/// Uniform double in [0, 1) from the top 53 bits of one mt19937_64 draw (portable, unlike
/// std::uniform_real_distribution).
double uniform01(std::uint64_t draw);

/// splitmix64 mixing of (seed, component, attempt) into an independent generator seed.
std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t component, std::uint64_t attempt);

}  // namespace freestand::motion
