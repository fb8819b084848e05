#pragma once
/// Golden comparison of result.json files (`freestand regress`; STYLE.md: goldens
/// compared numerically with an epsilon, refreshed by one command).
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace freestand::report {

/// One difference: JSON path ("/levels/3/slide_asce_m"), golden and fresh values as JSON text.
struct Difference {
    std::string path;
    std::string golden;
    std::string fresh;
};

/// Compares two result documents, ignoring the top-level "stamp". Numbers match when
/// |a - b| <= rtol max(|a|, |b|) (so 0 matches only 0); strings, booleans and nulls exactly;
/// objects by key set and arrays by length, then element-wise. rtol >= 0.
std::vector<Difference> compare_results(const nlohmann::ordered_json& golden,
                                        const nlohmann::ordered_json& fresh, double rtol);

}  // namespace freestand::report
