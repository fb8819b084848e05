// `freestand cache`: the history cache's folder (docs/methods.md s.12): what it holds, emptied,
// or filled ahead of a cluster run.
#include <fmt/format.h>

#include <chrono>
#include <iostream>

#include "assess/case.hpp"
#include "assess/histories.hpp"
#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/run_options.hpp"
#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/printable.hpp"

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

const core::ContentStore& store_or_fail(const RunContext& run) {
    if (run.cache() == nullptr)
        throw UsageError("no cache folder: give --cache DIR (neither XDG_CACHE_HOME nor HOME is "
                         "set to an absolute path)");
    return *run.cache();
}

int fill(const po::variables_map& vm, const RunContext& run) {
    store_or_fail(run);
    if (!vm.count("case")) throw UsageError("cache fill needs a case file (see freestand cache --help)");
    const std::filesystem::path file = vm["case"].as<std::string>();
    assess::Case c = assess::parse_case(core::read_input_file(file), file.string());
    if (vm.count("sets")) {
        c.options.histories_per_level = static_cast<int>(
            parse_whole(vm["sets"].as<std::string>(), "--sets", 1, 1000));
        // Seed records name one triple per set: the case's own count stays.
        if (!c.options.seed_records.empty() &&
            c.options.seed_records.size() != 3 * static_cast<std::size_t>(c.options.histories_per_level))
            throw UsageError("--sets: the case gives seed records for its own "
                             "histories_per_level only");
    }
    const auto start = std::chrono::steady_clock::now();
    assess::HistoryBank bank(c, run.settings());
    bank.sets();
    run.finish("cache");
    std::cout << fmt::format(
        "{} history sets of {} in {}: {} already there, {} generated, in {:.2f} s\n",
        bank.sets().size(), core::printable(file.string()),
        core::printable(run.cache()->dir().string()), bank.cache_hits(), bank.generated_sets(),
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    return 0;
}

int run(const std::vector<std::string>& args) {
    po::options_description desc("options");
    desc.add_options()("action", po::value<std::string>()->required(), "info, clear or fill")(
        "case", po::value<std::string>(), "case file (fill)")(
        "sets", po::value<std::string>(), "history sets to fill (default: histories_per_level)");
    add_run_options(desc);
    const auto vm = parse_options("cache", usage, desc, args, {"action", "case"});
    if (!vm) return 0;
    const std::string action = (*vm)["action"].as<std::string>();
    if ((*vm)["no-cache"].as<bool>()) throw UsageError("--no-cache: the cache command works on a cache");
    const RunContext run(*vm);
    if (action == "fill") return fill(*vm, run);
    if (vm->count("case") || vm->count("sets"))
        throw UsageError(fmt::format("cache {} takes no case file and no --sets", core::printable(action)));
    const core::ContentStore& store = store_or_fail(run);
    const core::ContentStore& runs = *run.runs();
    if (action == "info") {
        for (const auto& [s, what] : {std::pair{&store, "history sets"}, std::pair{&runs, "runs"}}) {
            const core::StoreInfo i = s->info();
            std::cout << fmt::format("{}: {} entries ({}), {:.1f} MiB of {:.0f} MiB\n",
                                     core::printable(i.dir.string()), i.entries, what,
                                     mib(i.bytes), mib(i.max_bytes));
        }
        return 0;
    }
    if (action == "clear") {
        for (const core::ContentStore* s : {&store, &runs})
            std::cout << fmt::format("{}: removed {} files\n", core::printable(s->dir().string()),
                                     s->clear());
        return 0;
    }
    throw UsageError(fmt::format("unknown action '{}': expected info, clear or fill",
                                 core::printable(action)));
}

const CommandRegistrar reg{
    {"cache", "the history cache: info, clear, or fill it with a case's sets", &run}};

}  // namespace
}  // namespace freestand::cli::cache_command
