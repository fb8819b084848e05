#include "cli/run_options.hpp"

#include <fmt/format.h>

#include <iostream>

#include "core/errors.hpp"
#include "core/printable.hpp"
#include "cli/usage_error.hpp"

namespace freestand::cli {

void add_run_options(po::options_description& desc) {
    desc.add_options()("threads", po::value<std::string>()->default_value("0"),
                       "worker threads (0: every core); outputs do not depend on it")(
        "cache", po::value<std::string>(),
        "history cache folder (default $XDG_CACHE_HOME/freestand, else "
        "~/.cache/freestand); outputs do not depend on it")(
        "no-cache", po::bool_switch(), "generate every history set, read and write no cache");
}

int threads_option(const po::variables_map& vm) {
    return static_cast<int>(parse_whole(vm["threads"].as<std::string>(), "--threads", 0, 1024));
}

std::optional<std::filesystem::path> cache_dir(const po::variables_map& vm) {
    const bool off = vm.count("no-cache") && vm["no-cache"].as<bool>();
    if (off && vm.count("cache")) throw UsageError("--cache and --no-cache: give one");
    if (off) return std::nullopt;
    if (vm.count("cache")) {
        const std::string dir = vm["cache"].as<std::string>();
        if (dir.empty()) throw InputError(SourceLocation{"", 0, "--cache"}, "empty folder name");
        return std::filesystem::path(dir);
    }
    return core::default_cache_dir();
}

RunContext::RunContext(const po::variables_map& vm) {
    settings_.threads = threads_option(vm);
    if (const auto dir = cache_dir(vm)) {
        const std::uint64_t max_bytes = core::cache_max_bytes_from_environment();
        cache_.emplace(*dir, max_bytes);
        runs_.emplace(*dir / runs_folder, max_bytes);
    }
    settings_.cache = cache();
    settings_.run_cache = runs();
    bar_ = std::make_shared<StepProgressBar>();
    settings_.progress = [bar = bar_](const std::string& step, std::size_t done,
                                      std::size_t total) { bar->update(step, done, total); };
}

void RunContext::finish(const std::string& command) const {
    bar_->finish();
    const std::string cache_failure = cache_ ? cache_->first_failure() : "";
    if (!cache_failure.empty())
        std::cerr << fmt::format("freestand {}: warning: history sets were not cached in {}: {}\n",
                                 command, core::printable(cache_->dir().string()),
                                 core::printable(cache_failure));
    if (!runs_) return;
    const std::string runs_failure = runs_->first_failure();
    if (!runs_failure.empty())
        std::cerr << fmt::format("freestand {}: warning: runs were not cached in {}: {}\n",
                                 command, core::printable(runs_->dir().string()),
                                 core::printable(runs_failure));
    else
        runs_->prune();
}

}  // namespace freestand::cli
