#pragma once
/// A shipped case cut down for a test: its own levels replaced, a fixed number of history sets
/// (no settling growth); and the trail lookup the level tests share.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "assess/case.hpp"
#include "assess/pipeline.hpp"
#include "assess/result.hpp"
#include "support/paths.hpp"

namespace freestand::test {

/// cases/<name> at the PGA levels pga_g, with `histories` sets per level and no more.
inline assess::Case shipped_case(const char* name, const std::vector<double>& pga_g,
                                 int histories) {
    assess::Case c =
        assess::read_case(std::filesystem::path(source_dir()) / "cases" / name);
    c.options.histories_per_level = histories;
    c.options.max_histories_per_level = histories;
    return assess::with_pga_levels(c, pga_g);
}

/// The level's decision trail has a line starting with `start`.
inline bool trail_has(const assess::LevelResult& l, const std::string& start) {
    return std::any_of(l.trail.begin(), l.trail.end(),
                       [&](const std::string& t) { return t.rfind(start, 0) == 0; });
}

}  // namespace freestand::test
