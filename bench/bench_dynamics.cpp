// Speed against error of the block simulator (issue 5): slide, rock and slide-rock cases on
// the first 20 s of El Centro #12 (140), event-driven at its default tolerance (and at 1e-10 and
// 1e-6) and central difference at dt = 1e-3, 1e-4, 1e-5 s; then speed alone on the record
// decimated to 0.01 s. Error: against the tightest
// event-driven solution (rel_tol 1e-13), on the peak slip (slide), peak rotation (rock) or both
// (slide-rock). Time: best of several runs of the thread's CPU time (the machine this runs on is
// shared, so wall time mostly measures the other processes).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>

#include "core/readers.hpp"
#include "dynamics/simulate.hpp"

using namespace freestand;

namespace {

struct Case {
    const char* name;
    double half_width_m, pga_g, mu;
};

double cpu_now() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double timed(const dynamics::BlockModel& m, const dynamics::Excitation& e,
             const dynamics::Options& o, dynamics::Summary& out, int reps) {
    double best = 1e9;
    for (int i = 0; i < reps; ++i) {
        const double t0 = cpu_now();
        out = dynamics::simulate(m, e, o).summary;
        best = std::min(best, cpu_now() - t0);
    }
    return best;
}

double error(const dynamics::Summary& s, const dynamics::Summary& ref) {
    const double es = ref.slide_max_m > 0 ? std::abs(s.slide_max_m - ref.slide_max_m) / ref.slide_max_m : 0.0;
    const double er = ref.rock_max_rad > 0 ? std::abs(s.rock_max_rad - ref.rock_max_rad) / ref.rock_max_rad : 0.0;
    return std::max(es, er);
}

}  // namespace

int main() {
    auto rec = core::read_at2(FREESTAND_TEST_DATA "/RSN175_IMPVALL.H_H-E12140.AT2");
    rec.accel_mps2.resize(static_cast<std::size_t>(20.0 / rec.dt_s) + 1);
    double peak = 0.0;
    for (double a : rec.accel_mps2) peak = std::max(peak, std::abs(a));
    // Slide: tan(alpha) = 0.25 > mu. Rock and slide-rock: tan(alpha) = 0.5; mu = 0.525 lies
    // between tan(alpha) and mu_crit at the peaks, so the block slide-rocks for ~0.3 s.
    const Case cases[] = {{"slide", 0.15, 0.5, 0.15}, {"rock", 0.3, 0.9, 0.6},
                          {"slide-rock", 0.3, 0.9, 0.525}};
    std::printf("%-11s %-15s %12s %12s %10s %8s\n", "case", "integrator", "cpu_s", "rel_error",
                "steps", "speedup");
    for (const Case& c : cases) {
        const auto m = dynamics::make_block_model(block::Block::uniform(c.half_width_m, 0.6, 38.0), c.mu);
        const auto e = dynamics::excitation_from_record(rec, c.pga_g * 9.81 / peak);
        dynamics::Options o;
        o.record_series = false;
        dynamics::Summary ref, s;
        auto ot = o;
        ot.rel_tol = 1e-13;
        ot.abs_tol = 1e-15;
        timed(m, e, ot, ref, 1);
        const double t_ed = timed(m, e, o, s, 50);
        std::printf("%-11s %-15s %12.3e %12.3e %10zu %8s   (peak slide %.4g m, rotation %.4g rad)\n",
                    c.name, "event", t_ed, error(s, ref), s.steps, "", ref.slide_max_m,
                    ref.rock_max_rad);
        // Other tolerances; the speedup column is their time over the default's.
        for (double tol : {1e-10, 1e-6}) {
            auto ol = o;
            ol.rel_tol = tol;
            ol.abs_tol = tol * 1e-2;
            const double t = timed(m, e, ol, s, 50);
            std::printf("%-11s event tol %-6.0e %12.3e %12.3e %10zu %7.2fx\n", c.name, tol, t,
                        error(s, ref), s.steps, t / t_ed);
        }
        for (double dt : {1e-3, 1e-4, 1e-5}) {
            auto oc = o;
            oc.integrator = dynamics::Integrator::central_difference;
            oc.cd_dt_s = dt;
            const double t = timed(m, e, oc, s, dt < 5e-5 ? 3 : 10);
            std::printf("%-11s cd dt=%-9.0e %12.3e %12.3e %10zu %7.1fx\n", c.name, dt, t,
                        error(s, ref), s.steps, t / t_ed);
        }
    }
    // The same cases on the record decimated to 0.01 s: half the segments for the event-driven
    // integrator (its contact steps end at every sample), the same 200,000 steps for central
    // difference at 1e-4 s.
    core::Record coarse = rec;
    coarse.dt_s = 2.0 * rec.dt_s;
    coarse.accel_mps2.clear();
    for (std::size_t i = 0; i < rec.accel_mps2.size(); i += 2) coarse.accel_mps2.push_back(rec.accel_mps2[i]);
    double peak_coarse = 0.0;
    for (double a : coarse.accel_mps2) peak_coarse = std::max(peak_coarse, std::abs(a));
    std::printf("\nrecord decimated to dt = %.3f s\n%-11s %12s %12s %8s\n", coarse.dt_s, "case", "event_s",
                "cd_1e-4_s", "speedup");
    for (const Case& c : cases) {
        const auto m = dynamics::make_block_model(block::Block::uniform(c.half_width_m, 0.6, 38.0), c.mu);
        const auto e = dynamics::excitation_from_record(coarse, c.pga_g * 9.81 / peak_coarse);
        dynamics::Options o;
        o.record_series = false;
        dynamics::Summary s;
        const double t_ed = timed(m, e, o, s, 50);
        auto oc = o;
        oc.integrator = dynamics::Integrator::central_difference;
        const double t_cd = timed(m, e, oc, s, 10);
        std::printf("%-11s %12.3e %12.3e %7.1fx\n", c.name, t_ed, t_cd, t_cd / t_ed);
    }
    return 0;
}
