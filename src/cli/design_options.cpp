#include "cli/design_options.hpp"

namespace freestand::cli {

void add_design_options(po::options_description& desc) {
    desc.add_options()("pga", po::value<std::string>(),
                       "rg1.60, is1893: peak ground acceleration, g (> 0)")(
        "sds", po::value<std::string>(), "asce7: SDS, g (> 0)")("sd1", po::value<std::string>(),
                                                                "asce7: SD1, g (> 0)")(
        "tl", po::value<std::string>(), "asce7: long-period transition TL, s (> SD1/SDS)")(
        "ag", po::value<std::string>(), "ec8: design ground acceleration a_g on rock, g (> 0)")(
        "type", po::value<std::string>(), "ec8: spectrum type 1 or 2")(
        "ground", po::value<std::string>(), "ec8: ground type A, B, C, D or E")(
        "soil", po::value<std::string>(), "is1893: rock, medium or soft");
}

api::DesignValues design_values(const po::variables_map& vm) {
    api::DesignValues v;
    v.pga_g = opt_number(vm, "pga");
    v.sds_g = opt_number(vm, "sds");
    v.sd1_g = opt_number(vm, "sd1");
    v.tl_s = opt_number(vm, "tl");
    v.ag_g = opt_number(vm, "ag");
    v.type = opt_string(vm, "type");
    v.ground = opt_string(vm, "ground");
    v.soil = opt_string(vm, "soil");
    return v;
}

}  // namespace freestand::cli
