#pragma once
/// --threads, --cache DIR and --no-cache: how a command uses the machine, never what it writes.
/// The commands that generate history sets (assess, fragility, batch, validate, regress, cache
/// fill) take them alike.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "api/cache.hpp"
#include "assess/run_settings.hpp"
#include "cli/options.hpp"
#include "cli/progress.hpp"
#include "cli/usage_error.hpp"

namespace freestand::cli {

/// Adds --threads (0, the default: every core), --cache and --no-cache to desc.
void add_run_options(po::options_description& desc);

/// The threads, the cache and a progress bar on standard error (a terminal only, after the
/// run's first second) for one command.
class RunContext {
  public:
    /// Reads the options add_run_options added. UsageError for --cache with --no-cache;
    /// InputError for a bad --threads or FREESTAND_CACHE_MAX_MB.
    explicit RunContext(const po::variables_map& vm);
    RunContext(const RunContext&) = delete;
    RunContext& operator=(const RunContext&) = delete;

    const assess::RunSettings& settings() const { return settings_; }
    /// Ends the progress line, warns on standard error when sets or runs could not be cached,
    /// and bounds the runs' folder (api::RunCaches::finish).
    void finish(const std::string& command) const;

  private:
    RunContext(int threads, const po::variables_map& vm);

    api::RunCaches caches_;
    std::shared_ptr<StepProgressBar> bar_;
    assess::RunSettings settings_;
};

/// The cache folder the options name: --cache DIR, else the default (XDG); none with
/// --no-cache or without a default.
std::optional<std::filesystem::path> cache_dir(const po::variables_map& vm);

/// A progress callback that draws on bar.
assess::StepProgress progress_on(std::shared_ptr<StepProgressBar> bar);

/// Each of warnings on standard error, as "freestand COMMAND: warning: ...".
void print_warnings(const std::string& command, const std::vector<std::string>& warnings);

/// --threads: a whole number of threads, 0 for every core.
int threads_option(const po::variables_map& vm);

}  // namespace freestand::cli
