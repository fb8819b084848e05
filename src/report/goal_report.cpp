#include "report/goal_report.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "report/fragility_json.hpp"
#include "report/template_render.hpp"

namespace freestand::report {
namespace {

std::string estimate_text(const fragility::Probability& p) {
    return fmt::format("{} [{}, {}]", goal::percent_text(p.p), goal::percent_text(p.ci95[0]),
                       goal::percent_text(p.ci95[1]));
}

mstch::map limit_state_row(const goal::LimitState& s, const fragility::Meta& m) {
    const std::optional<fragility::Fit>& fit = s.fit.fit;
    return mstch::map{{"event", std::string(fragility::event_name(s.event))},
                      {"meaning", event_meaning(s.event, m)},
                      {"p_dbe", estimate_text(s.at_dbe)},
                      {"p_150", estimate_text(s.at_150)},
                      {"theta", fit ? fmt::format("{:.3g}", fit->theta_m_g) : "no curve"},
                      {"beta", fit ? fmt::format("{:.3g}", fit->beta) : s.fit.note},
                      {"meets", std::string(s.passes ? "yes" : "no")}};
}

std::string summary(const goal::PerformanceGoal& g) {
    if (g.passes)
        return fmt::format("Met: {}, the least margin of the limit states.", goal::goal_basis(g));
    return fmt::format("Not met: {}. The verdict needs the levels and the goal both: anchor.",
                       goal::goal_basis(g));
}

}  // namespace

mstch::map goal_section_context(const goal::PerformanceGoal& g) {
    mstch::array rows;
    for (const goal::LimitState& s : g.limit_states) rows.push_back(limit_state_row(s, g.meta));
    std::vector<std::string> levels;
    for (const double a : g.meta.config.pga_g) levels.push_back(fmt::format("{:.3g}", a));
    return mstch::map{{"goal_summary", summary(g)},
                      {"goal_kind", std::string(g.passes ? "acceptable" : "anchor")},
                      {"goal_configuration", g.configuration},
                      {"goal_dbe", fmt::format("{:.3g}", g.dbe_pga_g)},
                      {"goal_levels", fmt::format("{}", fmt::join(levels, ", "))},
                      {"goal_samples", std::to_string(g.meta.config.samples)},
                      {"goal_pool", std::to_string(g.meta.config.pool)},
                      {"goal_models", g.models},
                      {"goal_mu_law", g.meta.mu_s_law},
                      {"goal_r_law", g.meta.restitution_law},
                      {"goal_rows", rows},
                      {"goal_notes", text_list(g.notes)}};
}

}  // namespace freestand::report
