#pragma once
/// Stage-internal entry points shared between the motion sources.
#include <cstdint>

#include "motion/motion.hpp"

namespace freestand::motion {

/// Wavelet matching of a record already near the target (no scaling): the loop of
/// match_record, ending with the exact baseline step and the full acceptance check.
MatchResult match_in_place(core::Record record, const Target& target, const MatchOptions& options);

/// check_acceptance for a caller that reads only `passed` unless the record passes: the
/// criteria in order of cost, returning at the first that fails (then only `passed`, false, is
/// meaningful). A record that passes gets check_acceptance's report, bit for bit.
Acceptance check_acceptance_or_reject(const core::Record& record, const Target& target);

}  // namespace freestand::motion
