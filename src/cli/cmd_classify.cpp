/// freestand classify: initiating mode of a block at rest under peak accelerations
/// (docs/methods.md s.2).
#include <cmath>
#include <fmt/format.h>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/command.hpp"
#include "cli/options.hpp"
#include "core/errors.hpp"
#include "rocking/checks.hpp"
#include "sliding/block_spec.hpp"
#include "sliding/initiation.hpp"

namespace freestand::cli {
namespace {

using json = nlohmann::ordered_json;

const char* edge_name(block::Edge e) { return e == block::Edge::left ? "left" : "right"; }

json to_json(const sliding::Initiation& i) {
    json j;
    j["mode"] = sliding::to_string(i.mode);
    j["edge"] = edge_name(i.edge);
    j["tan_alpha"] = i.tan_alpha;
    j["A"] = i.A;
    j["mu_crit"] = i.mu_crit ? json(*i.mu_crit) : json(nullptr);
    if (!i.mu_crit) j["mu_crit_reason"] = i.mu_crit_reason;
    j["decided_by"] = sliding::describe(i.decided_by);
    return j;
}

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
    po::options_description desc("classify options");
    desc.add_options()
        ("block", po::value<std::string>()->required(), "box b=HALF_WIDTH,h=HALF_HEIGHT[,m=KG] (m)")
        ("cg", po::value<std::string>(), "CG x=OFFSET_TO_RIGHT,h=HEIGHT (m); needs --inertia")
        ("inertia", po::value<std::string>(), "I_c about the CG, kg m^2 (needs m=)")
        ("mu", po::value<std::string>()->required(), "static friction coefficient mu_s >= 0")
        ("a-g", po::value<std::string>()->required(), "peak horizontal acceleration, g")
        ("av-g", po::value<std::string>()->default_value("0"),
         "peak vertical acceleration, g, applied downward (worst case)")
        ("json", "print JSON");
    const auto vm = parse_options("classify", "--block b=..,h=.. --mu MU --a-g A [options]", desc, args);
    if (!vm) return 0;
    std::optional<double> inertia;
    if (vm->count("inertia")) inertia = parse_double((*vm)["inertia"].as<std::string>(), "--inertia");
    const block::Block blk = block_from_options((*vm)["block"].as<std::string>(),
                                                opt_string(*vm, "cg"), inertia);
    const double mu = parse_double((*vm)["mu"].as<std::string>(), "--mu");
    const double a_g = parse_double((*vm)["a-g"].as<std::string>(), "--a-g");
    const double av_g = parse_double((*vm)["av-g"].as<std::string>(), "--av-g");
    require_in_range(mu, 0.0, HUGE_VAL, SourceLocation{"", 0, "--mu"}, true, false);
    require_in_range(a_g, 0.0, HUGE_VAL, SourceLocation{"", 0, "--a-g"}, true, false);
    require_in_range(av_g, 0.0, 1.0, SourceLocation{"", 0, "--av-g"}, true, false);
    const sliding::PeakInitiation p = sliding::classify_peak(blk, mu, a_g, av_g);
    if (!vm->count("json")) {
        print_text(p, mu, a_g, av_g);
        return 0;
    }
    json j = to_json(p.governing());
    j["mu_s"] = mu;
    j["a_h_g"] = a_g;
    j["av_g"] = av_g;
    j["vertical"] = "peak applied downward (worst case)";
    j["amplification_warning"] = rocking::amplification_warning(p.governing().mode, mu, p.governing().A);
    j["edges"] = json{{"left", to_json(p.left)}, {"right", to_json(p.right)}};
    std::cout << j.dump(2) << "\n";
    return 0;
}

const CommandRegistrar reg{{"classify", "initiating mode (rest/slide/rock/slide-rock) of a block",
                            &run_classify}};

}  // namespace
}  // namespace freestand::cli
