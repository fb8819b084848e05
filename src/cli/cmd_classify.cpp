/// freestand classify: initiating mode of a block at rest under peak accelerations
/// (docs/methods.md s.2).
#include <fmt/format.h>
#include <iostream>

#include "cli/command.hpp"
#include "cli/documents.hpp"
#include "cli/options.hpp"
#include "rocking/checks.hpp"
#include "sliding/initiation.hpp"

// The command's own namespace: the command files share a unity build (src/cli/CMakeLists.txt).
namespace freestand::cli::classify_command {
namespace {

void print_text(const sliding::PeakInitiation& p, double mu, double a_g, double av_g) {
    const auto& g = p.governing();
    std::cout << fmt::format("mode: {} (about the {} edge, which tips first)\n",
                             sliding::to_string(g.mode), edge_name(g.edge));
    std::cout << fmt::format("A = {:.6g} / (1 - {:.6g}) = {:.6g}, mu_s = {:.6g}, tan(alpha) = {:.6g}\n",
                             a_g, av_g, g.A, mu, g.tan_alpha);
    std::cout << (g.mu_crit ? fmt::format("mu_crit(A) = {:.6g}\n", *g.mu_crit)
                            : fmt::format("mu_crit(A): n/a ({})\n", g.mu_crit_reason));
    std::cout << fmt::format("decided by: {}\n", sliding::describe(g.decided_by));
    for (const auto* i : {&p.left, &p.right})
        std::cout << fmt::format("  {} edge: {} (tan(alpha) = {:.6g})\n", edge_name(i->edge),
                                 sliding::to_string(i->mode), i->tan_alpha);
    const std::string w = rocking::amplification_warning(g.mode, mu, g.A);
    if (!w.empty()) std::cout << "note: " << w << "\n";
}

int run_classify(const std::vector<std::string>& args) {
    po::options_description desc = classify_options();
    desc.add_options()("json", "print JSON");
    const auto vm = parse_options("classify", "--block b=..,h=.. --mu MU --a-g A [options]", desc, args);
    if (!vm) return 0;
    const ClassifyRun run = classify_run(*vm);
    if (vm->count("json"))
        std::cout << classify_json(run).dump(2) << "\n";
    else
        print_text(run.initiation, run.mu_s, run.a_h_g, run.av_g);
    return 0;
}

const CommandRegistrar reg{{"classify", "initiating mode (rest/slide/rock/slide-rock) of a block",
                            &run_classify}};

}  // namespace
}  // namespace freestand::cli::classify_command
