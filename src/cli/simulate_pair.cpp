#include "cli/simulate_pair.hpp"

#include <fmt/format.h>

#include <iostream>
#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "core/limits.hpp"
#include "dynamics/pair.hpp"

namespace freestand::cli {

namespace {

const std::array<const char*, 7> pair_options{"block2", "cg2", "inertia2", "mu2",
                                              "mu-k2", "restitution2", "tunnel-height"};

std::optional<double> opt_double(const po::variables_map& vm, const char* name) {
    if (!vm.count(name)) return std::nullopt;
    return vm[name].as<double>();
}

// The second unit, every error naming its option (make_block_model names mu_s, mu_k, restitution).
dynamics::BlockModel unit2_model(const po::variables_map& vm) {
    block::Block blk;
    try {
        blk = block_from_options(vm["block2"].as<std::string>(), opt_string(vm, "cg2"),
                                 opt_double(vm, "inertia2"), "2");
    } catch (const InputError& e) {
        throw InputError({"", 0, "--block2"}, e.what());
    }
    // The first unit's ranges, which are a case's (core/limits.hpp), named as these options.
    const double mu = vm["mu2"].as<double>();
    core::limits::require_in(mu, core::limits::friction, {"", 0, "--mu2"});
    const std::optional<double> mu_k = opt_double(vm, "mu-k2"), r = opt_double(vm, "restitution2");
    if (mu_k) require_in_range(*mu_k, 0.0, mu, {"", 0, "--mu-k2 (at most --mu2)"});
    if (r) core::limits::require_in(*r, core::limits::restitution, {"", 0, "--restitution2"});
    return dynamics::make_block_model(blk, mu, mu_k, r);
}

}  // namespace

void add_pair_options(po::options_description& desc) {
    desc.add_options()
        ("block2", po::value<std::string>(),
         "second unit, as --block: b=half-width,h=CG height,m=mass (m, kg)")
        ("cg2", po::value<std::string>(), "second unit's CG, as --cg")
        ("inertia2", po::value<double>(), "second unit's I_c about its CG (kg m^2)")
        ("mu2", po::value<double>(), "second unit's static friction coefficient")
        ("mu-k2", po::value<double>(), "second unit's kinetic friction (default: --mu2)")
        ("restitution2", po::value<double>(), "second unit's restitution (default Housner)")
        ("tunnel-height", po::value<double>(),
         "height of the tunnel joining the units above the base (m): prints relative_max_m");
}

bool pair_requested(const po::variables_map& vm) {
    for (const char* name : pair_options)
        if (vm.count(name)) return true;
    return false;
}

void require_pair_options(const po::variables_map& vm) {
    for (const char* name : {"block2", "mu2", "tunnel-height"})
        if (!vm.count(name))
            throw UsageError(fmt::format("--{}: needed for a second unit (--block2, --mu2 and "
                                         "--tunnel-height go together)",
                                         name));
    for (const char* name : {"motion-y", "sine-y", "out"})
        if (vm.count(name))
            throw UsageError(fmt::format("--{}: not available with a second unit (the pair is "
                                         "planar and prints no series)",
                                         name));
}

int run_pair_simulation(const po::variables_map& vm, const dynamics::BlockModel& unit1,
                        const dynamics::Excitation& excitation, const dynamics::Options& options) {
    const dynamics::BlockModel unit2 = unit2_model(vm);
    dynamics::PairOptions pair;
    pair.tunnel_height_m = vm["tunnel-height"].as<double>();
    require_in_range(pair.tunnel_height_m, 0.0, 1e3, {"", 0, "--tunnel-height (m)"});
    const dynamics::PairResult r = dynamics::simulate_pair({unit1, unit2}, excitation, pair, options);
    if (vm["json"].as<bool>()) {
        nlohmann::ordered_json j;
        j["relative_max_m"] = r.relative_max_m;
        j["relative_max_time_s"] = r.relative_max_time_s;
        j["relative_residual_m"] = r.relative_residual_m;
        j["tunnel_height_m"] = pair.tunnel_height_m;
        j["overturned"] = r.overturned;
        j["sampled_at"] = "the input samples";
        j["model"] = "two rigid planar blocks under the same base motion (docs/methods.md s.10)";
        j["unit1"] = summary_json(r.units[0]);
        j["unit2"] = summary_json(r.units[1]);
        std::cout << j.dump(2) << "\n";
        return 0;
    }
    std::cout << fmt::format(
        "relative displacement at {:.4g} m  peak {:.4g} m at {:.4f} s (residual {:.4g} m){}\n"
        "unit 1                 peak slide {:.4g} m, peak rotation {:.4g} rad, overturned {}\n"
        "unit 2                 peak slide {:.4g} m, peak rotation {:.4g} rad, overturned {}\n",
        pair.tunnel_height_m, r.relative_max_m, r.relative_max_time_s, r.relative_residual_m,
        r.overturned ? " (a unit overturned: unbounded)" : "", r.units[0].slide_max_m,
        r.units[0].rock_max_rad, r.units[0].overturned ? "yes" : "no", r.units[1].slide_max_m,
        r.units[1].rock_max_rad, r.units[1].overturned ? "yes" : "no");
    return 0;
}

}  // namespace freestand::cli
