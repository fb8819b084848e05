#include "assess/joined.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "assess/level.hpp"
#include "assess/pipeline.hpp"
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

TunnelDirection tunnel_direction(const Case& c, Direction d, double pga_g, HistoryBank& bank) {
    const std::array<UnitModels, 2> m{unit_models(c.units[0], d), unit_models(c.units[1], d)};
    dynamics::PairOptions pair;
    pair.tunnel_height_m = c.tunnel->height_m;
    dynamics::Options opt;
    opt.g_mps2 = c.site.g_mps2;
    TunnelDirection out;
    out.direction = d;
    std::vector<double> relative, common;
    double worst = -1.0;
    const auto& sets = bank.sets();
    // Per history: the pair with opposite friction bounds both ways, and with equal ones.
    struct Runs {
        double peak = 0.0, common = 0.0;
        bool overturned = false;
    };
    std::vector<Runs> runs(sets.size());
    core::parallel_for(sets.size(), bank.run().threads, [&](std::size_t k) {
        const dynamics::Excitation ex = excitation(sets[k], d, pga_g);
        const auto a = dynamics::simulate_pair({m[0].lower, m[1].upper}, ex, pair, opt);
        const auto b = dynamics::simulate_pair({m[0].upper, m[1].lower}, ex, pair, opt);
        const auto same = dynamics::simulate_pair({m[0].lower, m[1].lower}, ex, pair, opt);
        runs[k] = {std::max(a.relative_max_m, b.relative_max_m), same.relative_max_m,
                   a.overturned || b.overturned || same.overturned};
    });
    for (std::size_t k = 0; k < sets.size(); ++k) {
        const bool overturned = runs[k].overturned;
        const double peak = runs[k].peak;
        if (overturned) {
            ++out.overturned;
        } else {
            relative.push_back(peak);
            common.push_back(runs[k].common);
        }
        const double score = overturned ? 1e9 : peak;
        if (score > worst) {
            worst = score;
            out.governing_history = static_cast<int>(k);
        }
    }
    out.relative_m = stats_of(relative);
    out.relative_common_m = stats_of(common);
    return out;
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

TunnelLevel tunnel_level(const Case& c, double pga_g, HistoryBank& bank) {
    FREESTAND_EXPECT(c.units.size() == 2 && c.tunnel, "two units and a tunnel");
    TunnelLevel t;
    t.pga_g = pga_g;
    t.histories = static_cast<int>(bank.sets().size());
    t.model_reason =
        "the units stand free and are not braced: each slides and rocks as its own rigid block, "
        "and the tunnel sees their relative displacement at its height";
    double worst = -1.0;
    for (std::size_t i = 0; i < 2; ++i) {
        const Direction d = i == 0 ? Direction::x : Direction::y;
        t.directions[i] = tunnel_direction(c, d, pga_g, bank);
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
    t.text = level_text(t, *c.tunnel);
    return t;
}

AssessmentResult assess_joined(const Case& c, const RunSettings& run) {
    FREESTAND_EXPECT(c.units.size() == 2 && c.tunnel, "two units and a tunnel");
    auto joined = std::make_shared<JoinedResult>();
    joined->tunnel = *c.tunnel;
    for (std::size_t i = 0; i < 2; ++i) joined->units[i] = assess(unit_case(c, i), run);
    HistoryBank bank(c, run);
    for (double pga : c.site.pga_g) joined->levels.push_back(tunnel_level(c, pga, bank));
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
    r.histories_generated = static_cast<int>(bank.sets().size());
    for (const AssessmentResult& u : joined->units) {
        r.simulations_run += u.simulations_run;
    }
    // Per level: two directions, three pairings, two units, every history.
    r.simulations_run += static_cast<int>(joined->levels.size()) * 12 *
                         static_cast<int>(bank.sets().size());
    r.joined = std::move(joined);
    return r;
}

}  // namespace freestand::assess
