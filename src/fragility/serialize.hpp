#pragma once
/// Lossless JSON of a fragility run's inputs and samples, the lines of a shard file
/// (`--shard K/N` writes them, `freestand merge` reads them back). Doubles are written in
/// shortest round-trip form, so a merged run aggregates bit-identical numbers.
#include <nlohmann/json_fwd.hpp>

#include "fragility/fragility.hpp"

namespace freestand::fragility {

nlohmann::ordered_json to_json(const Meta& meta);
nlohmann::ordered_json to_json(const SampleResult& sample);

/// Throw nlohmann::json::exception on a missing key or a wrong type.
Meta meta_from_json(const nlohmann::json& j);
SampleResult sample_from_json(const nlohmann::json& j);

}  // namespace freestand::fragility
