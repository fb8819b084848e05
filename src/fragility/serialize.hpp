#pragma once
/// Lossless JSON of a fragility run's inputs and samples, the lines of a shard file
/// (`--shard K/N` writes them, `freestand merge` reads them back). Doubles are written in
/// shortest round-trip form, so a merged run aggregates bit-identical numbers.
#include <nlohmann/json_fwd.hpp>
#include <vector>

#include "core/errors.hpp"
#include "fragility/fragility.hpp"

namespace freestand::fragility {

nlohmann::ordered_json to_json(const Meta& meta);
nlohmann::ordered_json to_json(const SampleResult& sample);

/// A run's meta read back from at (its file and line; at.field, e.g. "run.meta", prefixes the
/// keys in messages), every value checked: the config as fragility::validate checks it, the
/// allowable slide in (0, 10] m, the required factor of safety in [1, 10], the laws as the
/// case reader admits them. InputError "malformed fragility shard" naming file, line and key.
Meta meta_from_json(const nlohmann::json& j, const SourceLocation& at);

/// One sample's values, types checked only (InputError naming the key): the MPI ranks' lines,
/// which one run writes and reads.
SampleResult sample_from_json(const nlohmann::json& j);

/// Every sample of a run from its shard records, at[i] the file and line of records[i]. Each is
/// checked against the run (meta) before any is aggregated: level and sample within the run
/// and given once; the motion, friction and restitution exactly those the sample's stream
/// (seed, level, sample) draws from meta's laws; the peak slide and theta/alpha finite and
/// >= 0; an overturn only with theta/alpha >= 1 (less 1e-6, the event location's slack).
/// Then every (level, sample) must be there.
/// InputError "malformed fragility shard" naming the file, line and key.
std::vector<SampleResult> samples_from_json(const std::vector<nlohmann::json>& records,
                                            const std::vector<SourceLocation>& at,
                                            const Meta& meta);

}  // namespace freestand::fragility
