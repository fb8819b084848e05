#include "report/history_json.hpp"

#include <nlohmann/json.hpp>

#include "report/json.hpp"

namespace freestand::report {
namespace {

nlohmann::ordered_json range_json(const std::optional<motion::Range>& r) {
    if (!r) return nullptr;
    return nlohmann::ordered_json::array({r->min, r->max});
}

}  // namespace

nlohmann::ordered_json measures_json(const motion::Acceptance& a) {
    return {{"pga_g", round10(a.pga_g)},
            {"pgv_mps", round10(a.pgv_mps)},
            {"pgd_m", round10(a.pgd_m)},
            {"va_mps_per_g", round10(a.va_mps_per_g)},
            {"adv2", round10(a.adv2)},
            {"da_m_per_g", round10(a.da_m_per_g)},
            {"arias_mps", round10(a.arias_mps)},
            {"d5_75_s", round10(a.d5_75_s)},
            {"d5_95_s", round10(a.d5_95_s)},
            {"zpa_g", round10(a.zpa_g)},
            {"pga_over_zpa", round10(a.pga_over_zpa)}};
}

nlohmann::ordered_json realism_json(const motion::Acceptance& a) {
    const motion::RealismLimits& lim = a.realism;
    return {{"passed", a.realism_passed},
            {"srp_passed", a.srp_passed},
            {"pga_over_zpa_range", range_json(lim.pga_over_zpa)},
            {"d5_75_min_s", lim.d5_75_min_s},
            {"va_range_mps_per_g", range_json(lim.va_mps_per_g)},
            {"adv2_range", range_json(lim.adv2)},
            {"da_max_m_per_g",
             lim.da_max_m_per_g ? nlohmann::ordered_json(*lim.da_max_m_per_g) : nullptr},
            {"ratios_checked", a.horizontal}};
}

}  // namespace freestand::report
