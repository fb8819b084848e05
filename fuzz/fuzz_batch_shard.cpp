// Fuzz target: a batch shard as `freestand merge` reads it: the first line the run's header
// ({"stamp", "names"}), every further line a component's record, merged into the batch's files.
// Only freestand's own errors may escape the reader (a line that is not JSON is the shard file
// reader's business, cli/shards.cpp, and is skipped here).
#include <cstdint>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "batch/run.hpp"
#include "batch/shard.hpp"
#include "core/errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    std::vector<nlohmann::json> lines;
    std::vector<freestand::SourceLocation> at;
    int number = 0;
    for (std::string line; std::getline(in, line);) {
        ++number;
        try {
            lines.push_back(nlohmann::json::parse(line));
        } catch (const nlohmann::json::exception&) {
            return 0;
        }
        at.push_back(freestand::SourceLocation{"fuzz.jsonl", number, ""});
    }
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
