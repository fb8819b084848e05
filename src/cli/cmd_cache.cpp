// `freestand cache`: the history cache's folder (docs/methods.md s.12): what it holds, emptied,
// or filled ahead of a cluster run.
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "api/cache.hpp"
#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/progress.hpp"
#include "cli/run_options.hpp"
#include "core/errors.hpp"
#include "core/printable.hpp"
#include "cli/usage_error.hpp"

// The command's own namespace: the command files share a unity build (src/cli/CMakeLists.txt).
namespace freestand::cli::cache_command {
namespace {

const char* const usage =
    "info|clear|fill [CASE.toml] [--sets N] [--threads T] [--cache DIR]\n\n"
    "info   the folder, its entries and size, and the bound (FREESTAND_CACHE_MAX_MB), for the\n"
    "       history sets and for the simulation runs (its runs/ folder)\n"
    "clear  removes every entry of both (only the cache's own files)\n"
    "fill   generates the first N history sets of CASE.toml into the cache (default N: the\n"
    "       case's histories_per_level; give fragility's --pool for a fragility run), so that\n"
    "       the shards of a cluster run read them instead of each generating them";

double mib(std::uint64_t bytes) { return static_cast<double>(bytes) / (1024.0 * 1024.0); }

po::options_description cache_options() {
    po::options_description desc("options");
    desc.add_options()("action", po::value<std::string>()->required(), "info, clear or fill")(
        "case", po::value<std::string>(), "case file (fill)")(
        "sets", po::value<std::string>(), "history sets to fill (default: histories_per_level)");
    add_run_options(desc);
    return desc;
}

api::CacheAction action_of(const std::string& name) {
    if (name == "info") return api::CacheAction::info;
    if (name == "clear") return api::CacheAction::clear;
    if (name == "fill") return api::CacheAction::fill;
    throw UsageError(fmt::format("unknown action '{}': expected info, clear or fill",
                                 core::printable(name)));
}

api::CacheRequest cache_request(const po::variables_map& vm) {
    if (vm["no-cache"].as<bool>()) throw UsageError("--no-cache: the cache command works on a cache");
    api::CacheRequest r;
    const std::string action = vm["action"].as<std::string>();
    r.action = action_of(action);
    r.threads = threads_option(vm);
    const auto dir = cache_dir(vm);
    const bool fill = r.action == api::CacheAction::fill;
    if (fill && !vm.count("case"))
        throw UsageError("cache fill needs a case file (see freestand cache --help)");
    if (!fill && (vm.count("case") || vm.count("sets")))
        throw UsageError(fmt::format("cache {} takes no case file and no --sets", core::printable(action)));
    if (!dir)
        throw UsageError("no cache folder: give --cache DIR (neither XDG_CACHE_HOME nor HOME is "
                         "set to an absolute path)");
    r.cache_dir = *dir;
    if (vm.count("case")) r.case_file = vm["case"].as<std::string>();
    if (vm.count("sets"))
        r.sets = static_cast<int>(parse_whole(vm["sets"].as<std::string>(), "--sets", 1, 1000));
    return r;
}

void print(const api::CacheResult& result) {
    for (const api::StoreState& s : result.stores)
        std::cout << fmt::format("{}: {} entries ({}), {:.1f} MiB of {:.0f} MiB\n",
                                 core::printable(s.info.dir.string()), s.info.entries, s.what,
                                 mib(s.info.bytes), mib(s.info.max_bytes));
    for (const auto& [dir, files] : result.removed)
        std::cout << fmt::format("{}: removed {} files\n", core::printable(dir.string()), files);
    if (result.request.action != api::CacheAction::fill) return;
    std::cout << fmt::format(
        "{} history sets of {} in {}: {} already there, {} generated, in {:.2f} s\n",
        result.filled_sets, core::printable(result.request.case_file->string()),
        core::printable(result.request.cache_dir.string()), result.cache_hits,
        result.generated_sets, result.fill_wall_s);
}

int run(const std::vector<std::string>& args) {
    const auto vm = parse_options("cache", usage, cache_options(), args, {"action", "case"});
    if (!vm) return 0;
    const api::CacheRequest request = cache_request(*vm);
    const auto bar = std::make_shared<StepProgressBar>();
    const api::CacheResult result = api::cache(request, progress_on(bar));
    bar->finish();
    print_warnings("cache", result.warnings);
    print(result);
    return 0;
}

const CommandRegistrar reg{
    {"cache", "the history cache: info, clear, or fill it with a case's sets", &run}};

}  // namespace
}  // namespace freestand::cli::cache_command
