// Speed against error of the block simulator (issues 5 and 15): slide, rock and slide-rock cases on
// the first 20 s of El Centro #12 (140), event-driven at its default tolerance (and at 1e-10 and
// 1e-6) and central difference at dt = 1e-3, 1e-4, 1e-5 s; the floor of the rock case (its Taylor
// steps chained alone); then the same cases on the record decimated to 0.01 and 0.02 s. Error:
// against the tightest event-driven solution (rel_tol 1e-13), on the peak slip (slide), peak
// rotation (rock) or both (slide-rock). Time: best per-run CPU time of the thread over rounds
// that run every configuration in turn (the machine is a shared virtual one whose speed drifts
// by up to 2x between minutes; interleaving keeps the ratios steadier than the times). Then, two
// units joined by a tunnel (dynamics::simulate_pair): time against the two planar runs and the
// peak relative displacement's error at 1, 4 and 16 samples per input step against 64, and of
// the pair of central-difference runs at 1e-4 and 1e-5 s.
// The flexible body (docs/methods.md s.10; flexible_rows.hpp): event-driven and central difference
// against the model's own converged reference and the planar run. Last, biaxial sliding (s.10;
// biaxial_rows.hpp): El Centro 140 as x and 230 as y, and the histories of
// cases/glovebox-single.toml, each against the planar run of its x component.
// Then the 3D body (docs/methods.md s.11; body3d_rows.hpp) beside the planar engine.
// `bench_dynamics flexible` runs the flexible rows alone, `bench_dynamics 3d` the 3D rows.
#include <algorithm>
#include <array>
#include <string>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <ctime>
#include <string_view>
#include <vector>

#include "support/paths.hpp"
#include "core/readers.hpp"
#include "dynamics/flexible.hpp"
#include "dynamics/integrators.hpp"
#include "dynamics/pair.hpp"
#include "dynamics/simulate.hpp"
#include "dynamics/taylor.hpp"
#include "biaxial_rows.hpp"
#include "body3d_rows.hpp"
#include "flexible_rows.hpp"
#include "timing.hpp"

using namespace freestand;

namespace {

struct Case {
    const char* name;
    double half_width_m, pga_g, mu;
};

using bench::thread_cpu_s;

// Best CPU time per run of each configuration. Rounds run every configuration in turn, so a
// slow phase of the (shared, virtual) machine falls on all of them alike and the ratios hold
// better than the times.
struct Config {
    const char* label;
    dynamics::Options o;
    int reps;                        // runs per round
    std::function<void()> run = {};  // timed instead of simulate() if set
    double best_s = 1e9;
    dynamics::Summary s{};
};

void time_interleaved(const dynamics::BlockModel& m, const dynamics::Excitation& e,
                      std::vector<Config>& configs, int rounds) {
    for (int r = 0; r < rounds; ++r)
        for (Config& c : configs)
            for (int i = 0; i < c.reps; ++i) {
                const double t0 = thread_cpu_s();
                if (c.run)
                    c.run();
                else
                    c.s = dynamics::simulate(m, e, c.o).summary;
                c.best_s = std::min(c.best_s, thread_cpu_s() - t0);
            }
}

// The least the rock case's steps can cost: n_steps Taylor steps of the integrator's kernel at
// its tolerance, chained (the state at one step's end starts the next, sin and cos carried by
// sin_cos_shift), on the record's segments from 2 s on, with no event search, no forces and no
// output; an impact is a bare switch of pivot with the block's restitution. Each step needs the
// previous one's end, so the chain bounds the case's time from below.
volatile double chain_sink = 0.0;  // keeps the chain from being optimised away
void rock_chain(const dynamics::detail::Geometry& g, const dynamics::detail::BaseMotion& bm,
                double dt_s, std::size_t n_steps, const dynamics::Options& o) {
    using namespace dynamics::detail;
    const std::size_t k0 = static_cast<std::size_t>(2.0 / dt_s);
    ContactStart x0;
    x0.th = 0.01;
    double phi0 = g.alpha[1] - x0.th;
    x0.sn = std::sin(phi0);
    x0.c = std::cos(phi0);
    ContactSeries S;
    RockDegree degree;
    for (std::size_t k = k0; k < k0 + n_steps; ++k) {
        bm.segment(k, x0.ax0, x0.ax1, x0.G0, x0.G1);
        taylor_contact_step(g, x0, dt_s, o.rel_tol, o.abs_tol, S, degree);
        sin_cos_shift(x0.sn, x0.c, phi0, S.th_end - x0.th, x0.sn, x0.c);
        x0.th = S.th_end;
        x0.om = S.om_end;
        const auto i = static_cast<std::size_t>(Geometry::index(-x0.s));
        if (x0.th < 0.0) {
            x0.s = -x0.s;
            x0.th = -x0.th;
            x0.om = -g.r_onto[i] * x0.om;
            x0.sn = std::sin(g.alpha[i] - x0.th);
            x0.c = std::cos(g.alpha[i] - x0.th);
        }
        phi0 = g.alpha[static_cast<std::size_t>(Geometry::index(x0.s))] - x0.th;
    }
    chain_sink = x0.th;
}

double error(const dynamics::Summary& s, const dynamics::Summary& ref) {
    const double es = ref.slide_max_m > 0 ? std::abs(s.slide_max_m - ref.slide_max_m) / ref.slide_max_m : 0.0;
    const double er = ref.rock_max_rad > 0 ? std::abs(s.rock_max_rad - ref.rock_max_rad) / ref.rock_max_rad : 0.0;
    return std::max(es, er);
}

// A case on a record: the block, the excitation scaled to the case's PGA, the options every
// configuration starts from, and the reference answer (event-driven at rel_tol 1e-13).
struct SetUp {
    dynamics::BlockModel m;
    dynamics::Excitation e;
    dynamics::Options o;
    dynamics::Summary ref;
};

SetUp set_up(const Case& c, const core::Record& rec) {
    double peak = 0.0;
    for (double a : rec.accel_mps2) peak = std::max(peak, std::abs(a));
    SetUp u{dynamics::make_block_model(block::Block::uniform(c.half_width_m, 0.6, 38.0), c.mu),
            dynamics::excitation_from_record(rec, c.pga_g * freestand::units::g_mps2 / peak), {}, {}};
    u.o.record_series = false;
    auto tight = u.o;
    tight.rel_tol = 1e-13;
    tight.abs_tol = 1e-15;
    u.ref = dynamics::simulate(u.m, u.e, tight).summary;
    return u;
}

dynamics::Options central_difference(dynamics::Options o, double dt_s) {
    o.integrator = dynamics::Integrator::central_difference;
    o.cd_dt_s = dt_s;
    return o;
}

// The pair options at one sample per input step (central difference records its own steps).
dynamics::PairOptions p1(dynamics::PairOptions p) {
    p.refine = 1;
    return p;
}

std::string fmt_refine(std::size_t refine) {
    return "pair, " + std::to_string(refine) + "/input step";
}

// Two units joined by a tunnel (docs/methods.md s.10), on the record scaled to pga_g. The pair
// is two planar runs with their series recorded; its peak relative displacement is taken over
// the samples, so the rows refine the sampling (the same piecewise-linear input, resampled) and
// compare with 64 samples per input step; and the pair of central-difference runs at 1e-4 and
// 1e-5 s against the same reference. Time: against the two planar runs without series.
void pair_rows(const core::Record& rec, const char* label, double pga_g,
               const std::array<dynamics::BlockModel, 2>& units, double tunnel_height_m) {
    double peak = 0.0;
    for (double a : rec.accel_mps2) peak = std::max(peak, std::abs(a));
    const auto e = dynamics::excitation_from_record(rec, pga_g * freestand::units::g_mps2 / peak);
    dynamics::Options o;
    o.record_series = false;
    dynamics::PairOptions p;
    p.tunnel_height_m = tunnel_height_m;
    p.refine = 64;
    const double ref = dynamics::simulate_pair(units, e, p, o).relative_max_m;
    std::vector<std::size_t> refines{1, 4, 16};
    std::vector<double> peaks(refines.size());
    std::vector<Config> configs = {{"planar runs", o, 10, [&] {
                                        dynamics::simulate(units[0], e, o);
                                        dynamics::simulate(units[1], e, o);
                                    }}};
    for (std::size_t k = 0; k < refines.size(); ++k) {
        configs.push_back({"pair", o, 5, [&, k] {
                               dynamics::PairOptions pk = p;
                               pk.refine = refines[k];
                               peaks[k] = dynamics::simulate_pair(units, e, pk, o).relative_max_m;
                           }});
    }
    const double cd_dts[] = {1e-4, 1e-5};
    double cd_peaks[2] = {0.0, 0.0};
    for (std::size_t k = 0; k < 2; ++k) {
        dynamics::Options ocd = o;
        ocd.integrator = dynamics::Integrator::central_difference;
        ocd.cd_dt_s = cd_dts[k];
        configs.push_back({"pair cd", ocd, 1, [&, k, ocd] {
                               cd_peaks[k] = dynamics::simulate_pair(units, e, p1(p), ocd).relative_max_m;
                           }});
    }
    time_interleaved(units[0], e, configs, 5);
    std::printf("\npair, %s, %.2g g, tunnel %.2g m: peak relative %.6g m at 64 samples per input "
                "step\n%-22s %12s %12s %8s\n",
                label, pga_g, tunnel_height_m, ref, "configuration", "cpu_s", "rel_error",
                "ratio");
    const double t1 = configs[0].best_s;
    std::printf("%-22s %12.3e %12s %8s\n", "two planar runs", t1, "-", "1.0x");
    for (std::size_t k = 0; k < refines.size(); ++k)
        std::printf("%-22s %12.3e %12.3e %7.1fx\n", fmt_refine(refines[k]).c_str(),
                    configs[k + 1].best_s, std::abs(peaks[k] - ref) / ref,
                    configs[k + 1].best_s / t1);
    for (std::size_t k = 0; k < 2; ++k) {
        const Config& c = configs[refines.size() + 1 + k];
        std::printf("pair, cd dt=%-10.0e %12.3e %12.3e %7.1fx\n", cd_dts[k], c.best_s,
                    std::abs(cd_peaks[k] - ref) / ref, c.best_s / t1);
    }
}

}  // namespace

// USGS SLAMMER's rigid-block comparison: the whole El Centro #12 (140) record (7,814 samples)
// times 3, mu 0.15 on a level floor, a block too squat to rock. SLAMMER (Java, fixed step) needs
// 0.024 ms at the record's 5 ms step with a 1.4% error, 0.35 ms for 0.1% and 1.8 ms for 0.01%
// against its converged residual 1.4801 cm (at standard gravity 9.80665; the thesis's 9.81,
// units::g_thesis_mps2, gives 1.4807 cm).
void slammer_row(const core::Record& whole) {
    dynamics::Excitation e = dynamics::excitation_from_record(whole, 3.0);
    const dynamics::BlockModel m =
        dynamics::make_block_model(block::Block::uniform(0.5, 0.6, 38.0), 0.15);
    dynamics::Options o;
    o.record_series = false;
    std::vector<Config> configs = {{"event", o, 20}};
    time_interleaved(m, e, configs, 15);
    const dynamics::Summary& s = configs[0].s;
    std::printf("\nSLAMMER's case (El Centro 140 x 3, %zu samples, mu 0.15, level floor): "
                "%.4f ms per run, residual %.6f cm, peak %.4f cm, %.0f runs per CPU second\n",
                whole.accel_mps2.size(), 1e3 * configs[0].best_s, 100.0 * s.slide_residual_m,
                100.0 * s.slide_max_m, 1.0 / configs[0].best_s);
}

int main(int argc, char** argv) {
    // An argument names one section to run alone: "flexible" (the flexible-body rows), "3d"
    // (the 3D body's rows), "slammer" (the sliding row against USGS SLAMMER).
    const std::string_view only = argc > 1 ? argv[1] : "";
    auto rec = core::read_at2(freestand::test::data_dir() + "/RSN175_IMPVALL.H_H-E12140.AT2");
    slammer_row(rec);
    if (only == "slammer") return 0;
    rec.accel_mps2.resize(static_cast<std::size_t>(20.0 / rec.dt_s) + 1);
    // Slide: tan(alpha) = 0.25 > mu. Rock and slide-rock: tan(alpha) = 0.5; mu = 0.525 lies
    // between tan(alpha) and mu_crit at the peaks, so the block slide-rocks for ~0.3 s.
    const Case cases[] = {{"slide", 0.15, 0.5, 0.15}, {"rock", 0.3, 0.9, 0.6},
                          {"slide-rock", 0.3, 0.9, 0.525}};
    if (only == "3d") {
        bench::body3d_rows(rec);
        return 0;
    }
    if (only == "flexible") {
        bench::flexible_rows(rec);
        return 0;
    }
    std::printf("%-11s %-15s %12s %12s %10s %8s\n", "case", "integrator", "cpu_s", "rel_error",
                "steps", "speedup");
    double floor_ratio = 0.0;
    for (const Case& c : cases) {
        const SetUp u = set_up(c, rec);
        const auto& o = u.o;
        std::vector<Config> configs = {{"event", o, 10}};
        for (double tol : {1e-10, 1e-6}) {
            auto ol = o;
            ol.rel_tol = tol;
            ol.abs_tol = tol * 1e-2;
            configs.push_back({tol == 1e-10 ? "event tol 1e-10" : "event tol 1e-6", ol, 10});
        }
        configs.push_back({"cd dt=1e-3", central_difference(o, 1e-3), 3});
        configs.push_back({"cd dt=1e-4", central_difference(o, 1e-4), 1});
        // The rock case's floor, timed in the same rounds: its Taylor steps chained alone.
        const auto g = dynamics::detail::make_geometry(u.m);
        const dynamics::detail::BaseMotion bm(u.e, o.g_mps2);
        const bool rock = std::string_view(c.name) == "rock";
        const std::size_t n_steps = rock ? dynamics::simulate(u.m, u.e, o).summary.steps : 0;
        if (rock)
            configs.push_back({"kernel chain", o, 10, [&] { rock_chain(g, bm, u.e.dt_s, n_steps, o); }});
        time_interleaved(u.m, u.e, configs, 15);
        std::vector<Config> fine = {{"cd dt=1e-5", central_difference(o, 1e-5), 1}};
        time_interleaved(u.m, u.e, fine, 3);
        configs.push_back(fine[0]);
        const double t_ed = configs[0].best_s;
        for (const Config& k : configs) {
            if (k.run) continue;
            std::printf("%-11s %-15s %12.3e %12.3e %10zu ", c.name, k.label, k.best_s,
                        error(k.s, u.ref), k.s.steps);
            if (&k == &configs[0])
                std::printf("%8s   (peak slide %.4g m, rotation %.4g rad)\n", "", u.ref.slide_max_m,
                            u.ref.rock_max_rad);
            else
                std::printf("%7.1fx\n", k.best_s / t_ed);
        }
        if (rock) {
            const double t_floor = configs[5].best_s;
            floor_ratio = configs[4].best_s / t_floor;
            std::printf("%-11s %-15s %12.3e %12s %10zu %7.2fx   (Taylor steps chained alone: the "
                        "floor)\n", c.name, "kernel chain", t_floor, "-", n_steps, t_floor / t_ed);
        }
    }
    std::printf("\nrock: central difference at 1e-4 s over the kernel chain alone: %.1fx\n",
                floor_ratio);
    bench::flexible_rows(rec);
    // The same cases on the record decimated to 0.01 and 0.02 s (every 2nd or 4th sample; the
    // content changes, as on a coarser recording): the event-driven integrator's contact steps end
    // at every sample, so it takes 2 or 4 times fewer, while central difference at 1e-4 s still
    // takes 200,000.
    for (std::size_t every : {2u, 4u}) {
        core::Record coarse = rec;
        coarse.dt_s = static_cast<double>(every) * rec.dt_s;
        coarse.accel_mps2.clear();
        for (std::size_t i = 0; i < rec.accel_mps2.size(); i += every)
            coarse.accel_mps2.push_back(rec.accel_mps2[i]);
        std::printf("\nrecord decimated to dt = %.3f s\n%-11s %12s %12s %12s %12s %8s\n", coarse.dt_s,
                    "case", "event_s", "event_error", "cd_1e-4_s", "cd_error", "speedup");
        for (const Case& c : cases) {
            const SetUp u = set_up(c, coarse);
            std::vector<Config> configs = {{"event", u.o, 10},
                                           {"cd dt=1e-4", central_difference(u.o, 1e-4), 1}};
            time_interleaved(u.m, u.e, configs, 15);
            const double t_ed = configs[0].best_s, t_cd = configs[1].best_s;
            std::printf("%-11s %12.3e %12.3e %12.3e %12.3e %7.1fx\n", c.name, t_ed,
                        error(configs[0].s, u.ref), t_cd, error(configs[1].s, u.ref), t_cd / t_ed);
        }
    }
    // A sliding and a rocking unit; two rocking units of different size (peaks mid-rocking).
    pair_rows(rec, "sliding (mu 0.15) + rocking unit", 0.9,
              {dynamics::make_block_model(block::Block::uniform(0.15, 0.6, 38.0), 0.15),
               dynamics::make_block_model(block::Block::uniform(0.3, 0.6, 38.0), 0.6)},
              1.0);
    pair_rows(rec, "two rocking units", 0.5,
              {dynamics::make_block_model(block::Block::uniform(0.4, 1.6, 400.0), 0.6),
               dynamics::make_block_model(block::Block::uniform(0.5, 1.5, 400.0), 0.6)},
              1.5);
    bench::biaxial_rows(rec);
    bench::body3d_rows(rec);
    return 0;
}
