#include "api/cache.hpp"

#include <fmt/format.h>

#include <chrono>

#include "assess/case.hpp"
#include "assess/histories.hpp"
#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/printable.hpp"

namespace freestand::api {

RunCaches::RunCaches(const std::optional<std::filesystem::path>& dir) {
    if (!dir) return;
    const std::uint64_t max_bytes = core::cache_max_bytes_from_environment();
    sets_.emplace(*dir, max_bytes);
    runs_.emplace(*dir / runs_folder, max_bytes);
}

assess::RunSettings RunCaches::settings(int threads, assess::StepProgress progress) const {
    assess::RunSettings s(threads);
    s.cache = sets();
    s.run_cache = runs();
    s.progress = std::move(progress);
    return s;
}

std::vector<std::string> RunCaches::finish() const {
    std::vector<std::string> warnings;
    const std::string sets_failure = sets_ ? sets_->first_failure() : "";
    if (!sets_failure.empty())
        warnings.push_back(fmt::format("history sets were not cached in {}: {}",
                                       core::printable(sets_->dir().string()),
                                       core::printable(sets_failure)));
    if (!runs_) return warnings;
    const std::string runs_failure = runs_->first_failure();
    if (!runs_failure.empty())
        warnings.push_back(fmt::format("runs were not cached in {}: {}",
                                       core::printable(runs_->dir().string()),
                                       core::printable(runs_failure)));
    else
        runs_->prune();
    return warnings;
}

namespace cache_detail {

void check(const CacheRequest& r) {
    const bool fill = r.action == CacheAction::fill;
    if (fill && !r.case_file)
        throw InputError(SourceLocation{"", 0, "case_file"}, "fill needs a case file");
    if (!fill && (r.case_file || r.sets))
        throw InputError(SourceLocation{"", 0, r.case_file ? "case_file" : "sets"},
                         "only fill takes a case file and a number of sets");
    if (r.sets) require_in_range(*r.sets, 1, 1000, SourceLocation{"", 0, "sets"});
    require_in_range(r.threads, 0, 1024, SourceLocation{"", 0, "threads"});
}

void fill(const CacheRequest& r, const RunCaches& caches, const assess::StepProgress& progress,
          CacheResult& out) {
    const std::filesystem::path& file = *r.case_file;
    assess::Case c = assess::parse_case(core::read_input_file(file), file.string());
    if (r.sets) {
        c.options.histories_per_level = *r.sets;
        // Seed records name one triple per set: the case's own count stays.
        if (!c.options.seed_records.empty() &&
            c.options.seed_records.size() != 3 * static_cast<std::size_t>(*r.sets))
            throw InputError(SourceLocation{"", 0, "sets"},
                             "the case gives seed records for its own histories_per_level only");
    }
    const auto start = std::chrono::steady_clock::now();
    assess::HistoryBank bank(c, caches.settings(r.threads, progress));
    out.filled_sets = bank.sets().size();
    out.cache_hits = bank.cache_hits();
    out.generated_sets = bank.generated_sets();
    out.fill_wall_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace cache_detail

CacheResult cache(const CacheRequest& request, const assess::StepProgress& progress) {
    cache_detail::check(request);
    CacheResult out{request, {}, {}, 0, 0, 0, 0.0, {}};
    const RunCaches caches(request.cache_dir);
    switch (request.action) {
        case CacheAction::fill:
            cache_detail::fill(request, caches, progress, out);
            out.warnings = caches.finish();
            break;
        case CacheAction::info:
            out.stores = {{caches.sets()->info(), "history sets"}, {caches.runs()->info(), "runs"}};
            break;
        case CacheAction::clear:
            for (const core::ContentStore* s : {caches.sets(), caches.runs()})
                out.removed.emplace_back(s->dir(), s->clear());
            break;
    }
    return out;
}

}  // namespace freestand::api
