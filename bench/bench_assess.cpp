// Speed of one case's assessment on the machine's cores and with the history and run caches
// (docs/methods.md s.12): the shipped glove box (cases/glovebox-single.toml, every level, the
// material search) assessed through api::assess_report as `freestand assess` does it:
//  1. without the cache on 1 and 2 threads (the speed-up);
//  2. with cold caches (every set generated, every run simulated, all stored) and warm ones
//     (every set and run read), on every core;
//  3. the history sets alone on 1 thread: generation per set, and reading them back.
// Each figure is the least of `repeats` runs (default 3); the rendered result.json of every run
// is compared with the first, byte for byte. Wall times on a shared virtual machine drift:
// read the ratios of one quiet run.
// Usage: bench_assess [REPEATS] [CASE]  (another case, e.g. the glove box with more histories).
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>

#include "api/assess.hpp"
#include "assess/case.hpp"
#include "assess/histories.hpp"
#include "core/content_store.hpp"
#include "core/parallel.hpp"
#include "timing.hpp"

using namespace freestand;
namespace fs = std::filesystem;

namespace {

using bench::Clock;
using bench::seconds_since;
using bench::source_dir;

struct Timing {
    double best_s = 1e300;
    bool same_bytes = true;
};

// Least wall time of `repeats` runs of f, which returns the run's result.json.
Timing time_runs(int repeats, const std::string& reference, const std::function<std::string()>& f,
                 const std::function<void()>& before_each = {}) {
    Timing t;
    for (int r = 0; r < repeats; ++r) {
        if (before_each) before_each();
        const auto t0 = Clock::now();
        const std::string json = f();
        t.best_s = std::min(t.best_s, seconds_since(t0));
        t.same_bytes = t.same_bytes && json == reference;
    }
    return t;
}

}  // namespace

int main(int argc, char** argv) {
    const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
    const fs::path case_file =
        argc > 2 ? fs::path(argv[2]) : source_dir() / "cases" / "glovebox-single.toml";
    const fs::path cache_dir =
        fs::temp_directory_path() / ("freestand-bench-cache-" + std::to_string(::getpid()));
    const core::ContentStore cache(cache_dir);
    const core::ContentStore runs(cache_dir / "runs");
    const auto run = [&](assess::RunSettings s) {
        api::AssessRequest request;
        request.case_file = case_file;
        request.commit = "bench";
        request.run = s;
        return api::assess_report(request).rendered.json;
    };
    const std::string reference = run(assess::RunSettings(1));
    std::printf("%s: assess, least of %d runs, %d cores\n", case_file.string().c_str(), repeats,
                core::thread_count(0));
    std::printf("   %-34s %9s %9s %s\n", "run", "wall s", "ratio", "result.json");
    const Timing one = time_runs(repeats, reference, [&] { return run(assess::RunSettings(1)); });
    const Timing two = time_runs(repeats, reference, [&] { return run(assess::RunSettings(2)); });
    const auto row = [&](const char* name, const Timing& t, double base) {
        std::printf("   %-34s %9.3f %8.2fx %s\n", name, t.best_s, base / t.best_s,
                    t.same_bytes ? "same bytes" : "DIFFERS");
    };
    row("no cache, 1 thread", one, one.best_s);
    row("no cache, 2 threads", two, one.best_s);
    assess::RunSettings cached;
    cached.cache = &cache;
    cached.run_cache = &runs;
    const Timing cold = time_runs(repeats, reference, [&] { return run(cached); }, [&] {
        cache.clear();
        runs.clear();
    });
    const Timing warm = time_runs(repeats, reference, [&] { return run(cached); });
    row("cold cache, every core", cold, cold.best_s);
    row("warm cache, every core", warm, cold.best_s);
    std::printf("   warm / cold = %.2f\n", warm.best_s / cold.best_s);

    // The sets alone, on one thread.
    const assess::Case c = assess::read_case(case_file);
    assess::RunSettings gen(1);
    gen.cache = &cache;
    double generate_s = 1e300, read_s = 1e300;
    std::size_t sets = 0;
    for (int r = 0; r < repeats; ++r) {
        cache.clear();
        auto t0 = Clock::now();
        assess::HistoryBank cold_bank(c, gen);
        sets = cold_bank.sets().size();
        generate_s = std::min(generate_s, seconds_since(t0));
        t0 = Clock::now();
        assess::HistoryBank warm_bank(c, gen);
        warm_bank.sets();
        read_s = std::min(read_s, seconds_since(t0));
    }
    std::printf("\nhistory sets on 1 thread (%zu sets of 3 components, 20 s at 5 ms, with the "
                "high-pass and PGV measures):\n", sets);
    std::printf("   generated and stored: %.3f s per set (%.3f s per component)\n",
                generate_s / static_cast<double>(sets), generate_s / static_cast<double>(3 * sets));
    std::printf("   read from the cache:  %.4f s per set\n", read_s / static_cast<double>(sets));
    cache.clear();
    runs.clear();
    fs::remove_all(cache_dir);
    return one.same_bytes && two.same_bytes && cold.same_bytes && warm.same_bytes ? 0 : 1;
}
