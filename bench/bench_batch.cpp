// Speed of `freestand batch` (README "Batch"): the shipped cases (cases/*.toml, a folder list) run
// as one batch on 1 and 2 worker threads; wall time per case from each component's own time
// on 1 thread, and the batch's wall time and speed-up on 2. The outputs of both runs are
// compared byte for byte (the batch's promise), and the folder is rendered but not written,
// so the time is the assessments' and the summary's.
// Wall times on a shared virtual machine drift by up to 2x between minutes; read the ratios.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "api/batch.hpp"
#include "batch/list.hpp"
#include "batch/run.hpp"
#include "timing.hpp"

using namespace freestand;
namespace fs = std::filesystem;

namespace {

using bench::Clock;
using bench::seconds_since;
using bench::source_dir;

api::BatchRequest request(unsigned threads) {
    api::BatchRequest r;
    r.commit = "bench";
    r.run = assess::RunSettings(static_cast<int>(threads));
    return r;
}

struct Timed {
    batch::BatchRun run;
    std::vector<core::OutputFile> files;
    double seconds = 0.0;
};

Timed timed_batch(const batch::BatchList& list, unsigned threads) {
    const auto t0 = Clock::now();
    Timed t;
    t.run = api::run_batch(list, request(threads));
    t.files = batch::batch_files(t.run);
    t.seconds = seconds_since(t0);
    return t;
}

// Each component alone on one worker: its own time, which the batch's per-case mean averages.
void per_case(const batch::BatchList& list) {
    std::printf("   %-22s %8s  %s\n", "case", "1 thr s", "verdict");
    for (std::size_t i = 0; i < list.entries.size(); ++i) {
        const auto t0 = Clock::now();
        const std::vector<batch::BatchRow> rows = api::run_rows(list, {i}, request(1));
        const report::SummaryRow& r = rows.at(0).row;
        std::printf("   %-22s %8.2f  %s\n", r.name.c_str(), seconds_since(t0),
                    r.outcome ? r.outcome->verdict_kind.c_str() : r.error.c_str());
    }
}

}  // namespace

int main() {
    const batch::BatchList list = batch::read_batch_list(source_dir() / "cases");
    const std::size_t n = list.entries.size();
    const double cases = static_cast<double>(n);
    std::printf("batch of the shipped cases (%zu in cases/)\n", n);
    std::printf("1. each case alone, 1 thread\n");
    per_case(list);
    std::printf("2. the whole batch\n");
    const Timed one = timed_batch(list, 1);
    const Timed two = timed_batch(list, 2);
    std::printf("   1 thread : %7.2f s, %6.2f s per case\n", one.seconds, one.seconds / cases);
    std::printf("   2 threads: %7.2f s, %6.2f s per case, speed-up %.2f\n", two.seconds,
                two.seconds / cases, one.seconds / two.seconds);
    bool same = one.files.size() == two.files.size();
    for (std::size_t i = 0; same && i < one.files.size(); ++i)
        same = one.files[i].name == two.files[i].name &&
               one.files[i].contents == two.files[i].contents;
    std::size_t bytes = 0;
    for (const core::OutputFile& f : one.files) bytes += f.contents.size();
    std::printf("   %zu files, %.1f MB; 1 and 2 threads byte-identical: %s; failed rows: %zu\n",
                one.files.size(), static_cast<double>(bytes) / 1e6, same ? "yes" : "NO",
                one.run.failed());
    return same && one.run.all_assessed() ? 0 : 1;
}
