#pragma once
/// fragility: P(overturn), P(slide > allowable), P(theta/alpha > 1/FS) against PGA
/// (docs/methods.md s.9), over the whole run or a shard's share of its samples (s.12).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "api/json.hpp"
#include "assess/run_settings.hpp"
#include "fragility/fragility.hpp"
#include "report/json.hpp"

namespace freestand::api {

struct FragilityRequest {
    std::filesystem::path case_file;       ///< named in messages and stamped
    std::optional<std::string> case_text;  ///< the case file's bytes; none: read case_file
    /// PGA levels, g: 1 to 1000, strictly increasing in [0.001, 3].
    std::vector<double> pga_g{0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
    int samples = 100;                    ///< per level, >= 1
    int pool = 20;                        ///< generated history sets the samples draw from
    std::optional<std::uint64_t> seed;    ///< none: the case's [options] seed
    std::vector<std::string> record_files;  ///< a user suite instead of generated sets
    /// The models the case's levels decide with (fragility::case_models) instead of the rigid
    /// planar block; generated sets only.
    bool case_models = false;
    /// This process computes the samples whose global index i has i % shard_n == shard_k - 1;
    /// 1 <= shard_k <= shard_n <= 100000.
    int shard_k = 1, shard_n = 1;
    int threads = 0;  ///< worker threads, 0 to 1024 (0: every core); outputs do not depend on it
    /// The history and run cache folder (api::RunCaches); none: no cache. Outputs do not
    /// depend on it.
    std::optional<std::filesystem::path> cache_dir;
    std::string commit = "unknown";  ///< the build's commit, stamped into the outputs
};

struct FragilityResult {
    FragilityRequest request;
    fragility::Meta meta;
    report::Stamp stamp;
    std::size_t total_samples = 0;                 ///< levels x samples of the whole run
    std::vector<fragility::SampleResult> samples;  ///< this share's, by global index
    std::optional<fragility::Result> result;       ///< the whole run (shard 1 of 1) aggregated
    std::vector<std::string> cache_warnings;       ///< api::RunCaches::finish
};

/// The checked request's share of the run (the whole run for shard 1 of 1, then aggregated).
/// progress reports the steps "history sets" and "samples". InputError naming the field
/// (fragility::validate's, "threads", "shard") or the case file's line.
FragilityResult fragility(const FragilityRequest& request,
                          const assess::StepProgress& progress = {});

/// The whole run from every share's samples (e.g. gathered from MPI ranks).
fragility::Result aggregate(const FragilityResult& share,
                            std::vector<fragility::SampleResult> all);

/// fragility.json of the whole run (result required).
json to_json(const FragilityResult& result);

/// A fragility shard's header "run", {"meta", "stamp"}, and its records, one per sample.
json shard_run_json(const fragility::Meta& meta, const report::Stamp& stamp);
std::vector<json> shard_records(const FragilityResult& result);

/// The levels START, START + STEP, ... up to STOP (within 1e-9 steps), each rounded to 1e-12 g:
/// the levels "START:STOP:STEP" names. InputError naming "pga_g" unless STEP > 0, STOP >= START
/// and at most core::limits::max_pga_levels levels.
std::vector<double> pga_range(double start_g, double stop_g, double step_g);

}  // namespace freestand::api
