#include "dynamics/pair.hpp"

#include <algorithm>
#include <cmath>

#include "core/contract.hpp"
#include "core/errors.hpp"
#include <fmt/format.h>

namespace freestand::dynamics {

namespace {

std::vector<double> interpolated(const std::vector<double>& a, std::size_t refine) {
    if (a.size() < 2) return a;
    std::vector<double> out;
    out.reserve((a.size() - 1) * refine + 1);
    const double k = static_cast<double>(refine);
    for (std::size_t i = 0; i + 1 < a.size(); ++i) {
        for (std::size_t j = 0; j < refine; ++j) {
            const double w = static_cast<double>(j) / k;
            out.push_back(a[i] + w * (a[i + 1] - a[i]));
        }
    }
    out.push_back(a.back());
    return out;
}

// The unit's state at sample i; past its series' end, its last state (it stopped at rest).
const Sample& at(const std::vector<Sample>& series, std::size_t i) {
    return series[std::min(i, series.size() - 1)];
}

}  // namespace

double displacement_at_height_m(const Sample& s, double cg_height_m, double height_m) {
    if (s.mode == Mode::flight) return s.slide_m + (height_m - cg_height_m) * s.rotation_rad;
    return s.slide_m + height_m * s.rotation_rad;
}

Excitation refined(const Excitation& excitation, std::size_t refine) {
    if (refine == 0) throw InputError({"", 0, "refine"}, "must be a whole number >= 1; got 0");
    if (refine == 1) return excitation;
    Excitation e = excitation;
    e.dt_s = excitation.dt_s / static_cast<double>(refine);
    e.horizontal_mps2 = interpolated(excitation.horizontal_mps2, refine);
    e.vertical_mps2 = interpolated(excitation.vertical_mps2, refine);
    return e;
}

PairResult simulate_pair(const std::array<BlockModel, 2>& units, const Excitation& excitation,
                         const PairOptions& pair, const Options& options) {
    if (!std::isfinite(pair.tunnel_height_m) || pair.tunnel_height_m < 0.0)
        throw InputError({"", 0, "tunnel_height_m"},
                         fmt::format("must be >= 0 m; got {}", pair.tunnel_height_m));
    const Excitation ex = refined(excitation, pair.refine);
    Options opt = options;
    opt.record_series = true;
    std::array<SimulationResult, 2> runs{simulate(units[0], ex, opt), simulate(units[1], ex, opt)};
    PairResult r;
    for (std::size_t k = 0; k < 2; ++k) {
        r.units[k] = runs[k].summary;
        FREESTAND_EXPECT(!runs[k].series.empty(), "a run records its first sample");
    }
    r.overturned = r.units[0].overturned || r.units[1].overturned;
    const std::size_t n = std::max(runs[0].series.size(), runs[1].series.size());
    const double h = pair.tunnel_height_m;
    double rel = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const Sample& a = at(runs[0].series, i);
        const Sample& b = at(runs[1].series, i);
        rel = displacement_at_height_m(a, units[0].block.h_m, h) -
              displacement_at_height_m(b, units[1].block.h_m, h);
        if (std::abs(rel) > r.relative_max_m) {
            r.relative_max_m = std::abs(rel);
            r.relative_max_time_s = std::max(a.time_s, b.time_s);
        }
    }
    r.relative_residual_m = std::abs(rel);
    r.samples = n;
    return r;
}

}  // namespace freestand::dynamics
