#include "assess/settle.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <random>

#include "assess/biaxial_level.hpp"
#include "assess/body3d_level.hpp"
#include "assess/level_runs.hpp"
#include "assess/verdict.hpp"
#include "core/random.hpp"
#include "core/statistics.hpp"

namespace freestand::assess {

namespace {

// Installs a level's kept runs in the bank for the scope of one level.
class KeptRuns {
  public:
    KeptRuns(HistoryBank& bank, LevelRuns& runs) : bank_(bank) { bank_.keep_level_runs(&runs); }
    ~KeptRuns() { bank_.keep_level_runs(nullptr); }
    KeptRuns(const KeptRuns&) = delete;
    KeptRuns& operator=(const KeptRuns&) = delete;

  private:
    HistoryBank& bank_;
};

// The simulation on the resampled sets: what decide_level reads.
Simulation resampled(const Simulation& s, const std::vector<std::size_t>& sets) {
    Simulation out;
    out.histories = static_cast<int>(sets.size());
    out.sliding_bound = s.sliding_bound;
    out.rocking_bound = s.rocking_bound;
    out.bounds_differ = s.bounds_differ;
    out.slide_m = resample(s.slide_m, sets);
    out.rock_over_alpha = resample(s.rock_over_alpha, sets);
    out.rock_rad = resample(s.rock_rad, sets);
    for (std::size_t k : sets) out.overturned += s.overturned_sets.at(k);
    return out;
}

// Index of one draw among n (n < 2^32), from the high 32 of 64 random bits (Lemire 2019:
// multiply and keep the high word), the same on every compiler, unlike
// std::uniform_int_distribution.
std::size_t draw_index(std::uint64_t bits, std::size_t n) {
    return static_cast<std::size_t>(((bits >> 32) * static_cast<std::uint64_t>(n)) >> 32);
}

// The level marked as failing for want of settling, with the agreeing share in words.
void fail_unsettled(LevelResult& l) {
    const bool passed = passes(l.verdict);
    l.verdict.kind = VerdictKind::anchor;
    l.verdict.failure = Failure::not_settled;
    l.verdict.conditions.clear();
    l.verdict.margin_basis =
        fmt::format("{}; the decision on all sets {} ({})", not_settled_text(*l.settling, passed),
                    passed ? "passes" : "fails", l.verdict.margin_basis);
}

// "; no overturn in N sets: the overturn rate is below U% (95%; 5% needed)", or "".
std::string overturn_bound_text(const Settling& s) {
    if (!s.overturn_rate_upper) return "";
    return fmt::format("; no overturn in {} sets: the overturn rate is below {:.1f}% (Clopper-"
                       "Pearson 95%; {:.0f}% or less needed to pass a level that can uplift)",
                       s.n_sets, 100.0 * *s.overturn_rate_upper, 100.0 * settle_overturn_rate);
}

std::string settling_line(const Settling& s) {
    return fmt::format("settled {}: {:.1f}% of {} bootstrap resamples of the {} sets agree with "
                       "the decision ({:.0f}% needed; {} batch{} of sets){}",
                       s.settled ? "yes" : "NO", 100.0 * s.settled_fraction, s.resamples,
                       s.n_sets, 100.0 * settle_agreement, s.rounds, s.rounds == 1 ? "" : "es",
                       overturn_bound_text(s));
}

}  // namespace

std::string not_settled_text(const Settling& s, bool passed) {
    const double pass_share = passed ? s.settled_fraction : 1.0 - s.settled_fraction;
    if (passed && s.settled_fraction >= settle_agreement && s.overturn_rate_upper) {
        return fmt::format("not settled: no overturn in N = {} sets (cap) bounds the overturn rate "
                           "only below {:.1f}% (Clopper-Pearson 95%; {:.0f}% needed)",
                           s.n_sets, 100.0 * *s.overturn_rate_upper,
                           100.0 * settle_overturn_rate);
    }
    return fmt::format("not settled: {:.0f}% of {} resamples pass at N = {} (cap; {:.0f}% needed "
                       "either way)",
                       100.0 * pass_share, s.resamples, s.n_sets, 100.0 * settle_agreement);
}

bool can_overturn(const LevelResult& level) {
    return uplifts(level.initiation.mode) || (level.body3d && level.body3d->ran) ||
           (level.flexible_simulation && level.flexible_simulation->uplifted > 0);
}

bool decided_by_sets(const LevelResult& level) {
    return level.flexible_simulation.has_value() ||
           (!level.screen.passed && level.simulation.has_value());
}

bool passes_on(const LevelResult& level, const std::vector<std::size_t>& sets,
               double allowable_slide_m, double required_fs) {
    LevelResult r;
    r.screen = level.screen;
    r.flexible = level.flexible;
    if (level.simulation) r.simulation = resampled(*level.simulation, sets);
    if (level.biaxial) {
        r.biaxial = BiaxialSlide{};
        r.biaxial->ran = level.biaxial->ran;
        if (level.biaxial->ran) r.biaxial->slide_m = resample(level.biaxial->slide_m, sets);
    }
    if (level.body3d && level.body3d->ran) {
        r.body3d = Body3dLevel{};
        r.body3d->ran = true;
        r.body3d->flexible = level.body3d->flexible;
        r.body3d->sim = resampled(level.body3d->sim, sets);
    }
    if (level.flexible_simulation) {
        r.flexible_simulation = FlexibleSimulation{};
        r.flexible_simulation->sim = resampled(level.flexible_simulation->sim, sets);
    }
    return passes(decide_level(r, allowable_slide_m, required_fs));
}

Settling settle(const LevelResult& level, std::uint64_t seed, double allowable_slide_m,
                double required_fs) {
    Settling out;
    const Simulation& sim =
        level.flexible_simulation ? level.flexible_simulation->sim : *level.simulation;
    const auto n = static_cast<std::size_t>(sim.histories);
    out.n_sets = sim.histories;
    out.resamples = bootstrap_resamples;
    const bool decision = passes_on(level, [&] {
        std::vector<std::size_t> all(n);
        for (std::size_t k = 0; k < n; ++k) all[k] = k;
        return all;
    }(), allowable_slide_m, required_fs);
    out.settled_fraction =
        bootstrap_agreement(n, seed, decision, [&](const std::vector<std::size_t>& sets) {
            return passes_on(level, sets, allowable_slide_m, required_fs);
        });
    out.settled = out.settled_fraction >= settle_agreement;
    if (decision && can_overturn(level)) {
        out.overturn_rate_upper = core::clopper_pearson(0, sim.histories)[1];
        out.settled = out.settled && *out.overturn_rate_upper <= settle_overturn_rate;
    }
    return out;
}

double bootstrap_agreement(std::size_t n, std::uint64_t seed, bool decision,
                           const std::function<bool(const std::vector<std::size_t>&)>& passes_on_sets) {
    std::mt19937_64 rng(seed);
    std::vector<std::size_t> sets(n);
    int agree = 0;
    for (int b = 0; b < bootstrap_resamples; ++b) {
        for (std::size_t& k : sets) k = draw_index(rng(), n);
        if (passes_on_sets(sets) == decision) ++agree;
    }
    return static_cast<double>(agree) / bootstrap_resamples;
}

std::vector<LevelResult> evaluate_settled(const Case& c, const LevelDemand& demand,
                                          std::size_t level, HistoryBank& bank) {
    const double allowable = c.component.allowable_slide_m;
    const double fs = c.component.required_overturn_fs;
    const std::size_t first = static_cast<std::size_t>(c.options.histories_per_level);
    const std::size_t cap = bank.max_sets();
    std::size_t n = std::min(first, cap);
    std::vector<LevelResult> out;
    // The first n sets' runs are kept from batch to batch (assess/level_runs.hpp).
    LevelRuns kept;
    const KeptRuns keeping(bank, kept);
    for (int round = 1;; ++round) {
        bank.use(n);
        out = {evaluate_level(c, Direction::x, demand, bank),
               evaluate_level(c, Direction::y, demand, bank)};
        apply_biaxial(c, demand, {&out[0], &out[1]}, bank);
        apply_body3d(c, demand, {&out[0], &out[1]}, bank);
        bool settled = true;
        for (LevelResult& l : out) {
            if (!decided_by_sets(l)) continue;
            const std::uint64_t seed =
                core::stream_seed(c.options.seed, 2 * level + (l.direction == Direction::y), n);
            l.settling = settle(l, seed, allowable, fs);
            l.settling->rounds = round;
            settled = settled && l.settling->settled;
        }
        if (settled || n >= cap) break;
        n = std::min(n + static_cast<std::size_t>(settle_batch_sets), cap);
    }
    for (LevelResult& l : out) {
        if (!l.settling) continue;
        l.trail.insert(l.trail.end() - 1, settling_line(*l.settling));
        if (!l.settling->settled) {
            fail_unsettled(l);
            l.trail.back() = fmt::format("governed by {}: fails ({}), {}",
                                         to_string(l.verdict.decided_by),
                                         to_string(l.verdict.failure), l.verdict.margin_basis);
        }
    }
    bank.use(std::min(first, cap));
    return out;
}

}  // namespace freestand::assess
