// Fuzz target: one shard file as `freestand merge` reads it (api/merge.hpp): the file's text
// parsed (header line, then JSON lines), joined as a run of one shard, then its records merged as
// the header's kind says: fragility samples checked against the run's meta and aggregated, or a
// batch's components into the batch's files. Only freestand's own errors may escape.
#include <cstdint>
#include <string>

#include "api/merge.hpp"
#include "batch/shard.hpp"
#include "core/errors.hpp"
#include "fragility/shard_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        std::vector<freestand::fragility::ShardFile> files{
            freestand::fragility::parse_shard(text, "fuzz.jsonl")};
        const auto set = freestand::fragility::join_shards(std::move(files));
        if (set.kind == "fragility") freestand::api::merge_fragility(set);
        if (set.kind == "batch")
            freestand::batch::batch_files(
                freestand::batch::merge_shards(set.run, set.records, set.run_at, set.record_at));
    } catch (const freestand::Error&) {
    }
    return 0;
}
