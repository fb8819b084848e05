// Speed against error of biaxial sliding (issue 15): the first 20 s of El Centro #12, 140 as x
// and 230 as y, scaled so that x peaks at 0.5 g, on a block with mu = 0.2 (tan(alpha) = 0.5:
// it only slides). Event-driven (Dormand-Prince) at its default tolerance and at 1e-6, central
// difference at 1e-4 and 1e-5 s; error on the peak |u| against the event-driven answer at
// rel_tol 1e-12. Beside them the planar event-driven slide of the x component alone, which the
// issue asks the biaxial run to stay within 10x of. Time: best CPU time of the thread per run
// over rounds that run every configuration in turn (the machine is shared).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <vector>

#include "core/readers.hpp"
#include "dynamics/biaxial.hpp"
#include "timing.hpp"

using namespace freestand;

namespace {

using bench::thread_cpu_s;

struct Config {
    const char* label;
    std::function<double(std::size_t&)> run;  // returns the peak slip, sets the steps
    int reps;
    double best_s = 1e9, peak_m = 0.0;
    std::size_t steps = 0;
};

dynamics::Options with(double rel_tol, dynamics::Integrator integ, double cd_dt_s) {
    dynamics::Options o;
    o.record_series = false;
    o.rel_tol = rel_tol;
    o.abs_tol = rel_tol * 1e-2;
    o.integrator = integ;
    o.cd_dt_s = cd_dt_s;
    return o;
}

}  // namespace

int main() {
    auto x = core::read_at2(FREESTAND_TEST_DATA "/RSN175_IMPVALL.H_H-E12140.AT2");
    auto y = core::read_at2(FREESTAND_TEST_DATA "/RSN175_IMPVALL.H_H-E12230.AT2");
    const std::size_t n = static_cast<std::size_t>(20.0 / x.dt_s) + 1;
    x.accel_mps2.resize(n);
    y.accel_mps2.resize(n);
    double peak = 0.0;
    for (double a : x.accel_mps2) peak = std::max(peak, std::abs(a));
    const double scale = 0.5 * 9.81 / peak;
    const auto xy = dynamics::biaxial_excitation_from_records(x, y, scale);
    const auto planar_e = dynamics::excitation_from_record(x, scale);
    const auto bi = dynamics::make_biaxial_model(0.2);
    const auto planar = dynamics::make_block_model(block::Block::uniform(0.3, 0.6, 38.0), 0.2);
    using dynamics::Integrator;
    const double ref =
        dynamics::simulate_biaxial(bi, xy, with(1e-12, Integrator::event, 1e-4)).summary.slide_max_m;
    auto biaxial = [&](dynamics::Options o) {
        return [&, o](std::size_t& steps) {
            const auto s = dynamics::simulate_biaxial(bi, xy, o).summary;
            steps = s.steps;
            return s.slide_max_m;
        };
    };
    dynamics::Options po;
    po.record_series = false;
    std::vector<Config> configs = {
        {"planar event (x)", [&](std::size_t& steps) {
             const auto s = dynamics::simulate(planar, planar_e, po).summary;
             steps = s.steps;
             return s.slide_max_m;
         }, 10},
        {"biaxial event", biaxial(with(1e-9, Integrator::event, 1e-4)), 10},
        {"biaxial tol 1e-6", biaxial(with(1e-6, Integrator::event, 1e-4)), 10},
        {"biaxial cd 1e-4", biaxial(with(1e-9, Integrator::central_difference, 1e-4)), 1},
        {"biaxial cd 1e-5", biaxial(with(1e-9, Integrator::central_difference, 1e-5)), 1},
    };
    for (int round = 0; round < 5; ++round)
        for (Config& c : configs)
            for (int i = 0; i < c.reps; ++i) {
                const double t0 = thread_cpu_s();
                c.peak_m = c.run(c.steps);
                c.best_s = std::min(c.best_s, thread_cpu_s() - t0);
            }
    std::printf("biaxial reference (rel_tol 1e-12): peak |u| %.6g m\n", ref);
    std::printf("%-18s %12s %12s %10s %10s\n", "config", "cpu_s", "rel_error", "steps",
                "x planar");
    for (const Config& c : configs)
        std::printf("%-18s %12.3e %12.3e %10zu %9.1fx\n", c.label, c.best_s,
                    &c == &configs[0] ? 0.0 : std::abs(c.peak_m - ref) / ref, c.steps,
                    c.best_s / configs[0].best_s);
    std::printf("(planar row: its own peak %.6g m, not compared with the biaxial reference)\n",
                configs[0].peak_m);
    return 0;
}
