#pragma once
// Flexible-body rows of bench_dynamics (docs/methods.md s.10): each bench block
// carrying a 7.5 Hz mode (damping 0.02, cantilever defaults) on the first 20 s of El Centro #12
// (140), plus the rock block at 0.2 g (below g tan(alpha) = 0.5 g: only the flexible body
// uplifts). Time: best thread CPU time over interleaved rounds (timing.hpp), against the planar
// rigid event-driven run of the same block and record (the aim is at most 10x). Error:
// relative, against the model's own reference (event-driven at rel_tol 1e-12), of the peak
// slip, rotation and modal displacement, each shown; the event-driven runs at rel_tol 1e-9 (the
// default) and 1e-6, central difference at 1e-4 and 1e-5 s.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "core/record.hpp"
#include "dynamics/flexible.hpp"
#include "timing.hpp"

namespace freestand::bench {

struct FlexCase {
    const char* name;
    double half_width_m, pga_g, mu;
};

struct FlexConfig {
    const char* label;
    dynamics::Options o;
    int reps;
    double best_s = 1e9;
    dynamics::FlexibleSummary s{};
};

inline double flex_rel(double a, double b) { return b > 0.0 ? std::abs(a - b) / b : 0.0; }

inline void flexible_rows(const core::Record& rec) {
    const FlexCase cases[] = {{"slide", 0.15, 0.5, 0.15},
                              {"rock", 0.3, 0.9, 0.6},
                              {"slide-rock", 0.3, 0.9, 0.525},
                              {"rock 0.2g", 0.3, 0.2, 0.6}};
    std::printf("\nflexible body, 7.5 Hz mode: event-driven (rest exact, else Dormand-Prince 5(4)) "
                "and central difference\n%-11s %-14s %10s %10s %10s %10s %9s %7s %9s\n",
                "case", "integrator", "cpu_s", "err_slide", "err_rot", "err_modal", "steps",
                "reject", "/planar");
    double peak = 0.0;
    for (double a : rec.accel_mps2) peak = std::max(peak, std::abs(a));
    for (const FlexCase& c : cases) {
        const auto rigid =
            dynamics::make_block_model(block::Block::uniform(c.half_width_m, 0.6, 38.0), c.mu);
        const auto e = dynamics::excitation_from_record(rec, c.pga_g * freestand::units::g_mps2 / peak);
        dynamics::FlexibleMode mode;
        mode.frequency_hz = 7.5;
        const dynamics::FlexibleModel fm = dynamics::make_flexible_model(rigid, mode);
        dynamics::Options o;
        o.record_series = false;
        auto tight = o;
        tight.rel_tol = 1e-12;
        tight.abs_tol = 1e-14;
        const dynamics::FlexibleSummary ref = dynamics::simulate_flexible(fm, e, tight).summary;
        auto with_tol = [&](double tol) {
            auto ot = o;
            ot.rel_tol = tol;
            ot.abs_tol = tol * 1e-2;
            return ot;
        };
        auto cd = [&](double dt_s) {
            auto oc = o;
            oc.integrator = dynamics::Integrator::central_difference;
            oc.cd_dt_s = dt_s;
            return oc;
        };
        std::vector<FlexConfig> configs = {{"event 1e-9", with_tol(1e-9), 3},
                                           {"event 1e-6", with_tol(1e-6), 3},
                                           {"cd 1e-4", cd(1e-4), 1},
                                           {"cd 1e-5", cd(1e-5), 1}};
        double planar_s = 1e9;
        for (int round = 0; round < 5; ++round) {
            for (int r = 0; r < 10; ++r) {
                const double t0 = thread_cpu_s();
                (void)dynamics::simulate(rigid, e, o);
                planar_s = std::min(planar_s, thread_cpu_s() - t0);
            }
            for (FlexConfig& k : configs) {
                // Central difference at 1e-5 s takes seconds: two rounds of it suffice.
                if (k.o.integrator == dynamics::Integrator::central_difference &&
                    k.o.cd_dt_s < 5e-5 && round >= 2)
                    continue;
                for (int r = 0; r < k.reps; ++r) {
                    const double t0 = thread_cpu_s();
                    k.s = dynamics::simulate_flexible(fm, e, k.o).summary;
                    k.best_s = std::min(k.best_s, thread_cpu_s() - t0);
                }
            }
        }
        std::printf("%-11s %-14s %10.3e %10s %10s %10s %9s %7s %9s   (peaks: slide %.4g m, "
                    "rotation %.4g rad, modal %.4g m; %s)\n",
                    c.name, "planar", planar_s, "-", "-", "-", "-", "-", "1.0x",
                    ref.base.slide_max_m, ref.base.rock_max_rad, ref.modal_max_m,
                    ref.base.overturned ? "overturns" : "stands");
        for (const FlexConfig& k : configs)
            std::printf("%-11s %-14s %10.3e %10.2e %10.2e %10.2e %9zu %7zu %8.1fx%s\n", c.name,
                        k.label, k.best_s, flex_rel(k.s.base.slide_max_m, ref.base.slide_max_m),
                        flex_rel(k.s.base.rock_max_rad, ref.base.rock_max_rad),
                        flex_rel(k.s.modal_max_m, ref.modal_max_m), k.s.base.steps,
                        k.s.rejected_steps, k.best_s / planar_s,
                        k.s.base.overturned != ref.base.overturned ? "  overturn differs" : "");
    }
}

}  // namespace freestand::bench
