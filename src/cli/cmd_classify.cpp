/// freestand classify: initiating mode of a block at rest under peak accelerations
/// (docs/methods.md s.2).
#include <fmt/format.h>
#include <iostream>

#include "api/classify.hpp"
#include "cli/command.hpp"
#include "cli/options.hpp"
#include "rocking/checks.hpp"

// The command's own namespace: the command files share a unity build (src/cli/CMakeLists.txt).
namespace freestand::cli::classify_command {
namespace {

using api::edge_name;

po::options_description classify_options() {
    po::options_description desc("classify options");
    desc.add_options()
        ("block", po::value<std::string>()->required(), "box b=HALF_WIDTH,h=HALF_HEIGHT[,m=KG] (m)")
        ("cg", po::value<std::string>(), "CG x=OFFSET_TO_RIGHT,h=HEIGHT (m); needs --inertia")
        ("inertia", po::value<std::string>(), "I_c about the CG, kg m^2 (needs m=)")
        ("mu", po::value<std::string>()->required(), "static friction coefficient mu_s in [0, 2]")
        ("a-g", po::value<std::string>()->required(), "peak horizontal acceleration, g")
        ("av-g", po::value<std::string>()->default_value("0"),
         "peak vertical acceleration, g, applied downward (worst case)")
        ("json", "print JSON");
    return desc;
}

api::ClassifyRequest classify_request(const po::variables_map& vm) {
    std::optional<double> inertia;
    if (vm.count("inertia")) inertia = parse_double(vm["inertia"].as<std::string>(), "--inertia");
    api::ClassifyRequest r;
    r.box = box_from_options(vm["block"].as<std::string>(), opt_string(vm, "cg"), inertia);
    r.mu_s = parse_double(vm["mu"].as<std::string>(), "--mu");
    r.a_h_g = parse_double(vm["a-g"].as<std::string>(), "--a-g");
    r.av_g = parse_double(vm["av-g"].as<std::string>(), "--av-g");
    return r;
}

void print_text(const api::ClassifyResult& result) {
    const sliding::PeakInitiation& p = result.initiation;
    const api::ClassifyRequest& r = result.request;
    const auto& g = p.governing();
    std::cout << fmt::format("mode: {} (about the {} edge, which tips first)\n",
                             sliding::to_string(g.mode), edge_name(g.edge));
    std::cout << fmt::format("A = {:.6g} / (1 - {:.6g}) = {:.6g}, mu_s = {:.6g}, tan(alpha) = {:.6g}\n",
                             r.a_h_g, r.av_g, g.A, r.mu_s, g.tan_alpha);
    std::cout << (g.mu_crit ? fmt::format("mu_crit(A) = {:.6g}\n", *g.mu_crit)
                            : fmt::format("mu_crit(A): n/a ({})\n", g.mu_crit_reason));
    std::cout << fmt::format("decided by: {}\n", sliding::describe(g.decided_by));
    for (const auto* i : {&p.left, &p.right})
        std::cout << fmt::format("  {} edge: {} (tan(alpha) = {:.6g})\n", edge_name(i->edge),
                                 sliding::to_string(i->mode), i->tan_alpha);
    const std::string w = rocking::amplification_warning(g.mode, r.mu_s, g.A);
    if (!w.empty()) std::cout << "note: " << w << "\n";
}

int run_classify(const std::vector<std::string>& args) {
    const auto vm = parse_options("classify", "--block b=..,h=.. --mu MU --a-g A [options]",
                                  classify_options(), args);
    if (!vm) return 0;
    const api::ClassifyResult result = api::classify(classify_request(*vm));
    if (vm->count("json"))
        std::cout << api::to_json(result).dump(2) << "\n";
    else
        print_text(result);
    return 0;
}

const CommandRegistrar reg{{"classify", "initiating mode (rest/slide/rock/slide-rock) of a block",
                            &run_classify}};

}  // namespace
}  // namespace freestand::cli::classify_command
