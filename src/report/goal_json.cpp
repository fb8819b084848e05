#include "report/goal_json.hpp"

#include <nlohmann/json.hpp>

#include "report/fragility_json.hpp"
#include "report/json.hpp"

namespace freestand::report {
namespace {

using nlohmann::ordered_json;

ordered_json interval_json(const fragility::Probability& p) {
    return {json_number(p.ci95[0]), json_number(p.ci95[1])};
}

ordered_json optional_number(const std::optional<double>& v) {
    return v ? json_number(*v) : ordered_json(nullptr);
}

// The estimates, margin and fit of one limit state, as the top level carries the governing one's.
void put_estimates(ordered_json& j, const goal::LimitState& s) {
    j["p_dbe"] = json_number(s.at_dbe.p);
    j["p_dbe_ci95"] = interval_json(s.at_dbe);
    j["p_150"] = json_number(s.at_150.p);
    j["p_150_ci95"] = interval_json(s.at_150);
    j["passes"] = s.passes;
    j["margin"] = optional_number(s.margin);
    j["theta_m_g"] = s.fit.fit ? json_number(s.fit.fit->theta_m_g) : ordered_json(nullptr);
    j["beta"] = s.fit.fit ? json_number(s.fit.fit->beta) : ordered_json(nullptr);
}

ordered_json limit_state_json(const goal::LimitState& s, const fragility::Meta& m) {
    ordered_json j;
    j["meaning"] = event_meaning(s.event, m);
    put_estimates(j, s);
    j["fit_note"] = s.fit.fit ? ordered_json(nullptr) : ordered_json(s.fit.note);
    return j;
}

ordered_json levels_json(const std::vector<fragility::Level>& levels, double dbe_pga_g) {
    ordered_json out = ordered_json::array();
    for (const fragility::Level& l : levels) {
        ordered_json k;
        for (std::size_t e = 0; e < fragility::all_events.size(); ++e)
            k[fragility::event_name(fragility::all_events[e])] = l.events[e].k;
        out.push_back({{"pga_g", json_number(l.pga_g)},
                       {"multiple_of_dbe", json_number(l.pga_g / dbe_pga_g)},
                       {"n", l.n},
                       {"k", k}});
    }
    return out;
}

}  // namespace

ordered_json goal_json(const goal::PerformanceGoal& g) {
    const goal::LimitState& gov = g.governing_state();
    const fragility::Config& config = g.meta.config;
    ordered_json j;
    j["dbe_pga_g"] = json_number(g.dbe_pga_g);
    j["configuration"] = g.configuration;
    j["limit_state"] = fragility::event_name(gov.event);
    put_estimates(j, gov);
    j["passes"] = g.passes;
    j["margin_basis"] = goal::goal_basis(g);
    j["targets"] = {{"p_dbe", goal::target_dbe}, {"p_150", goal::target_150}};
    std::vector<ordered_json> levels_g;
    for (const double a : config.pga_g) levels_g.push_back(json_number(a));
    j["levels_g"] = levels_g;
    j["samples_per_level"] = config.samples;
    j["pool"] = config.pool;
    j["seed"] = config.seed;
    j["models"] = g.models;
    j["motions"] = g.meta.motion_source;
    j["mu_s"] = g.meta.mu_s_law;
    j["restitution"] = g.meta.restitution_law;
    ordered_json states;
    for (const goal::LimitState& s : g.limit_states)
        states[fragility::event_name(s.event)] = limit_state_json(s, g.meta);
    j["limit_states"] = states;
    j["levels"] = levels_json(g.levels, g.dbe_pga_g);
    j["notes"] = g.notes;
    j["method"] =
        "docs/methods.md s.6 step 5 and s.9; ASCE 43-05 s.1.3; 95% intervals by the "
        "profile likelihood (Venzon & Moolgavkar 1988)";
    return j;
}

}  // namespace freestand::report
