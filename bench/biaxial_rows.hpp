#pragma once
// Biaxial sliding rows of bench_dynamics (docs/methods.md s.10): time and error of the biaxial
// slide against its own converged reference (event-driven at rel_tol 1e-12) and against central
// difference at 1e-4 and 1e-5 s, with the ratio to the planar event-driven run of the x component
// alone (the aim is at most 10x). Two inputs: the first 20 s of El Centro #12, 140 as x and 230 as
// y, scaled so that x peaks at 0.5 g, on a block with mu = 0.2 (tan(alpha) = 0.5: it only slides);
// and the seven histories of cases/glovebox-single.toml at its PGA levels, at the case's lower
// friction bound, as assess runs them.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "support/paths.hpp"
#include "assess/case.hpp"
#include "assess/histories.hpp"
#include "assess/level.hpp"
#include "core/readers.hpp"
#include "dynamics/biaxial.hpp"
#include "timing.hpp"

namespace freestand::bench {

struct BiaxialConfig {
    const char* label;
    std::function<double(std::size_t&)> run;  // returns the peak slip, sets the steps
    int reps;
    double best_s = 1e9, peak_m = 0.0;
    std::size_t steps = 0;
};

inline void time_biaxial(std::vector<BiaxialConfig>& configs, int rounds) {
    for (int round = 0; round < rounds; ++round)
        for (BiaxialConfig& c : configs)
            for (int i = 0; i < c.reps; ++i) {
                const double t0 = thread_cpu_s();
                c.peak_m = c.run(c.steps);
                c.best_s = std::min(c.best_s, thread_cpu_s() - t0);
            }
}

inline dynamics::Options biaxial_with(double rel_tol, dynamics::Integrator integ, double cd_dt_s) {
    dynamics::Options o = dynamics::biaxial_options();
    o.record_series = false;
    if (rel_tol > 0.0) {
        o.rel_tol = rel_tol;
        o.abs_tol = rel_tol * 1e-2;
    }
    o.integrator = integ;
    o.cd_dt_s = cd_dt_s;
    return o;
}

inline std::function<double(std::size_t&)> biaxial_run(const dynamics::BiaxialModel& m,
                                                       const dynamics::BiaxialExcitation& e,
                                                       dynamics::Options o) {
    return [&m, &e, o](std::size_t& steps) {
        const auto s = dynamics::simulate_biaxial(m, e, o).summary;
        steps = s.steps;
        return s.slide_max_m;
    };
}

inline std::function<double(std::size_t&)> planar_run(const dynamics::BlockModel& m,
                                                      const dynamics::Excitation& e) {
    return [&m, &e](std::size_t& steps) {
        dynamics::Options o;
        o.record_series = false;
        const auto s = dynamics::simulate(m, e, o).summary;
        steps = s.steps;
        return s.slide_max_m;
    };
}

// The El Centro pair: one row per configuration.
inline void biaxial_record_rows(const core::Record& x140) {
    auto y = core::read_at2(freestand::test::data_dir() + "/RSN175_IMPVALL.H_H-E12230.AT2");
    y.accel_mps2.resize(x140.accel_mps2.size());
    double peak = 0.0;
    for (double a : x140.accel_mps2) peak = std::max(peak, std::abs(a));
    const double scale = 0.5 * freestand::units::g_mps2 / peak;
    const auto xy = dynamics::biaxial_excitation_from_records(x140, y, scale);
    const auto planar_e = dynamics::excitation_from_record(x140, scale);
    const auto bi = dynamics::make_biaxial_model(0.2);
    const auto planar = dynamics::make_block_model(block::Block::uniform(0.3, 0.6, 38.0), 0.2);
    using dynamics::Integrator;
    const double ref =
        dynamics::simulate_biaxial(bi, xy, biaxial_with(1e-12, Integrator::event, 1e-4))
            .summary.slide_max_m;
    std::vector<BiaxialConfig> configs = {
        {"planar event (x)", planar_run(planar, planar_e), 10},
        {"event (default)", biaxial_run(bi, xy, biaxial_with(0.0, Integrator::event, 1e-4)), 10},
        {"event tol 1e-9", biaxial_run(bi, xy, biaxial_with(1e-9, Integrator::event, 1e-4)), 5},
        {"cd dt=1e-4", biaxial_run(bi, xy, biaxial_with(0.0, Integrator::central_difference, 1e-4)), 1},
    };
    time_biaxial(configs, 5);
    std::vector<BiaxialConfig> fine = {
        {"cd dt=1e-5", biaxial_run(bi, xy, biaxial_with(0.0, Integrator::central_difference, 1e-5)), 1}};
    time_biaxial(fine, 2);
    configs.push_back(fine[0]);
    std::printf("\nbiaxial slide, El Centro 140 (x) + 230 (y) at 0.5 g, mu 0.2: reference "
                "(rel_tol 1e-12) peak |u| %.6g m\n%-11s %-16s %12s %12s %10s %8s\n", ref, "case",
                "integrator", "cpu_s", "rel_error", "steps", "planar");
    for (const BiaxialConfig& c : configs) {
        const bool is_planar = &c == &configs[0];
        char err[32] = "-";
        if (!is_planar) std::snprintf(err, sizeof err, "%.3e", std::abs(c.peak_m - ref) / ref);
        std::printf("%-11s %-16s %12.3e %12s %10zu %7.1fx\n", "biaxial", c.label, c.best_s, err,
                    c.steps, c.best_s / configs[0].best_s);
    }
    std::printf("(planar row: its own peak %.6g m, not compared with the biaxial reference)\n",
                configs[0].peak_m);
}

// The shipped glove box's histories at each PGA level: total time of the seven planar (x) and
// biaxial runs at the case's lower friction bound, and the biaxial error against rel_tol 1e-12.
inline void biaxial_case_rows() {
    const assess::Case c = assess::read_case(source_dir() / "cases" / "glovebox-single.toml");
    assess::HistoryBank bank(c, assess::RunSettings(1));
    const auto& sets = bank.sets();
    const assess::DirectionBounds bounds = assess::direction_bounds(c.component, assess::Direction::x);
    const auto planar = assess::block_model(c.component, bounds.sliding, assess::Direction::x);
    const auto bi = dynamics::make_biaxial_model(bounds.sliding.mu_s, bounds.sliding.mu_k);
    std::printf("\nbiaxial slide, cases/glovebox-single.toml: %zu histories per level, mu_s %.3g\n"
                "%-8s %12s %12s %8s %12s %12s %12s %12s\n", sets.size(), bounds.sliding.mu_s,
                "pga_g", "planar_s", "biaxial_s", "ratio", "max_rel_err", "cd4_rel_err",
                "cd5_rel_err", "peak_|u|_m");
    for (double pga_g : c.site.pga_g) {
        std::vector<dynamics::Excitation> px;
        std::vector<dynamics::BiaxialExcitation> bx;
        for (const auto& set : sets) {
            px.push_back(assess::excitation(set, assess::Direction::x, pga_g));
            bx.push_back(dynamics::biaxial_excitation_from_records(set.h1, set.h2, pga_g, &set.v));
        }
        using dynamics::Integrator;
        auto all = [&](dynamics::Options o) {
            return [&, o](std::size_t& steps) {
                double peak = 0.0;
                steps = 0;
                for (const auto& e : bx) {
                    const auto s = dynamics::simulate_biaxial(bi, e, o).summary;
                    peak = std::max(peak, s.slide_max_m);
                    steps += s.steps;
                }
                return peak;
            };
        };
        std::vector<BiaxialConfig> configs = {
            {"planar", [&](std::size_t& steps) {
                 double peak = 0.0;
                 steps = 0;
                 for (const auto& e : px) {
                     std::size_t n = 0;
                     peak = std::max(peak, planar_run(planar, e)(n));
                     steps += n;
                 }
                 return peak;
             }, 3},
            {"biaxial", all(biaxial_with(0.0, Integrator::event, 1e-4)), 3}};
        time_biaxial(configs, 3);
        double err = 0.0, err4 = 0.0, err5 = 0.0, peak = 0.0;
        for (const auto& e : bx) {
            auto peak_of = [&](dynamics::Options o) {
                return dynamics::simulate_biaxial(bi, e, o).summary.slide_max_m;
            };
            const double ref = peak_of(biaxial_with(1e-12, Integrator::event, 1e-4));
            peak = std::max(peak, ref);
            if (ref <= 0.0) continue;
            auto rel = [&](double v) { return std::abs(v - ref) / ref; };
            err = std::max(err, rel(peak_of(biaxial_with(0.0, Integrator::event, 1e-4))));
            err4 = std::max(err4, rel(peak_of(biaxial_with(0.0, Integrator::central_difference, 1e-4))));
            err5 = std::max(err5, rel(peak_of(biaxial_with(0.0, Integrator::central_difference, 1e-5))));
        }
        std::printf("%-8.2f %12.3e %12.3e %7.1fx %12.3e %12.3e %12.3e %12.4g\n", pga_g,
                    configs[0].best_s, configs[1].best_s, configs[1].best_s / configs[0].best_s,
                    err, err4, err5, peak);
    }
}

inline void biaxial_rows(const core::Record& x140) {
    biaxial_record_rows(x140);
    biaxial_case_rows();
}

}  // namespace freestand::bench
