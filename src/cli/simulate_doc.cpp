// `simulate`'s planar rigid block: its options, model and JSON summary (cli/documents.hpp).
#include "cli/documents.hpp"

#include <fmt/format.h>

#include "core/errors.hpp"

namespace freestand::cli {

po::options_description simulate_model_options() {
    po::options_description desc("simulate options");
    desc.add_options()
        ("block", po::value<std::string>()->required(), "b=half-width,h=CG height,m=mass (m, kg)")
        ("cg", po::value<std::string>(),
         "x,y: CG x from the left edge and y above the base (m); or x=OFFSET,h=HEIGHT: x right "
         "of the base's centre, as classify and rock take it")
        ("inertia", po::value<double>(), "I_c about the CG (kg m^2)")
        ("top", po::value<double>(), "height of the top corners for top_accel (m; default 2 h)")
        ("mu", po::value<double>()->required(), "static friction coefficient, in [0, 2]")
        ("mu-k", po::value<double>(), "kinetic friction coefficient (default: --mu)")
        ("restitution", po::value<double>(), "restitution on angular velocity (default Housner)")
        ("integrator", po::value<std::string>()->default_value("event"), "event | cd")
        ("dt", po::value<double>()->default_value(1e-4), "central-difference step (s)");
    return desc;
}

namespace {

std::optional<double> optional_double(const po::variables_map& vm, const char* name) {
    if (!vm.count(name)) return std::nullopt;
    return vm[name].as<double>();
}

}  // namespace

block::Block simulate_block(const po::variables_map& vm) {
    return block_from_options(vm["block"].as<std::string>(), opt_string(vm, "cg"),
                              optional_double(vm, "inertia"));
}

dynamics::BlockModel simulate_model(const po::variables_map& vm, const block::Block& blk) {
    return dynamics::make_block_model(blk, vm["mu"].as<double>(), optional_double(vm, "mu-k"),
                                      optional_double(vm, "restitution"),
                                      optional_double(vm, "top"));
}

dynamics::Options simulate_run_options(const po::variables_map& vm, dynamics::Options base) {
    const std::string integ = vm["integrator"].as<std::string>();
    if (integ == "cd") base.integrator = dynamics::Integrator::central_difference;
    else if (integ != "event")
        throw UsageError(fmt::format("--integrator: expected event or cd; got \"{}\"", integ));
    base.cd_dt_s = vm["dt"].as<double>();
    require_positive(base.cd_dt_s, {"", 0, "--dt"});
    return base;
}

json summary_json(const dynamics::Summary& s) {
    json j;
    j["slide_max_m"] = s.slide_max_m;
    j["slide_residual_m"] = s.slide_residual_m;
    j["rock_max_rad"] = s.rock_max_rad;
    j["rock_max_over_alpha"] = s.rock_max_over_alpha;
    j["overturned"] = s.overturned;
    j["overturn_time_s"] = s.overturn_time_s ? json(*s.overturn_time_s) : nullptr;
    j["overturn_mode"] = s.overturn_mode ? json(*s.overturn_mode) : nullptr;
    j["impacts"] = s.impacts;
    j["mode_changes"] = s.mode_changes;
    j["top_accel_max_g"] = s.top_accel_max_g;
    j["amplification"] = s.amplification;
    j["wall_s"] = s.wall_s;
    j["integrator"] = s.integrator;
    j["overturn_criterion"] = dynamics::overturn_criterion_name(s.overturn_criterion);
    json t;
    for (std::size_t m = 0; m < dynamics::mode_count; ++m)
        t[dynamics::mode_name(static_cast<dynamics::Mode>(m))] = s.time_in_mode_s[m];
    j["time_in_mode_s"] = t;
    j["pga_g"] = s.pga_g;
    j["settlements"] = s.settlements;
    j["steps"] = s.steps;
    j["end_time_s"] = s.end_time_s;
    return j;
}

}  // namespace freestand::cli
