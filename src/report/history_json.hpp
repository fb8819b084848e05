#pragma once
/// One history's ground-motion measures and realism checks as JSON, the same block in
/// `generate`'s match.json and in `assess`'s result.json (docs/methods.md s.8).
#include <nlohmann/json_fwd.hpp>

#include "motion/motion.hpp"

namespace freestand::report {

/// {"pga_g", "pgv_mps", "pgd_m", "va_mps_per_g", "adv2", "da_m_per_g", "arias_mps", "d5_75_s",
///  "d5_95_s", "zpa_g", "pga_over_zpa"}: SI units in the key names, ratios dimensionless.
nlohmann::ordered_json measures_json(const motion::Acceptance& a);

/// {"passed", "srp_passed", "pga_over_zpa_range", "d5_75_min_s", "va_range_mps_per_g",
///  "adv2_range", "da_max_m_per_g", "ratios_checked"}: a range is null when it is not set
/// (its ratio reported, not checked); ratios_checked is false on vertical components.
nlohmann::ordered_json realism_json(const motion::Acceptance& a);

}  // namespace freestand::report
