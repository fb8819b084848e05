#include "assess/plot_data.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "assess/verdict.hpp"
#include "core/units.hpp"
#include "sliding/initiation.hpp"
#include "spectra/response.hpp"

namespace freestand::assess {

namespace {

constexpr std::size_t max_history_points = 1500;

InitiationDiagram initiation_diagram(const AssessmentResult& r, Direction d) {
    InitiationDiagram out;
    out.direction = d;
    const block::Block blk = r.input.component.block(d);
    const block::Edge e = blk.critical_edge();
    out.tan_alpha = blk.tan_alpha(e);
    double a_max = 0.0;
    for (const LevelResult& l : r.levels) {
        if (l.direction != d) continue;
        out.points.push_back({l.initiation.a_ratio, l.initiation.mu_s});
        a_max = std::max(a_max, l.initiation.a_ratio);
    }
    const double x_max = std::max({1.25 * a_max, 2.0 * out.tan_alpha, 0.2});
    constexpr int samples = 120;
    for (int i = 0; i <= samples; ++i) {
        const double a = out.tan_alpha + (x_max - out.tan_alpha) * i / static_cast<double>(samples);
        out.a_g.push_back(a);
        out.mu_crit.push_back(sliding::mu_crit(blk, e, a));
    }
    return out;
}

// The simulated level with the most severe verdict (the last such, i.e. the highest PGA, on ties).
std::optional<std::size_t> governing_simulated(const std::vector<LevelResult>& levels) {
    std::optional<std::size_t> gov;
    for (std::size_t i = 0; i < levels.size(); ++i) {
        if (!levels[i].simulation) continue;
        if (!gov || !more_severe(levels[*gov].verdict, levels[i].verdict)) gov = i;
    }
    return gov;
}

Series history_series(std::string label, const std::vector<double>& t,
                      const std::vector<double>& y) {
    return decimate(Series{std::move(label), t, y}, max_history_points);
}

void add_histories(PlotData& p, const AssessmentResult& r, const LevelResult& lvl,
                   HistoryBank& bank) {
    const HistorySet& set =
        bank.made().at(static_cast<std::size_t>(lvl.simulation->governing_history));
    const dynamics::Excitation ex = excitation(set, lvl.direction, lvl.pga_g);
    std::vector<double> t(ex.horizontal_mps2.size());
    for (std::size_t i = 0; i < t.size(); ++i) t[i] = ex.dt_s * static_cast<double>(i);
    auto in_g = [g_mps2 = r.input.site.g_mps2](std::vector<double> a) {
        for (double& v : a) v /= g_mps2;
        return a;
    };
    p.ground_motion.push_back(history_series("horizontal", t, in_g(ex.horizontal_mps2)));
    p.ground_motion.push_back(history_series("vertical", t, in_g(ex.vertical_mps2)));
    dynamics::Options opt;
    opt.g_mps2 = r.input.site.g_mps2;
    // Slip at the sliding bound, rotation at the rocking bound: the runs the verdict read.
    const Simulation& lsim = *lvl.simulation;
    const dynamics::SimulationResult slide_run = dynamics::simulate(
        block_model(r.input.component, lsim.sliding_bound, lvl.direction), ex, opt);
    const dynamics::SimulationResult rock_run =
        lsim.bounds_differ
            ? dynamics::simulate(
                  block_model(r.input.component, lsim.rocking_bound, lvl.direction), ex, opt)
            : slide_run;
    std::vector<double> ts, slip;
    for (const dynamics::Sample& s : slide_run.series) {
        ts.push_back(s.time_s);
        slip.push_back(s.slide_m);
    }
    std::vector<double> tr, rot;
    const double alpha = lvl.rocking.alpha_rad;
    for (const dynamics::Sample& s : rock_run.series) {
        tr.push_back(s.time_s);
        rot.push_back(s.rotation_rad / alpha);
    }
    p.slip.push_back(history_series(fmt::format("slip, mu_s {:.3f}", lsim.sliding_bound.mu_s), ts, slip));
    p.rotation.push_back(history_series(
        fmt::format("theta / alpha, mu_s {:.3f}, r {:.3f}", lsim.rocking_bound.mu_s,
                    lsim.rocking_bound.restitution),
        tr, rot));
    p.governing = fmt::format("PGA {:.3f} g, direction {}, history {} of {}", lvl.pga_g,
                              to_string(lvl.direction), lvl.simulation->governing_history + 1,
                              lvl.simulation->histories);
}

}  // namespace

Series decimate(const Series& s, std::size_t max_points) {
    if (s.x.size() <= max_points || max_points < 4) return s;
    Series out{s.label, {}, {}};
    const std::size_t buckets = max_points / 2;
    const std::size_t n = s.x.size();
    for (std::size_t b = 0; b < buckets; ++b) {
        const std::size_t lo = b * n / buckets;
        const std::size_t hi = std::max(lo + 1, (b + 1) * n / buckets);
        const auto [mn, mx] = std::minmax_element(s.y.begin() + static_cast<std::ptrdiff_t>(lo),
                                                  s.y.begin() + static_cast<std::ptrdiff_t>(hi));
        const std::size_t i = static_cast<std::size_t>(mn - s.y.begin());
        const std::size_t j = static_cast<std::size_t>(mx - s.y.begin());
        for (std::size_t k : {std::min(i, j), std::max(i, j)}) {
            out.x.push_back(s.x[k]);
            out.y.push_back(s.y[k]);
        }
    }
    return out;
}

PlotData plot_data(const AssessmentResult& r, const std::vector<LevelDemand>& demands,
                   HistoryBank& bank) {
    PlotData p;
    for (Direction d : {Direction::x, Direction::y})
        p.initiation.push_back(initiation_diagram(r, d));
    const std::optional<std::size_t> gov = governing_simulated(r.levels);
    const LevelResult& shown = r.levels.at(gov ? *gov : r.own.level);
    // The demand of the shown level (levels are built from the same PGA list, so equal exactly).
    const auto demand = std::find_if(demands.begin(), demands.end(),
                                     [&](const LevelDemand& d) { return d.pga_g == shown.pga_g; });
    const spectra::Spectrum& target = demand->h5_of(shown.direction);
    const bool own_y = demand->h5_y && shown.direction == Direction::y;
    p.spectra.push_back(Series{fmt::format("{} target{}, 5%, PGA {:.3f} g",
                                           r.input.site.targets ? "File" : "RG 1.60",
                                           own_y ? " of direction y" : "", shown.pga_g),
                               target.frequency_hz, target.psa_g});
    if (bank.generated()) {
        const std::vector<double> f = spectra::log_frequencies(0.1, 50.0, 40);
        const auto& sets = bank.sets();
        for (std::size_t k = 0; k < sets.size(); ++k) {
            const core::Record& h = shown.direction == Direction::x ? sets[k].h1 : sets[k].h2;
            p.spectra.push_back(
                Series{fmt::format("history {}", k + 1), f,
                       spectra::psa_g(HistoryBank::scaled(h, shown.pga_g), 0.05, f,
                                      r.input.site.g_mps2)});
        }
    }
    if (gov) add_histories(p, r, r.levels[*gov], bank);
    return p;
}

}  // namespace freestand::assess
