#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "core/errors.hpp"
#include "core/limits.hpp"
#include "goal/goal.hpp"
#include "goal/models_detail.hpp"

namespace freestand::goal {
namespace {

// The engine's highest level (fragility::validate), g.
constexpr double kMaxPga_g = core::limits::max_design_level_g;

double margin_of(double target, double p) {
    return p > 0.0 ? target / p : std::numeric_limits<double>::infinity();
}

LimitState limit_state(const fragility::Result& r, std::size_t e, double dbe_g) {
    std::vector<int> k, n;
    for (const fragility::Level& l : r.levels) {
        k.push_back(l.events[e].k);
        n.push_back(l.events[e].n);
    }
    const std::vector<double>& pga = r.meta.config.pga_g;
    LimitState s;
    s.event = fragility::all_events[e];
    s.fit = r.fits[e];
    s.at_dbe = fragility::probability_at(pga, k, n, dbe_g);
    s.at_150 = fragility::probability_at(pga, k, n, 1.5 * dbe_g);
    const double m_dbe = margin_of(target_dbe, s.at_dbe.p);
    const double m_150 = margin_of(target_150, s.at_150.p);
    s.at_150_governs = m_150 < m_dbe;
    if (std::min(m_dbe, m_150) < std::numeric_limits<double>::infinity())
        s.margin = std::min(m_dbe, m_150);
    s.passes = s.at_dbe.p <= target_dbe && s.at_150.p <= target_150;
    return s;
}

// The least margin governs; "any" unless a single limit state has as little (it then says
// which failure it is) or none has a margin at all.
std::size_t governing_of(const std::array<LimitState, 4>& states) {
    const auto key = [&](std::size_t e) {
        return states[e].margin.value_or(std::numeric_limits<double>::infinity());
    };
    std::size_t best = 3;
    for (std::size_t e = 0; e < 3; ++e) {
        const bool tie = best == 3 && key(e) == key(3) && states[e].margin.has_value();
        if (key(e) < key(best) || tie) best = e;
    }
    return best;
}

std::vector<std::string> estimate_notes(const PerformanceGoal& g) {
    std::vector<std::string> out;
    out.push_back(fmt::format(
        "P and its 95% interval come from the lognormal fitted by maximum likelihood over the "
        "levels; the interval is the profile likelihood's (docs/methods.md s.9) and covers the "
        "sampling of {} samples a level, given the lognormal form and the {} history sets the "
        "samples draw from (the case's own, options.histories_per_level).",
        g.meta.config.samples, g.meta.config.pool));
    const std::size_t levels = g.meta.config.pga_g.size();
    if (levels < dbe_multiples.size()) {
        const bool extrapolated = 1.5 * g.dbe_pga_g > kMaxPga_g;
        const bool below = 0.5 * g.dbe_pga_g < core::limits::min_pga_level_g;
        out.push_back(fmt::format(
            "Levels {} {:g} g, the engine's range, are left out ({} of {}){}.",
            below ? "below" : "above", below ? core::limits::min_pga_level_g : kMaxPga_g,
            dbe_multiples.size() - levels, dbe_multiples.size(),
            extrapolated ? ": P at 1.5 x DBE is read off the curve fitted below it" : ""));
    }
    return out;
}

}  // namespace

PerformanceGoal evaluate_goal(const assess::Case& c, const assess::RunSettings& run) {
    if (!c.site.dbe_pga_g) throw std::invalid_argument("evaluate_goal: the case names no DBE");
    if (!c.units.empty())
        throw InputError(SourceLocation{c.file, 0, "site.dbe_pga_g"},
                         "the performance goal runs the fragility engine, which takes one "
                         "component, not two [[unit]] tables");
    PerformanceGoal g;
    g.dbe_pga_g = *c.site.dbe_pga_g;
    fragility::Config config;
    for (const double m : dbe_multiples)
        if (core::limits::within(m * g.dbe_pga_g, core::limits::pga_level_g))
            config.pga_g.push_back(m * g.dbe_pga_g);
    config.samples = samples_per_level;
    config.seed = c.options.seed;
    config.pool = c.options.histories_per_level;
    detail::GoalModels models = detail::goal_models(c, config.pga_g);
    config.models = models.models;
    fragility::Runner runner(c, config);
    runner.prepare(run);
    std::vector<std::size_t> all(runner.total());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    auto samples =
        fragility::run_samples(runner, all, run.threads, [&](std::size_t done, std::size_t total) {
            if (run.progress) run.progress("performance goal: samples", done, total);
        });
    const fragility::Meta meta = fragility::make_meta(c, config);
    const fragility::Result result = fragility::aggregate(meta, std::move(samples));
    g.meta = meta;
    g.models = models.text;
    g.levels = result.levels;
    for (std::size_t e = 0; e < fragility::all_events.size(); ++e)
        g.limit_states[e] = limit_state(result, e, g.dbe_pga_g);
    g.governing = governing_of(g.limit_states);
    g.passes = std::all_of(g.limit_states.begin(), g.limit_states.end(),
                           [](const LimitState& s) { return s.passes; });
    g.notes = std::move(models.notes);
    for (std::string& n : estimate_notes(g)) g.notes.push_back(std::move(n));
    return g;
}

}  // namespace freestand::goal
