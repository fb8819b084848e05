#include "api/fragility.hpp"

#include <fmt/format.h>

#include <cmath>

#include "api/cache.hpp"
#include "assess/case.hpp"
#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/limits.hpp"
#include "core/sha256.hpp"
#include "fragility/serialize.hpp"
#include "report/fragility_json.hpp"

namespace freestand::api {

namespace fragility_detail {

// --shard's own range: at most 100000 shards.
constexpr int kMaxShards = 100000;

void check(const FragilityRequest& r) {
    require_in_range(r.threads, 0, 1024, SourceLocation{"", 0, "threads"});
    if (r.shard_n < 1 || r.shard_n > kMaxShards || r.shard_k < 1 || r.shard_k > r.shard_n)
        throw InputError(SourceLocation{"", 0, "shard"},
                         fmt::format("{}/{}; expected K/N with 1 <= K <= N <= {}", r.shard_k,
                                     r.shard_n, kMaxShards));
}

fragility::Config config(const FragilityRequest& r, const assess::Case& c) {
    fragility::Config cfg;
    cfg.pga_g = r.pga_g;
    cfg.samples = r.samples;
    cfg.pool = r.pool;
    cfg.seed = r.seed.value_or(c.options.seed);
    cfg.record_files = r.record_files;
    if (r.case_models) cfg.models = fragility::case_models(c, cfg.pga_g).models;
    return cfg;
}

// The case's bytes, the seed, the case's other inputs and the records of a user suite, each
// hashed, and the build's commit.
report::Stamp stamp(const std::string& case_text, const FragilityRequest& r,
                    const assess::Case& c, const fragility::Config& cfg) {
    report::Stamp s = report::make_stamp(case_text, r.case_file.string(), cfg.seed, r.commit);
    s.inputs = report::stamped_inputs(c);
    for (const std::string& f : cfg.record_files)
        s.inputs.push_back({f, core::sha256_hex(core::read_input_file(f))});
    return s;
}

// The global indices shard k of n computes: every n-th, so slow levels spread over shards.
std::vector<std::size_t> share(std::size_t total, int k, int n) {
    std::vector<std::size_t> out;
    for (std::size_t g = 0; g < total; ++g)
        if (g % static_cast<std::size_t>(n) == static_cast<std::size_t>(k - 1)) out.push_back(g);
    return out;
}

}  // namespace fragility_detail

FragilityResult fragility(const FragilityRequest& request, const assess::StepProgress& progress) {
    fragility_detail::check(request);
    const std::string case_text =
        request.case_text ? *request.case_text : core::read_input_file(request.case_file);
    const assess::Case c = assess::parse_case(case_text, request.case_file.string());
    const fragility::Config cfg = fragility_detail::config(request, c);
    const RunCaches caches(request.cache_dir);
    fragility::Runner runner(c, cfg);
    FragilityResult out;
    out.request = request;
    out.meta = fragility::make_meta(c, cfg);
    out.stamp = fragility_detail::stamp(case_text, request, c, cfg);
    out.total_samples = runner.total();
    const assess::RunSettings settings = caches.settings(request.threads, progress);
    runner.prepare(settings);
    out.samples = fragility::run_samples(
        runner, fragility_detail::share(runner.total(), request.shard_k, request.shard_n),
        request.threads, [&](std::size_t done, std::size_t total) {
            if (progress) progress("samples", done, total);
        });
    out.cache_warnings = caches.finish();
    if (request.shard_n == 1) out.result = fragility::aggregate(out.meta, out.samples);
    return out;
}

fragility::Result aggregate(const FragilityResult& share,
                            std::vector<fragility::SampleResult> all) {
    return fragility::aggregate(share.meta, std::move(all));
}

json to_json(const FragilityResult& result) {
    return report::fragility_json(result.result.value(), result.stamp);
}

json shard_run_json(const fragility::Meta& meta, const report::Stamp& stamp) {
    return {{"meta", fragility::to_json(meta)}, {"stamp", report::stamp_json(stamp)}};
}

std::vector<json> shard_records(const FragilityResult& result) {
    std::vector<json> out;
    for (const auto& s : result.samples) out.push_back(fragility::to_json(s));
    return out;
}

std::vector<double> pga_range(double start_g, double stop_g, double step_g) {
    const SourceLocation where{"", 0, "pga_g"};
    if (!(step_g > 0.0) || !(stop_g >= start_g))
        throw InputError(where, fmt::format("{}:{}:{} needs STEP > 0 and STOP >= START", start_g,
                                            stop_g, step_g));
    const double count = core::limits::pga_range_count(start_g, stop_g, step_g);
    if (count > core::limits::max_pga_levels)
        throw InputError(where, fmt::format("{}:{}:{} gives {} levels; at most {}", start_g,
                                            stop_g, step_g, count, core::limits::max_pga_levels));
    return core::limits::pga_range_levels(start_g, step_g, count);
}

}  // namespace freestand::api
