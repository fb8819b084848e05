#pragma once
/// Generated history sets in the content-addressed cache (core::ContentStore): the key of one
/// set, and the set as bytes. A set read back is the set generated, bit for bit, so every
/// output is the same with or without the cache.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "assess/histories.hpp"
#include "motion/motion.hpp"

namespace freestand::assess {

/// SHA-256 (hex) of everything set k of a case depends on: the generator's version, the build
/// and the run-time libraries (another compiler may round differently), the targets, the
/// generation options (seed and seed records included), the case seed and k.
std::string history_key(const motion::TargetSet& targets, const motion::GenerateOptions& options,
                        std::uint64_t case_seed, std::size_t k);

std::string encode_history(const HistorySet& set);
/// None when the bytes are not a whole set of this format.
std::optional<HistorySet> decode_history(std::string_view bytes);

}  // namespace freestand::assess
