#include "cli/run_options.hpp"

#include <fmt/format.h>

#include <iostream>

#include "core/errors.hpp"
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

assess::StepProgress progress_on(std::shared_ptr<StepProgressBar> bar) {
    return [bar = std::move(bar)](const std::string& step, std::size_t done, std::size_t total) {
        bar->update(step, done, total);
    };
}

void print_warnings(const std::string& command, const std::vector<std::string>& warnings) {
    for (const std::string& warning : warnings)
        std::cerr << fmt::format("freestand {}: warning: {}\n", command, warning);
}

// --threads is read before the cache options, so its error comes first when both are bad.
RunContext::RunContext(const po::variables_map& vm) : RunContext(threads_option(vm), vm) {}

RunContext::RunContext(int threads, const po::variables_map& vm)
    : caches_(cache_dir(vm)), bar_(std::make_shared<StepProgressBar>()) {
    settings_ = caches_.settings(threads, progress_on(bar_));
}

void RunContext::finish(const std::string& command) const {
    bar_->finish();
    print_warnings(command, caches_.finish());
}

}  // namespace freestand::cli
