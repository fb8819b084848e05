#pragma once
/// The one-line verdict of an assessed case, for a terminal.
#include <string>

#include "assess/result.hpp"

namespace freestand::report {

/// All from the headline's one governing level: "<name>: <verdict> (governing PGA 0.400 g,
/// direction x[ with <material>], margin 1.15 | no motion, decided by <model>)" and
/// "; open condition: ..." for each open condition.
std::string verdict_line(const assess::AssessmentResult& r);

}  // namespace freestand::report
