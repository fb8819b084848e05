// Fuzz target: a batch shard as `freestand merge` reads it: the first line the run's header
// ({"stamp", "names"}), every further line a component's record, merged into the batch's files.
// Only freestand's own errors may escape the reader (a line that is not JSON is the shard file
// reader's business, fragility/shard_file.cpp, fuzzed by fuzz_shard_file, and is skipped here).
#include <cstdint>

#include "batch/run.hpp"
#include "batch/shard.hpp"
#include "core/errors.hpp"
#include "json_lines.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    auto [lines, at] = freestand::fuzz::json_lines(data, size, "fuzz.jsonl");
    if (lines.empty()) return 0;
    try {
        const nlohmann::json run = lines[0];
        lines.erase(lines.begin());
        at.erase(at.begin());
        const auto merged = freestand::batch::merge_shards(run, lines, {"fuzz.jsonl", 1, ""}, at);
        freestand::batch::batch_files(merged);
    } catch (const freestand::Error&) {
    }
    return 0;
}
