#pragma once
// The fuzz input as the lines of a JSON Lines shard, each with its location: what
// fragility/shard_file.cpp hands the shard readers. An input with a line that is not JSON is the shard
// file reader's business, not the readers', and gives no lines.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/errors.hpp"

namespace freestand::fuzz {

struct JsonLines {
    std::vector<nlohmann::json> lines;
    std::vector<SourceLocation> at;
};

inline JsonLines json_lines(const std::uint8_t* data, std::size_t size, const std::string& file) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    JsonLines out;
    int number = 0;
    for (std::string line; std::getline(in, line);) {
        ++number;
        try {
            out.lines.push_back(nlohmann::json::parse(line));
        } catch (const nlohmann::json::exception&) {
            return {};
        }
        out.at.push_back(SourceLocation{file, number, ""});
    }
    return out;
}

}  // namespace freestand::fuzz
