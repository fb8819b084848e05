#include "cli/simulate_pair.hpp"

#include <fmt/format.h>

#include <iostream>

#include "core/errors.hpp"
#include "cli/usage_error.hpp"

namespace freestand::cli {

namespace simulate_pair_detail {

const std::array<const char*, 7> pair_options{"block2", "cg2", "inertia2", "mu2",
                                              "mu-k2", "restitution2", "tunnel-height"};

std::optional<double> opt_double(const po::variables_map& vm, const char* name) {
    if (!vm.count(name)) return std::nullopt;
    return vm[name].as<double>();
}

}  // namespace simulate_pair_detail

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
    for (const char* name : simulate_pair_detail::pair_options)
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

api::JoinedUnit joined_unit(const po::variables_map& vm) {
    using simulate_pair_detail::opt_double;
    api::JoinedUnit u;
    try {
        u.box = box_from_options(vm["block2"].as<std::string>(), opt_string(vm, "cg2"),
                                 opt_double(vm, "inertia2"), "2");
    } catch (const InputError& e) {
        throw InputError({"", 0, "unit2." + e.where().field}, e.message());
    }
    u.mu_s = vm["mu2"].as<double>();
    u.mu_k = opt_double(vm, "mu-k2");
    u.restitution = opt_double(vm, "restitution2");
    u.tunnel_height_m = vm["tunnel-height"].as<double>();
    return u;
}

void print_pair(const api::PairRun& run) {
    const dynamics::PairResult& r = run.result;
    std::cout << fmt::format(
        "relative displacement at {:.4g} m  peak {:.4g} m at {:.4f} s (residual {:.4g} m){}\n"
        "unit 1                 peak slide {:.4g} m, peak rotation {:.4g} rad, overturned {}\n"
        "unit 2                 peak slide {:.4g} m, peak rotation {:.4g} rad, overturned {}\n",
        run.tunnel_height_m, r.relative_max_m, r.relative_max_time_s, r.relative_residual_m,
        r.overturned ? " (a unit overturned: unbounded)" : "", r.units[0].slide_max_m,
        r.units[0].rock_max_rad, r.units[0].overturned ? "yes" : "no", r.units[1].slide_max_m,
        r.units[1].rock_max_rad, r.units[1].overturned ? "yes" : "no");
}

}  // namespace freestand::cli
