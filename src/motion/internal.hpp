#pragma once
/// Stage-internal entry points shared between the motion sources.
#include <cstdint>

#include "motion/motion.hpp"

namespace freestand::motion {

/// Wavelet matching of a record already near the target (no scaling): the loop of
/// match_record, ending with the exact baseline step and the full acceptance check.
MatchResult match_in_place(core::Record record, const Target& target, const MatchOptions& options);

/// splitmix64 mixing of (seed, component, attempt) into an independent generator seed.
std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t component, std::uint64_t attempt);

}  // namespace freestand::motion
