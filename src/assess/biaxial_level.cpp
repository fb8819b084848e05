#include "assess/biaxial_level.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <string>

#include "assess/level_runs.hpp"
#include "assess/run_cache.hpp"
#include "assess/verdict.hpp"
#include "core/parallel.hpp"
#include "dynamics/biaxial.hpp"

namespace freestand::assess {

namespace {

// Why the biaxial model does not apply to the level, or nullopt: it needs a block that slides at
// the sliding bound and rocks under none of the histories (in either direction's geometry).
std::optional<std::string> not_applicable(const Case& c, const LevelResult& l,
                                          const dynamics::BiaxialModel& model,
                                          const std::vector<dynamics::BiaxialExcitation>& ex) {
    if (l.initiation_lower.mode != Mode::slide)
        return fmt::format("the block does not slide alone at the sliding bound (mode {}): "
                           "the biaxial model has no rocking",
                           to_string(l.initiation_lower.mode));
    for (Direction d : {Direction::x, Direction::y}) {
        for (std::size_t k = 0; k < ex.size(); ++k) {
            const auto why = dynamics::biaxial_rocking_reason(c.component.block(d), model, ex[k],
                                                              c.site.g_mps2);
            if (why)
                return fmt::format("history {}, block of direction {}: {}; the biaxial model "
                                   "has no rocking",
                                   k + 1, to_string(d), *why);
        }
    }
    return std::nullopt;
}

// Peak |u| of every history run biaxially at the sliding bound, the excitations at pga_g.
Stats biaxial_peaks(const dynamics::BiaxialModel& model,
                    const std::vector<dynamics::BiaxialExcitation>& ex, double pga_g,
                    double g_mps2, HistoryBank& bank) {
    dynamics::Options opt = dynamics::biaxial_options();
    opt.record_series = false;
    opt.g_mps2 = g_mps2;
    std::vector<double> peaks(ex.size());
    RunTable<double>* kept = bank.level_runs() ? &bank.level_runs()->biaxial(ex.size()) : nullptr;
    core::parallel_for(ex.size(), bank.run().threads, [&](std::size_t k) {
        peaks[k] = remembered(
            kept, k, [&] {
                return biaxial_peak_run(bank.run().run_cache, model, ex[k],
                                        bank.excitation_key(k, 2, pga_g, ex[k]), opt);
            });
    });
    return stats_of(peaks);
}

}  // namespace

void apply_biaxial(const Case& c, const LevelDemand& demand, std::vector<LevelResult*> levels,
                   HistoryBank& bank) {
    std::vector<LevelResult*> simulated;
    for (LevelResult* l : levels)
        if (l->simulation) simulated.push_back(l);
    if (simulated.empty()) return;
    // The sliding bound is the base's lower friction, the same in x and y.
    const ContactBound& bound = simulated.front()->bounds.sliding;
    const dynamics::BiaxialModel model = dynamics::make_biaxial_model(bound.mu_s, bound.mu_k);
    std::vector<dynamics::BiaxialExcitation> ex;
    for (const HistorySet& set : bank.sets())
        ex.push_back(dynamics::biaxial_excitation_from_records(set.h1, set.h2, demand.pga_g,
                                                               &set.v));
    // The larger governing planar peak slip of the level's simulated directions.
    const LevelResult* planar = *std::max_element(
        simulated.begin(), simulated.end(), [](const LevelResult* a, const LevelResult* b) {
            return a->simulation->governing(a->simulation->slide_m) <
                   b->simulation->governing(b->simulation->slide_m);
        });
    std::optional<Stats> peaks;
    for (LevelResult* l : simulated) {
        BiaxialSlide b;
        if (const auto why = not_applicable(c, *l, model, ex)) {
            b.reason = *why;
            l->model_reason += "; biaxial sliding does not apply: " + *why;
        } else {
            if (!peaks) peaks = biaxial_peaks(model, ex, demand.pga_g, c.site.g_mps2, bank);
            b.ran = true;
            b.slide_m = *peaks;
            b.reason = "the block slides without rocking at the sliding bound: both horizontal "
                       "components act at once (docs/methods.md s.10)";
            b.planar_direction = planar->direction;
            b.planar_governing_m = planar->simulation->governing(planar->simulation->slide_m);
            if (b.planar_governing_m > 0.0)
                b.ratio = l->simulation->governing(b.slide_m) / b.planar_governing_m;
            if (l->flexible_simulation) {
                // The flexible model stays the level's model; the biaxial |u| joins its sliding
                // demand (decide_level takes the larger).
                l->model_reason += "; biaxial sliding of the rigid block ran too (" + b.reason +
                                   "): the larger sliding demand of the two governs";
            } else {
                l->model = biaxial_model_name;
                l->model_reason = b.reason + "; rocking and overturning stay with the planar block";
                if (l->flexible.raised)
                    l->model_reason += "; the flexible-body flag is raised and stays a condition";
            }
        }
        l->biaxial = std::move(b);
        redecide_level(*l, c.component);
    }
}

}  // namespace freestand::assess
