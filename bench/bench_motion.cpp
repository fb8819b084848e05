// Speed and accuracy of spectrum-compatible generation (issue 3): wall time and iterations to pass
// SRP 3.7.1 for one 20 s component at dt = 0.005 s and for the three-component set, from the
// synthetic method and from seed records, with the achieved min / max 5% ratios.
// Run: build/<dir>/bench/bench_motion [repeats]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/readers.hpp"
#include "motion/motion.hpp"

using namespace freestand;
using Clock = std::chrono::steady_clock;

namespace {

void row(const char* what, const motion::GeneratedSet& s, double wall_s, int repeats) {
    for (const auto& c : s.components)
        std::printf("%-34s %-3s %-6s it %3d att %d  min %.3f max %.3f  psd %.2f  %.3f s\n", what,
                    c.record.component.c_str(), c.acceptance.passed ? "pass" : "FAIL", c.iterations,
                    c.attempts, c.acceptance.min_ratio, c.acceptance.max_ratio,
                    c.acceptance.psd_min_ratio.value_or(-1.0), c.wall_s);
    std::printf(
        "%-34s set %s, |rho| max %.3f, %.3f s per set (mean of %d)\n\n", what,
        s.passed ? "pass" : "FAIL",
        [&] {
            double m = 0.0;
            for (const auto& c : s.correlations) m = std::max(m, std::abs(c.rho));
            return m;
        }(),
        wall_s / repeats, repeats);
}

template <class F>
void timed(const char* what, int repeats, F make) {
    motion::GeneratedSet s;
    const auto t0 = Clock::now();
    for (int k = 0; k < repeats; ++k) s = make();
    row(what, s, std::chrono::duration<double>(Clock::now() - t0).count(), repeats);
}

}  // namespace

int main(int argc, char** argv) {
    const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
    const motion::TargetSet ts = motion::rg160_targets(0.3);
    const std::string data = FREESTAND_TEST_DATA;
    std::printf(
        "RG 1.60, PGA 0.3 g, 20 s at dt 0.005 s (synthetic); seeds at their own length\n\n");
    timed("synthetic h1", repeats, [&] {
        motion::GenerateOptions o;
        o.components = {"h1"};
        return motion::generate_set(ts, o);
    });
    timed("synthetic h1,h2,v", repeats,
          [&] { return motion::generate_set(ts, motion::GenerateOptions{}); });
    timed("seed E12140 (39 s) h1", repeats, [&] {
        motion::GenerateOptions o;
        o.components = {"h1"};
        o.seed_records = {core::read_at2(data + "/RSN175_IMPVALL.H_H-E12140.AT2")};
        return motion::generate_set(ts, o);
    });
    timed("seeds E12140,E12230,TCU122 h1,h2,v", repeats, [&] {
        motion::GenerateOptions o;
        o.seed_records = {core::read_at2(data + "/RSN175_IMPVALL.H_H-E12140.AT2"),
                          core::read_at2(data + "/RSN175_IMPVALL.H_H-E12230.AT2"),
                          core::read_at2(data + "/RSN1546_CHICHI_TCU122-N.AT2")};
        return motion::generate_set(ts, o);
    });
    // Cost of the acceptance report alone (spectra at 271 points x 2 dampings, PSD, measures).
    const auto rec = motion::generate_set(ts,
                                          [] {
                                              motion::GenerateOptions o;
                                              o.components = {"h1"};
                                              return o;
                                          }())
                         .components[0]
                         .record;
    const auto t0 = Clock::now();
    for (int k = 0; k < 10; ++k) (void)motion::check_acceptance(rec, ts.horizontal);
    std::printf("acceptance report alone: %.4f s\n",
                std::chrono::duration<double>(Clock::now() - t0).count() / 10);
    return 0;
}
