#pragma once
/// The history cache's folder (docs/methods.md s.12): the stores a run reads and writes, and the
/// `cache` command's actions on them (what it holds, emptied, filled ahead of a cluster run).
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "assess/run_settings.hpp"
#include "core/content_store.hpp"

namespace freestand::api {

/// The simulation runs' folder inside the cache folder: the history sets' entries stay apart.
inline constexpr const char* runs_folder = "runs";

/// The stores of one cache folder: history sets in it, simulation runs in its runs/ folder,
/// each bounded by FREESTAND_CACHE_MAX_MB (InputError when that is malformed).
class RunCaches {
  public:
    /// No folder: no store (every set generated, every run simulated).
    explicit RunCaches(const std::optional<std::filesystem::path>& dir);

    const core::ContentStore* sets() const { return sets_ ? &*sets_ : nullptr; }
    const core::ContentStore* runs() const { return runs_ ? &*runs_ : nullptr; }
    /// threads threads on these stores, silent unless progress is given.
    assess::RunSettings settings(int threads, assess::StepProgress progress = {}) const;
    /// After a run: one warning per store a write failed in ("history sets were not cached in
    /// DIR: why"), and the runs' folder bounded when every write succeeded.
    std::vector<std::string> finish() const;

  private:
    std::optional<core::ContentStore> sets_;
    std::optional<core::ContentStore> runs_;
};

enum class CacheAction { info, clear, fill };

struct CacheRequest {
    CacheAction action = CacheAction::info;
    std::filesystem::path cache_dir;                 ///< the cache folder
    std::optional<std::filesystem::path> case_file;  ///< fill: the case whose sets are generated
    /// fill: how many history sets (1 to 1000); none: the case's histories_per_level.
    std::optional<int> sets;
    int threads = 0;  ///< fill: worker threads, 0 to 1024 (0: every core)
};

/// One store's state, and what it is ("history sets", "runs").
struct StoreState {
    core::StoreInfo info;
    std::string what;
};

struct CacheResult {
    CacheRequest request;
    std::vector<StoreState> stores;                              ///< info
    std::vector<std::pair<std::filesystem::path, std::size_t>> removed;  ///< clear: files per folder
    std::size_t filled_sets = 0, cache_hits = 0, generated_sets = 0;    ///< fill
    double fill_wall_s = 0.0;                                    ///< fill: generation time
    std::vector<std::string> warnings;                           ///< RunCaches::finish
};

/// The action on the folder. InputError naming the field: case_file missing for fill or given
/// otherwise, sets given other than with fill, sets outside 1 to 1000 or, for a case with seed
/// records (one triple per set), other than its own histories_per_level; threads outside its
/// range.
CacheResult cache(const CacheRequest& request, const assess::StepProgress& progress = {});

}  // namespace freestand::api
