#include "api/target.hpp"

#include <fmt/format.h>

#include <map>
#include <set>

#include "core/errors.hpp"
#include "core/limits.hpp"
#include "spectra/design.hpp"

namespace freestand::api {

namespace target_detail {

/// The values each design takes, by request field.
const std::map<std::string, std::set<std::string>>& design_fields() {
    static const std::map<std::string, std::set<std::string>> fields{
        {"rg1.60", {"pga_g"}},
        {"asce7", {"sds_g", "sd1_g", "tl_s"}},
        {"ec8", {"ag_g", "type", "ground"}},
        {"is1893", {"pga_g", "soil"}},
    };
    return fields;
}

std::vector<std::pair<std::string, bool>> given(const DesignValues& v) {
    return {{"pga_g", v.pga_g.has_value()}, {"sds_g", v.sds_g.has_value()},
            {"sd1_g", v.sd1_g.has_value()}, {"tl_s", v.tl_s.has_value()},
            {"ag_g", v.ag_g.has_value()},   {"type", v.type.has_value()},
            {"ground", v.ground.has_value()}, {"soil", v.soil.has_value()}};
}

/// The value, required by the design and > 0; a design level also within the project's limit.
double required_positive(const std::optional<double>& v, const char* field,
                         const std::string& design, bool level) {
    const SourceLocation where{"", 0, field};
    if (!v) throw InputError(where, fmt::format("required by design {}", design));
    require_positive(*v, where);
    if (level)
        core::limits::require_within(*v, core::limits::max_design_level_g, where,
                                     "a design level (g)");
    return *v;
}

std::string required_text(const std::optional<std::string>& v, const char* field,
                          const std::string& design, const char* expected) {
    if (!v)
        throw InputError(SourceLocation{"", 0, field},
                         fmt::format("required by design {}; expected {}", design, expected));
    return *v;
}

spectra::Spectrum asce7(const DesignValues& v, const std::vector<double>& f) {
    const double sds = required_positive(v.sds_g, "sds_g", "asce7", true);
    const double sd1 = required_positive(v.sd1_g, "sd1_g", "asce7", true);
    const double tl = required_positive(v.tl_s, "tl_s", "asce7", false);
    if (!(tl > sd1 / sds))
        throw InputError(SourceLocation{"", 0, "tl_s"},
                         fmt::format("{} s; expected more than TS = SD1/SDS = {} s", tl,
                                     sd1 / sds));
    return spectra::asce7(sds, sd1, tl, f);
}

spectra::Spectrum ec8(const DesignValues& v, double damping, const std::vector<double>& f) {
    const double ag = required_positive(v.ag_g, "ag_g", "ec8", true);
    const std::string type = required_text(v.type, "type", "ec8", "1 or 2");
    if (type != "1" && type != "2")
        throw InputError(SourceLocation{"", 0, "type"},
                         fmt::format("\"{}\"; expected 1 or 2", type));
    const std::string ground = required_text(v.ground, "ground", "ec8", "A, B, C, D or E");
    if (ground.size() != 1 || ground[0] < 'A' || ground[0] > 'E')
        throw InputError(SourceLocation{"", 0, "ground"},
                         fmt::format("\"{}\"; expected A, B, C, D or E", ground));
    const auto t = type == "1" ? spectra::Ec8Type::type1 : spectra::Ec8Type::type2;
    return spectra::ec8(ag, t, ground[0], damping, f);
}

spectra::Spectrum is1893(const DesignValues& v, const std::vector<double>& f) {
    static const std::map<std::string, spectra::Is1893Soil> soils{
        {"rock", spectra::Is1893Soil::rock},
        {"medium", spectra::Is1893Soil::medium},
        {"soft", spectra::Is1893Soil::soft}};
    const std::string soil = required_text(v.soil, "soil", "is1893", "rock, medium or soft");
    if (!soils.count(soil))
        throw InputError(SourceLocation{"", 0, "soil"},
                         fmt::format("\"{}\"; expected rock, medium or soft", soil));
    return spectra::is1893(required_positive(v.pga_g, "pga_g", "is1893", true), soils.at(soil), f);
}

}  // namespace target_detail

const std::vector<std::string>& design_names() {
    static const std::vector<std::string> names{"rg1.60", "asce7", "ec8", "is1893"};
    return names;
}

void check_design(const std::string& design_field, const std::string& design,
                  const DesignValues& values) {
    const auto it = target_detail::design_fields().find(design);
    if (it == target_detail::design_fields().end())
        throw InputError(SourceLocation{"", 0, design_field},
                         fmt::format("unknown design \"{}\"; expected one of rg1.60, asce7, ec8, "
                                     "is1893",
                                     design));
    for (const auto& [field, present] : target_detail::given(values))
        if (present && !it->second.count(field))
            throw InputError(SourceLocation{"", 0, field},
                             fmt::format("does not apply to design {}", design));
}

spectra::Spectrum design_spectrum(const std::string& design_field, const std::string& design,
                                  const DesignValues& values, double damping, bool vertical,
                                  const std::vector<double>& f) {
    check_design(design_field, design, values);
    if (vertical && design != "rg1.60")
        throw InputError(SourceLocation{"", 0, "vertical"},
                         fmt::format("does not apply to design {}", design));
    if (design == "rg1.60")
        return spectra::rg160(target_detail::required_positive(values.pga_g, "pga_g", design, true),
                              damping, vertical, f);
    if (design == "asce7") return target_detail::asce7(values, f);
    if (design == "ec8") return target_detail::ec8(values, damping, f);
    return target_detail::is1893(values, f);
}

TargetResult target(const TargetRequest& request) {
    const std::string& design = request.design;
    check_design("design", design, request.values);
    const std::vector<double>& dampings = checked_dampings(request.dampings);
    std::vector<double> f = frequencies(request.grid);
    const SourceLocation at_damping{"", 0, "damping"};
    if ((design == "asce7" || design == "is1893") &&
        (dampings.size() != 1 || dampings[0] != 0.05))
        throw InputError(at_damping,
                         fmt::format("design {} is defined at 5% only; expected 0.05", design));
    std::vector<spectra::Spectrum> out;
    for (double d : dampings) {
        if (design == "rg1.60") require_in_range(d, 0.005, 0.10, at_damping);
        out.push_back(design_spectrum("design", design, request.values, d, request.vertical, f));
    }
    return {request, std::move(f), std::move(out)};
}

json to_json(const TargetResult& result) {
    std::vector<std::vector<double>> psa;
    psa.reserve(result.spectra.size());
    for (const auto& s : result.spectra) psa.push_back(s.psa_g);
    json j;
    j["design"] = result.request.design;
    j["labels"] = json::array();
    for (const auto& s : result.spectra) j["labels"].push_back(s.label);
    j["frequencies_hz"] = result.frequency_hz;
    j["psa_g"] = by_damping(result.request.dampings, psa);
    return j;
}

const std::string& design_source(const std::string& design) {
    static const std::map<std::string, std::string> source{
        {"rg1.60",
         "US NRC Regulatory Guide 1.60 Rev. 2, Tables I and II: control points A 33 Hz, "
         "B 9 Hz, C 2.5 Hz (vertical 3.5 Hz), D 0.25 Hz (36 in ground displacement per 1 g), "
         "log-log lines, PSA = PGA above 33 Hz, constant SD below 0.25 Hz (docs/methods.md s.8)"},
        {"asce7",
         "ASCE 7-16 section 11.4.6 design response spectrum: T0 = 0.2 SD1/SDS, TS = SD1/SDS, "
         "SD1/T to TL, SD1 TL/T^2 beyond (docs/methods.md s.8)"},
        {"ec8",
         "EN 1998-1:2004 3.2.2.2 horizontal elastic spectrum, eqs. (3.2)-(3.6), recommended "
         "S, TB, TC, TD of Tables 3.2 (Type 1) and 3.3 (Type 2) (docs/methods.md s.8)"},
        {"is1893",
         "IS 1893 (Part 1) Sa/g at 5% damping: 1 + 15 T below 0.1 s, 2.5 plateau, "
         "then 1.0/T, 1.36/T, 1.67/T (rock, medium, soft) to 4 s, constant beyond "
         "(docs/methods.md s.8)"},
    };
    return source.at(design);
}

const std::string& design_scaling(const std::string& design) {
    static const std::map<std::string, std::string> scaling{
        {"rg1.60",
         "PSA is proportional to PGA: multiply psa_g by the design PGA in g over the PGA of the "
         "label"},
        {"asce7", "PSA is proportional to SDS and SD1 scaled together (same TS); TL fixed"},
        {"ec8",
         "PSA is proportional to a_g: multiply psa_g by the design a_g in g over the a_g of the "
         "label"},
        {"is1893",
         "PSA is proportional to PGA: multiply psa_g by the design PGA in g over the PGA of the "
         "label"},
    };
    return scaling.at(design);
}

}  // namespace freestand::api
