#include "assess/joined.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <limits>

#include "assess/level.hpp"
#include "assess/pipeline.hpp"
#include "assess/settle.hpp"
#include "core/random.hpp"
#include "assess/verdict.hpp"
#include "core/contract.hpp"
#include "core/parallel.hpp"
#include "dynamics/pair.hpp"

namespace freestand::assess {

namespace {

// Below this the units move together (the sliding "no motion" threshold of docs/methods.md s.2).
constexpr double no_relative_motion_m = 1e-4;

struct UnitModels {
    dynamics::BlockModel lower;  ///< lower friction bound, upper restitution
    dynamics::BlockModel upper;  ///< upper friction and restitution bounds
};

UnitModels unit_models(const Component& unit, Direction d) {
    const DirectionBounds b = direction_bounds(unit, d);
    return UnitModels{block_model(unit, b.sliding, d), block_model(unit, b.rocking, d)};
}

// One set's pair runs in one direction: the larger relative peak of the two opposite-friction
// pairings, the relative peak at the common lower bound, and whether a unit overturned.
struct PairRuns {
    double peak_m = 0.0;
    double common_m = 0.0;
    bool overturned = false;
};

// Appends the runs of the bank's sets from runs.size() on in direction d.
void run_pairs(const Case& c, Direction d, double pga_g, HistoryBank& bank,
               std::vector<PairRuns>& runs) {
    const std::array<UnitModels, 2> m{unit_models(c.units[0], d), unit_models(c.units[1], d)};
    dynamics::PairOptions pair;
    pair.tunnel_height_m = c.tunnel->height_m;
    dynamics::Options opt;
    opt.g_mps2 = c.site.g_mps2;
    const auto sets = bank.sets();
    const std::size_t first = runs.size();
    runs.resize(sets.size());
    core::parallel_for(sets.size() - first, bank.run().threads, [&](std::size_t i) {
        const std::size_t k = first + i;
        const dynamics::Excitation ex = excitation(sets[k], d, pga_g);
        const auto a = dynamics::simulate_pair({m[0].lower, m[1].upper}, ex, pair, opt);
        const auto b = dynamics::simulate_pair({m[0].upper, m[1].lower}, ex, pair, opt);
        const auto same = dynamics::simulate_pair({m[0].lower, m[1].lower}, ex, pair, opt);
        runs[k] = {std::max(a.relative_max_m, b.relative_max_m), same.relative_max_m,
                   a.overturned || b.overturned || same.overturned};
    });
}

TunnelDirection tunnel_direction(Direction d, const std::vector<PairRuns>& runs) {
    TunnelDirection out;
    out.direction = d;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> relative, common;
    double worst = -1.0;
    for (std::size_t k = 0; k < runs.size(); ++k) {
        const PairRuns& r = runs[k];
        if (r.overturned) ++out.overturned;
        relative.push_back(r.overturned ? nan : r.peak_m);
        common.push_back(r.overturned ? nan : r.common_m);
        const double score = r.overturned ? 1e9 : r.peak_m;
        if (score > worst) {
            worst = score;
            out.governing_history = static_cast<int>(k);
        }
    }
    out.relative_m = stats_of(relative);
    out.relative_common_m = stats_of(common);
    return out;
}

// The tunnel's decision on the sets at the given indices: any overturned unit, or the 84th
// percentile of either direction's relative peaks above the slack, fails.
bool tunnel_passes_on(const std::array<std::vector<PairRuns>, 2>& runs,
                      const std::vector<std::size_t>& sets, double allowable_m) {
    for (const std::vector<PairRuns>& dir : runs) {
        std::vector<double> peaks;
        peaks.reserve(sets.size());
        for (std::size_t k : sets) {
            if (dir[k].overturned) return false;
            peaks.push_back(dir[k].peak_m);
        }
        if (order_statistic(peaks, governing_percentile) > allowable_m) return false;
    }
    return true;
}

// The level's statistics and decision on the runs so far.
TunnelLevel decide_tunnel(const Case& c, double pga_g,
                          const std::array<std::vector<PairRuns>, 2>& runs) {
    TunnelLevel t;
    t.pga_g = pga_g;
    t.histories = static_cast<int>(runs[0].size());
    t.model_reason =
        "the units stand free and are not braced: each slides and rocks as its own rigid block, "
        "and the tunnel sees their relative displacement at its height";
    double worst = -1.0;
    for (std::size_t i = 0; i < 2; ++i) {
        t.directions[i] = tunnel_direction(i == 0 ? Direction::x : Direction::y, runs[i]);
        const TunnelDirection& td = t.directions[i];
        const double demand = td.relative_m.p84;
        const double score = td.overturned > 0 ? 1e9 : demand;
        if (score > worst) {
            worst = score;
            t.governing_direction = i;
            t.demand_m = demand;
        }
    }
    const TunnelDirection& g = t.directions[t.governing_direction];
    const double allowable = c.tunnel->allowable_relative_m;
    if (g.overturned == 0 && t.demand_m >= no_relative_motion_m) t.margin = allowable / t.demand_m;
    t.passes = g.overturned == 0 && t.demand_m <= allowable;
    return t;
}

// Bootstrap streams of the tunnel: after the 2 per level of the units' own levels.
std::uint64_t tunnel_stream(const Case& c, std::size_t level) {
    return 2 * c.site.pga_g.size() + level;
}

std::string level_text(const TunnelLevel& t, const Tunnel& tunnel) {
    const TunnelDirection& g = t.directions[t.governing_direction];
    const std::string stat = "84th-percentile";
    if (g.overturned > 0)
        return fmt::format("a unit overturned in {} of {} histories (direction {}): the tunnel "
                           "is lost",
                           g.overturned, t.histories, to_string(g.direction));
    return fmt::format("{} relative displacement {:.1f} mm (direction {}) {} slack {:.1f} mm",
                       stat, t.demand_m * 1000.0, to_string(g.direction),
                       t.passes ? "<=" : ">", tunnel.allowable_relative_m * 1000.0);
}

std::string bounds_text(const Case& c) {
    return fmt::format(
        "Tunnel check (docs/methods.md s.10): units 1 and 2 stand side by side, each its own "
        "rigid planar block under the same base motion (the level's histories, in x and in y), "
        "the tunnel {:.3g} m above the base. The friction is measured once and the two units' "
        "feet need not share it, so the relative demand is bounded by letting them differ as "
        "far as the bounds allow: per history, the larger relative peak of unit 1 at its lower "
        "friction bound with unit 2 at its upper, and the reverse; both at their upper "
        "restitution bound (more rocking, docs/methods.md s.6 step 6). Both units at their "
        "common lower bound is shown beside it. The relative displacement u_1 - u_2 + h_t "
        "(theta_1 - theta_2) is taken at the input samples (the miss between samples is below "
        "0.1% of the peak on El Centro at 0.01 s, tests/dynamics/test_pair.cpp). Any overturned "
        "unit loses the tunnel. The check runs on the case's own base: a material the units' "
        "search recommends is not re-checked at the tunnel.",
        c.tunnel->height_m);
}

const char* const remedy_text =
    "brace the units together into one body (cross bracing between the stands, as the thesis "
    "did: braced, the pair kept its integrity to 0.4 g with negligible relative slip; Saraswat "
    "2017 ch. 7), then assess the braced pair as one component";

}  // namespace

Case unit_case(const Case& c, std::size_t i) {
    FREESTAND_EXPECT(i < c.units.size(), "a unit of the case");
    Case out = c;
    out.component = c.units[i];
    out.units.clear();
    out.tunnel.reset();
    return out;
}

TunnelLevel tunnel_level(const Case& c, std::size_t level, HistoryBank& bank) {
    FREESTAND_EXPECT(c.units.size() == 2 && c.tunnel, "two units and a tunnel");
    FREESTAND_EXPECT(level < c.site.pga_g.size(), "a level of the case");
    const double pga_g = c.site.pga_g[level];
    const double allowable = c.tunnel->allowable_relative_m;
    const std::size_t cap = bank.max_sets();
    const std::size_t first = std::min(static_cast<std::size_t>(c.options.histories_per_level), cap);
    std::size_t n = first;
    std::array<std::vector<PairRuns>, 2> runs;
    TunnelLevel t;
    for (int round = 1;; ++round) {
        bank.use(n);
        run_pairs(c, Direction::x, pga_g, bank, runs[0]);
        run_pairs(c, Direction::y, pga_g, bank, runs[1]);
        t = decide_tunnel(c, pga_g, runs);
        t.settling.n_sets = static_cast<int>(n);
        t.settling.resamples = bootstrap_resamples;
        t.settling.rounds = round;
        t.settling.settled_fraction = bootstrap_agreement(
            n, core::stream_seed(c.options.seed, tunnel_stream(c, level), n), t.passes,
            [&](const std::vector<std::size_t>& sets) {
                return tunnel_passes_on(runs, sets, allowable);
            });
        t.settling.settled = t.settling.settled_fraction >= settle_agreement;
        if (t.settling.settled || n >= cap) break;
        n = std::min(n + static_cast<std::size_t>(settle_batch_sets), cap);
    }
    bank.use(first);
    t.text = level_text(t, *c.tunnel);
    if (!t.settling.settled) {
        t.text = fmt::format("{}; on all sets {}", not_settled_text(t.settling, t.passes), t.text);
        t.passes = false;
    }
    return t;
}

AssessmentResult assess_joined(const Case& c, const RunSettings& run) {
    FREESTAND_EXPECT(c.units.size() == 2 && c.tunnel, "two units and a tunnel");
    auto joined = std::make_shared<JoinedResult>();
    joined->tunnel = *c.tunnel;
    for (std::size_t i = 0; i < 2; ++i) joined->units[i] = assess(unit_case(c, i), run);
    HistoryBank bank(c, run);
    for (std::size_t i = 0; i < c.site.pga_g.size(); ++i)
        joined->levels.push_back(tunnel_level(c, i, bank));
    std::vector<std::string> failing;
    for (std::size_t i = 0; i < joined->levels.size(); ++i) {
        const TunnelLevel& l = joined->levels[i];
        if (!l.passes && joined->tunnel_passes) {
            joined->tunnel_passes = false;
            joined->governing_level = i;
        }
        if (joined->tunnel_passes && l.demand_m > joined->levels[joined->governing_level].demand_m)
            joined->governing_level = i;
    }
    if (!joined->tunnel_passes) {
        const TunnelLevel& l = joined->levels[joined->governing_level];
        joined->remedy = remedy_text;
        failing.push_back(fmt::format("tunnel fails at PGA {:.3f} g ({}): {}", l.pga_g, l.text,
                                      remedy_text));
    }
    for (std::size_t i = 0; i < 2; ++i) {
        const AssessmentResult& u = joined->units[i];
        if (!passes(u.overall.verdict))
            failing.push_back(fmt::format("unit {} ({}): {}", i + 1, u.input.component.name,
                                          verdict_text(u.overall.verdict)));
    }
    joined->passes = failing.empty();
    joined->verdict = joined->passes ? "free-standing acceptable: both units pass and the tunnel "
                                       "keeps its seat at every level"
                                     : fmt::format("{}", fmt::join(failing, "; "));
    joined->bounds = bounds_text(c);
    AssessmentResult r;
    r.input = c;
    const bool second_worse = more_severe(joined->units[1].overall.verdict,
                                          joined->units[0].overall.verdict);
    r.overall = joined->units[second_worse ? 1 : 0].overall;
    r.own = r.overall;
    r.histories_generated = static_cast<int>(bank.made().size());
    for (const AssessmentResult& u : joined->units) {
        r.simulations_run += u.simulations_run;
    }
    // Per level: two directions, three pairings, two units, every set of the level.
    for (const TunnelLevel& l : joined->levels) r.simulations_run += 12 * l.histories;
    r.joined = std::move(joined);
    return r;
}

}  // namespace freestand::assess
