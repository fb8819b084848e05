// Fuzz target: a fragility shard as `freestand merge` reads it: the first line the run's meta,
// every further line a sample, each checked against the run, then aggregated. Only freestand's
// own errors may escape the readers (a line that is not JSON is the shard file reader's
// business, fragility/shard_file.cpp, fuzzed by fuzz_shard_file, and is skipped here).
#include <cstdint>

#include "core/errors.hpp"
#include "json_lines.hpp"
#include "fragility/fragility.hpp"
#include "fragility/serialize.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    auto [lines, at] = freestand::fuzz::json_lines(data, size, "fuzz.jsonl");
    if (lines.empty()) return 0;
    try {
        const auto meta = freestand::fragility::meta_from_json(lines[0], {"fuzz.jsonl", 1, "meta"});
        lines.erase(lines.begin());
        at.erase(at.begin());
        auto samples = freestand::fragility::samples_from_json(lines, at, meta);
        freestand::fragility::aggregate(meta, std::move(samples));
    } catch (const freestand::Error&) {
    }
    return 0;
}
