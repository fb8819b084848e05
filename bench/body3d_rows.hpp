#pragma once
// The 3D body's rows of bench_dynamics (docs/methods.md s.11): speed against error of the
// Moreau-Jean steps with the rigid body's smooth phases taken whole (the default), and of the
// steps alone, next to the planar event-driven engine, on the rock case (b = 0.3 m, h = 0.6 m,
// mu = 0.6) under the first 20 s of El Centro #12.
//   - x alone (140 scaled to 0.9 g): the planar engine is the exact reference; the 3D body's
//     peak tilt error and time at dt = 1e-3, 2.5e-4, 1e-4 and 2.5e-5 s, and its time over the
//     planar run's (the aim is at most 30x); then by steps alone at 1e-3 and 2.5e-4 s, with
//     landings split ("steps") and every step whole ("whole").
//   - both components (140 as x at 0.9 g, 230 as y on the same scale), on a block 0.3 x 0.4 m:
//     the error of the peak tilt and slide against the steps alone at dt = 1e-5 s (the
//     scheme's converged reference, sharing no code with the phases), with and without the
//     phases, and the peak tilt beside the planar runs of each component.
//   - x alone with a mode (8 Hz, 0.4 M at 0.9 m; no phase is taken whole): the peak tilt and
//     |q| against the planar flexible body's event-driven run, and the time over it.
//   - the speed goal's case (goal_rows): the whole record, both components, at assess's step,
//     with and without the phases.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "support/paths.hpp"
#include "core/readers.hpp"
#include "dynamics/biaxial.hpp"
#include "dynamics/body3d.hpp"
#include "dynamics/flexible.hpp"
#include "dynamics/simulate.hpp"
#include "timing.hpp"

namespace freestand::bench {

inline dynamics::Body3dSummary run_3d(const dynamics::Body3dModel& m,
                                      const dynamics::BiaxialExcitation& e,
                                      dynamics::Body3dOptions o, double& best_s, int reps) {
    o.record_series = false;
    dynamics::Body3dSummary s;
    for (int i = 0; i < reps; ++i) {
        const double t0 = thread_cpu_s();
        s = dynamics::simulate_body3d(m, e, o).summary;
        best_s = std::min(best_s, thread_cpu_s() - t0);
    }
    return s;
}

inline dynamics::Body3dSummary run_3d(const dynamics::Body3dModel& m,
                                      const dynamics::BiaxialExcitation& e, double dt_s,
                                      double& best_s, int reps) {
    dynamics::Body3dOptions o;
    o.dt_s = dt_s;
    return run_3d(m, e, o, best_s, reps);
}

inline dynamics::Summary run_planar(const dynamics::BlockModel& m, const dynamics::Excitation& e,
                                    double& best_s, int reps) {
    dynamics::Options o;
    o.record_series = false;
    dynamics::Summary s;
    for (int i = 0; i < reps; ++i) {
        const double t0 = thread_cpu_s();
        s = dynamics::simulate(m, e, o).summary;
        best_s = std::min(best_s, thread_cpu_s() - t0);
    }
    return s;
}

// The speed goal's case: the whole record (39 s), both components at 0.9 g, on the block
// 0.3 x 0.4 m, at the step assess uses (1e-3 s) with the default sweeps (to 1e-12 g dt, at
// most 500) and with assess's (to 1e-8 g dt, at most 100): its time over the planar event run
// of x alone and over the planar runs of both components (a planar assessment of the record).
inline void goal_rows() {
    auto x140 = core::read_at2(freestand::test::data_dir() + "/RSN175_IMPVALL.H_H-E12140.AT2");
    auto y230 = core::read_at2(freestand::test::data_dir() + "/RSN175_IMPVALL.H_H-E12230.AT2");
    y230.accel_mps2.resize(x140.accel_mps2.size());
    double peak = 0.0;
    for (double a : x140.accel_mps2) peak = std::max(peak, std::abs(a));
    const double factor = 0.9 * 9.81 / peak;
    const auto x = dynamics::excitation_from_record(x140, factor);
    const auto y = dynamics::excitation_from_record(y230, factor);
    double t_px = 1e9, t_py = 1e9;
    const auto px = run_planar(dynamics::make_block_model(block::Block::uniform(0.3, 0.6, 100.0), 0.6),
                               x, t_px, 20);
    const auto py = run_planar(dynamics::make_block_model(block::Block::uniform(0.4, 0.6, 100.0), 0.6),
                               y, t_py, 20);
    std::printf("\n3D body, the speed goal's case: the whole record (%.1f s), both components\n"
                "%-26s %12s %10s %10s %10s %12s\n", x.duration_s(), "run", "cpu_s", "steps",
                "unconv", "x_planar", "x+y_planar");
    std::printf("%-26s %12.3e %10zu %10s %10s %12s   (peak rotation %.4g rad)\n", "planar event x",
                t_px, px.steps, "-", "1", "-", px.rock_max_rad);
    std::printf("%-26s %12.3e %10zu %10s %10s %12s   (peak rotation %.4g rad)\n", "planar event y",
                t_py, py.steps, "-", "-", "-", py.rock_max_rad);
    const auto body = dynamics::make_body3d_model(dynamics::box_body(0.3, 0.4, 0.6, 100.0), 0.6);
    const auto exy = dynamics::biaxial_excitation(x, y.horizontal_mps2);
    struct Setting {
        const char* label;
        double tol;
        std::size_t sweeps;
        bool phases;
    };
    for (const Setting& k : {Setting{"3D 1e-3, sweeps 1e-12/500", 1e-12, 500, true},
                             Setting{"3D 1e-3, sweeps 1e-8/100", 1e-8, 100, true},
                             Setting{"  the same, steps alone", 1e-8, 100, false}}) {
        dynamics::Body3dOptions o;
        o.dt_s = 1e-3;
        o.solver_tol = k.tol;
        o.max_sweeps = k.sweeps;
        o.phases = k.phases;
        double t = 1e9;
        const auto s = run_3d(body, exy, o, t, 3);
        std::printf("%-26s %12.3e %10zu %10zu %9.0fx %11.0fx   (peak tilt %.4g rad)\n", k.label, t,
                    s.steps, s.unconverged_steps, t / t_px, t / (t_px + t_py), s.tilt_max_rad);
    }
}

inline void body3d_rows(const core::Record& x140) {
    auto y230 = core::read_at2(freestand::test::data_dir() + "/RSN175_IMPVALL.H_H-E12230.AT2");
    y230.accel_mps2.resize(x140.accel_mps2.size());
    double peak = 0.0;
    for (double a : x140.accel_mps2) peak = std::max(peak, std::abs(a));
    const double factor = 0.9 * 9.81 / peak;
    const auto x = dynamics::excitation_from_record(x140, factor);
    const auto y = dynamics::excitation_from_record(y230, factor);

    std::printf("\n3D body (Moreau-Jean) against the planar event-driven engine: rock case, x alone\n"
                "%-22s %12s %12s %10s %10s\n", "run", "cpu_s", "tilt_error", "steps", "x_planar");
    const auto planar_model = dynamics::make_block_model(block::Block::uniform(0.3, 0.6, 100.0), 0.6);
    double t_planar = 1e9;
    const auto ref = run_planar(planar_model, x, t_planar, 20);
    std::printf("%-22s %12.3e %12s %10zu %10s   (peak rotation %.4g rad)\n", "planar event",
                t_planar, "-", ref.steps, "1", ref.rock_max_rad);
    const auto body_x = dynamics::make_body3d_model(dynamics::box_body(0.3, 0.45, 0.6, 100.0), 0.6);
    const auto ex = dynamics::biaxial_excitation(x, std::vector<double>(x.horizontal_mps2.size(), 0.0));
    for (double dt : {1e-3, 2.5e-4, 1e-4, 2.5e-5}) {
        double t = 1e9;
        const auto s = run_3d(body_x, ex, dt, t, dt < 1e-4 ? 1 : 3);
        std::printf("3D dt=%-16.3g %12.3e %12.3e %10zu %9.0fx\n", dt, t,
                    std::abs(s.tilt_max_rad - ref.rock_max_rad) / ref.rock_max_rad, s.steps,
                    t / t_planar);
    }
    // Every phase by steps (the phases' gain), and every step whole besides (the split's).
    for (const std::size_t substeps : {std::size_t{16}, std::size_t{1}})
        for (double dt : {1e-3, 2.5e-4}) {
            dynamics::Body3dOptions o;
            o.dt_s = dt;
            o.phases = false;
            o.arrival_substeps = substeps;
            double t = 1e9;
            const auto s = run_3d(body_x, ex, o, t, 3);
            std::printf("3D dt=%-9.3g %-5s %12.3e %12.3e %10zu %9.0fx\n", dt,
                        substeps == 1 ? "whole" : "steps", t,
                        std::abs(s.tilt_max_rad - ref.rock_max_rad) / ref.rock_max_rad, s.steps,
                        t / t_planar);
        }

    // The reference takes every phase by steps, so that it does not share the phases' code.
    std::printf("\n3D body, both components (140 x, 230 y): error against steps alone at 1e-5 s\n"
                "%-22s %12s %12s %12s %10s\n", "run", "cpu_s", "tilt_error", "slide_error", "x_planar");
    const auto body = dynamics::make_body3d_model(dynamics::box_body(0.3, 0.4, 0.6, 100.0), 0.6);
    const auto exy = dynamics::biaxial_excitation(x, y.horizontal_mps2);
    const auto with = [](double dt, bool phases) {
        dynamics::Body3dOptions o;
        o.dt_s = dt;
        o.phases = phases;
        return o;
    };
    double t_ref = 1e9;
    const auto conv = run_3d(body, exy, with(1e-5, false), t_ref, 1);
    for (const bool phases : {true, false})
        for (double dt : {1e-3, 2.5e-4, 1e-4}) {
            double t = 1e9;
            const auto s = run_3d(body, exy, with(dt, phases), t, 3);
            std::printf("3D dt=%-9.3g %-6s %12.3e %12.3e %12.3e %9.0fx\n", dt,
                        phases ? "" : "steps", t,
                        std::abs(s.tilt_max_rad - conv.tilt_max_rad) / conv.tilt_max_rad,
                        std::abs(s.slide_max_m - conv.slide_max_m) /
                            std::max(conv.slide_max_m, 1e-12),
                        t / t_planar);
        }
    double t_px = 1e9, t_py = 1e9;
    const auto px = run_planar(dynamics::make_block_model(block::Block::uniform(0.3, 0.6, 100.0), 0.6),
                               x, t_px, 5);
    const auto py = run_planar(dynamics::make_block_model(block::Block::uniform(0.4, 0.6, 100.0), 0.6),
                               y, t_py, 5);
    std::printf("peak tilt: 3D %.4g rad (%.3g x critical, twist %.3g rad); planar x %.4g rad, "
                "planar y %.4g rad\n",
                conv.tilt_max_rad, conv.tilt_max_over_critical, conv.twist_max_rad, px.rock_max_rad,
                py.rock_max_rad);

    // The body carrying a mode (8 Hz, 0.4 M at 0.9 m) along x, against the planar flexible
    // body's event-driven run of the same record (its converged reference).
    std::printf("\n3D body with a mode (8 Hz, 0.4 M at 0.9 m), x alone, against the planar flexible "
                "body\n%-22s %12s %12s %12s %10s\n", "run", "cpu_s", "tilt_error", "modal_error",
                "x_planar");
    const auto flex_planar = dynamics::make_flexible_model(planar_model, {8.0, 0.02, 0.4, 0.9});
    double t_flex = 1e9;
    dynamics::FlexibleSummary flex_ref;
    for (int i = 0; i < 5; ++i) {
        dynamics::Options o;
        o.record_series = false;
        const double t0 = thread_cpu_s();
        flex_ref = dynamics::simulate_flexible(flex_planar, x, o).summary;
        t_flex = std::min(t_flex, thread_cpu_s() - t0);
    }
    std::printf("%-22s %12.3e %12s %12s %10s   (peak rotation %.4g rad, |q| %.4g m)\n",
                "planar flexible", t_flex, "-", "-", "1", flex_ref.base.rock_max_rad,
                flex_ref.modal_max_m);
    const auto body_mode = dynamics::with_mode(body_x, {8.0, 8.0, 0.02, 0.4, 0.9});
    {
        // The planar flexible body's other integrator at a fine step: on this record the peaks
        // of both engines move by several percent as the step refines (docs/methods.md s.11).
        dynamics::Options o;
        o.record_series = false;
        o.integrator = dynamics::Integrator::central_difference;
        o.cd_dt_s = 2.5e-6;
        const auto c = dynamics::simulate_flexible(flex_planar, x, o).summary;
        std::printf("%-22s %12s %12.3e %12.3e %10s\n", "planar flexible cd 2.5e-6", "-",
                    std::abs(c.base.rock_max_rad - flex_ref.base.rock_max_rad) /
                        flex_ref.base.rock_max_rad,
                    std::abs(c.modal_max_m - flex_ref.modal_max_m) / flex_ref.modal_max_m, "-");
    }
    for (double dt : {1e-3, 2.5e-4, 1e-4, 2.5e-5, 1e-5}) {
        double t = 1e9;
        const auto s = run_3d(body_mode, ex, dt, t, dt < 1e-4 ? 1 : 3);
        std::printf("3D dt=%-16.3g %12.3e %12.3e %12.3e %9.0fx\n", dt, t,
                    std::abs(s.tilt_max_rad - flex_ref.base.rock_max_rad) / flex_ref.base.rock_max_rad,
                    std::abs(s.modal_max_m - flex_ref.modal_max_m) / flex_ref.modal_max_m,
                    t / t_flex);
    }
    goal_rows();
}

}  // namespace freestand::bench
