#include "cli/design_options.hpp"

#include <fmt/format.h>

#include <map>
#include <set>

#include "core/errors.hpp"
#include "core/limits.hpp"
#include "spectra/design.hpp"

namespace freestand::cli {
namespace {

/// Options each design accepts; any other design option given is an error.
const std::map<std::string, std::set<std::string>>& design_keys() {
    static const std::map<std::string, std::set<std::string>> keys{
        {"rg1.60", {"pga"}},
        {"asce7", {"sds", "sd1", "tl"}},
        {"ec8", {"ag", "type", "ground"}},
        {"is1893", {"pga", "soil"}},
    };
    return keys;
}

std::string text_option(const po::variables_map& vm, const char* name) {
    return vm.count(name) ? vm[name].as<std::string>() : "";
}

}  // namespace

double required_positive(const po::variables_map& vm, const std::string& selector,
                         const std::string& design, const std::string& name) {
    if (!vm.count(name))
        throw UsageError(fmt::format("{} {} needs --{}", selector, design, name));
    const double v = parse_double(vm[name].as<std::string>(), "--" + name);
    require_positive(v, SourceLocation{"", 0, "--" + name});
    if (name == "pga" || name == "sds" || name == "sd1" || name == "ag")
        core::limits::require_within(v, core::limits::max_design_level_g,
                                     SourceLocation{"", 0, "--" + name}, "a design level (g)");
    return v;
}

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

void check_design_options(const po::variables_map& vm, const std::string& selector,
                          const std::string& design) {
    const auto it = design_keys().find(design);
    if (it == design_keys().end())
        throw UsageError(fmt::format(
            "{}: unknown design \"{}\"; expected one of rg1.60, asce7, ec8, is1893", selector,
            design));
    for (const char* opt : {"pga", "sds", "sd1", "tl", "ag", "type", "ground", "soil"})
        if (vm.count(opt) && !it->second.count(opt))
            throw UsageError(fmt::format("--{} does not apply to {} {}", opt, selector, design));
}

spectra::Spectrum design_spectrum(const po::variables_map& vm, const std::string& selector,
                                  const std::string& design, double damping, bool vertical,
                                  const std::vector<double>& f) {
    check_design_options(vm, selector, design);
    if (vertical && design != "rg1.60")
        throw UsageError(fmt::format("--vertical does not apply to {} {}", selector, design));
    if (design == "rg1.60")
        return spectra::rg160(required_positive(vm, selector, design, "pga"), damping, vertical, f);
    if (design == "asce7") {
        const double sds = required_positive(vm, selector, design, "sds");
        const double sd1 = required_positive(vm, selector, design, "sd1");
        const double tl = required_positive(vm, selector, design, "tl");
        if (!(tl > sd1 / sds))  // checked here too so the message names the option
            throw InputError(SourceLocation{"", 0, "--tl"},
                             fmt::format("{} s; expected more than TS = SD1/SDS = {} s", tl,
                                         sd1 / sds));
        return spectra::asce7(sds, sd1, tl, f);
    }
    if (design == "ec8") {
        const double ag = required_positive(vm, selector, design, "ag");
        const std::string type = text_option(vm, "type");
        if (type != "1" && type != "2")
            throw UsageError(
                fmt::format("--type: \"{}\"; {} ec8 needs --type 1 or 2", type, selector));
        const std::string ground = text_option(vm, "ground");
        if (ground.size() != 1 || ground[0] < 'A' || ground[0] > 'E')
            throw UsageError(fmt::format(
                "--ground: \"{}\"; {} ec8 needs --ground A, B, C, D or E", ground, selector));
        const auto t = type == "1" ? spectra::Ec8Type::type1 : spectra::Ec8Type::type2;
        return spectra::ec8(ag, t, ground[0], damping, f);
    }
    const std::string soil = text_option(vm, "soil");
    const std::map<std::string, spectra::Is1893Soil> soils{{"rock", spectra::Is1893Soil::rock},
                                                           {"medium", spectra::Is1893Soil::medium},
                                                           {"soft", spectra::Is1893Soil::soft}};
    if (!soils.count(soil))
        throw UsageError(fmt::format("--soil: \"{}\"; {} is1893 needs --soil rock, medium or soft",
                                     soil, selector));
    return spectra::is1893(required_positive(vm, selector, design, "pga"), soils.at(soil), f);
}

}  // namespace freestand::cli
