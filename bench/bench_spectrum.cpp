/// Benchmark: response spectrum of the 90 s Chi-Chi TCU122-N record (18,000 steps) at 301
/// log-spaced frequencies 0.1-100 Hz and dampings 0.05 and 0.10. Prints wall time (median of
/// several runs) and the largest relative PSA error against a reference with sub-steps <= T/200,
/// with the T/20 rule (the default) and without sub-stepping.
///   usage: bench_spectrum [RECORD.AT2] [runs]
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

#include "support/paths.hpp"
#include "core/readers.hpp"
#include "spectra/response.hpp"
#include "spectra/spectrum.hpp"

using namespace freestand;

namespace {

struct Timing {
    double median_ms = 0.0;      ///< wall clock
    double median_cpu_ms = 0.0;  ///< process CPU time: robust when other jobs share the cores
    spectra::ResponseSpectra result;
};

Timing time_runs(const core::Record& rec, const std::vector<double>& dampings,
                 const std::vector<double>& f, int steps_per_period, int runs) {
    Timing t;
    std::vector<double> ms, cpu_ms;
    for (int r = 0; r < runs; ++r) {
        const auto start = std::chrono::steady_clock::now();
        const std::clock_t cpu_start = std::clock();
        t.result =
            spectra::response_spectra(rec, dampings, f, spectra::ResponseOptions{steps_per_period});
        const std::clock_t cpu_stop = std::clock();
        const auto stop = std::chrono::steady_clock::now();
        ms.push_back(std::chrono::duration<double, std::milli>(stop - start).count());
        cpu_ms.push_back(1000.0 * static_cast<double>(cpu_stop - cpu_start) / CLOCKS_PER_SEC);
    }
    std::sort(ms.begin(), ms.end());
    std::sort(cpu_ms.begin(), cpu_ms.end());
    t.median_ms = ms[ms.size() / 2];
    t.median_cpu_ms = cpu_ms[cpu_ms.size() / 2];
    return t;
}

double max_rel_error(const spectra::ResponseSpectra& a, const spectra::ResponseSpectra& ref,
                     double* at_hz) {
    double worst = 0.0;
    for (std::size_t d = 0; d < a.dampings.size(); ++d) {
        for (std::size_t i = 0; i < a.frequency_hz.size(); ++i) {
            const double e = std::abs(a.psa_g[d][i] / ref.psa_g[d][i] - 1.0);
            if (e > worst) {
                worst = e;
                *at_hz = a.frequency_hz[i];
            }
        }
    }
    return worst;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string path =
        argc > 1 ? argv[1] : std::string(freestand::test::data_dir()) + "/RSN1546_CHICHI_TCU122-N.AT2";
    const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 9;
    const core::Record rec = core::read_at2(path);
    const std::vector<double> f = spectra::log_frequencies(0.1, 100.0, 100);
    const std::vector<double> dampings{0.05, 0.10};
    const double oscillator_steps =
        static_cast<double>(rec.size() - 1) * static_cast<double>(f.size() * dampings.size());

    fmt::print("record {}: {} samples, dt {} s; {} frequencies 0.1-100 Hz x {} dampings\n",
               rec.name, rec.size(), rec.dt_s, f.size(), dampings.size());
    const Timing ref = time_runs(rec, dampings, f, 200, 1);
    fmt::print("reference: sub-steps <= T/200, {:.1f} ms\n\n", ref.median_ms);
    fmt::print("{:<22} {:>10} {:>10} {:>14} {:>14} {:>8}\n", "sub-stepping", "wall ms", "cpu ms",
               "cpu ns/osc-smp", "max rel error", "at Hz");
    for (const auto& [label, m] : {std::pair<const char*, int>{"T/20 (default)", 20},
                                   std::pair<const char*, int>{"none (1 per sample)", 0},
                                   std::pair<const char*, int>{"T/10", 10}}) {
        const Timing t = time_runs(rec, dampings, f, m, runs);
        double at_hz = 0.0;
        const double err = max_rel_error(t.result, ref.result, &at_hz);
        fmt::print("{:<22} {:>10.2f} {:>10.2f} {:>14.2f} {:>14.3e} {:>8.2f}\n", label, t.median_ms,
                   t.median_cpu_ms, t.median_cpu_ms * 1e6 / oscillator_steps, err, at_hz);
    }
    // The matching loops' entry points, one damping (5%), same record and frequencies.
    fmt::print("\n{:<22} {:>10} {:>10}\n", "one damping (5%)", "wall ms", "cpu ms");
    for (const auto& [label, fn] :
         {std::pair<const char*, std::function<void()>>{
              "psa_g", [&] { (void)spectra::psa_g(rec, 0.05, f); }},
          std::pair<const char*, std::function<void()>>{
              "peak_responses", [&] { (void)spectra::peak_responses(rec, 0.05, f); }}}) {
        std::vector<double> ms, cpu_ms;
        for (int r = 0; r < runs; ++r) {
            const auto start = std::chrono::steady_clock::now();
            const std::clock_t cpu_start = std::clock();
            fn();
            const std::clock_t cpu_stop = std::clock();
            ms.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count());
            cpu_ms.push_back(1000.0 * static_cast<double>(cpu_stop - cpu_start) / CLOCKS_PER_SEC);
        }
        std::sort(ms.begin(), ms.end());
        std::sort(cpu_ms.begin(), cpu_ms.end());
        fmt::print("{:<22} {:>10.2f} {:>10.2f}\n", label, ms[ms.size() / 2],
                   cpu_ms[cpu_ms.size() / 2]);
    }
    return 0;
}
