#include "parameter_names.hpp"

namespace freestand::python {

const std::map<std::string, std::string>& keyword_names() {
    static const std::map<std::string, std::string> names{
        // api::ClassifyRequest
        {"mu_s", "mu"},
        {"a_h_g", "a_g"},
        {"av_g", "av_g"},
        // api::SpectrumRequest and api::TargetRequest: dampings and the frequency grid
        {"damping", "damping"},
        {"frequency_hz", "frequencies"},
        {"fmin_hz", "fmin"},
        {"fmax_hz", "fmax"},
        {"per_decade", "per_decade"},
        // api::DesignValues, behind design_target's and generate's design values
        {"design", "design"},
        {"vertical", "vertical"},
        {"pga_g", "pga"},
        {"sds_g", "sds"},
        {"sd1_g", "sd1"},
        {"tl_s", "tl"},
        {"ag_g", "ag"},
        {"type", "type"},
        {"ground", "ground"},
        {"soil", "soil"},
        // api::GenerateRequest and motion::GenerateOptions
        {"target", "target"},
        {"target_file", "target_file"},
        {"vertical_ratio", "vertical_ratio"},
        {"seed_records", "seed_record"},
        {"components", "components"},
        {"duration_s", "duration"},
        {"dt_s", "dt"},
        {"va_range_mps_per_g", "va_range"},
        {"adv2_range", "adv2_range"},
        {"da_max_m_per_g", "da_max"},
        // sliding::BoxSpec, behind block= , cg= and inertia=
        {"b (half-width, m)", "block['b']"},
        {"h (half-height, m)", "block['h']"},
        {"m", "block['m']"},
        {"cg x", "cg['x']"},
        {"cg h", "cg['h']"},
        {"inertia", "inertia"},
    };
    return names;
}

InputError in_python(const InputError& e) {
    const SourceLocation& w = e.where();
    if (!w.file.empty() || w.line != 0) return e;
    const auto it = keyword_names().find(w.field);
    if (it == keyword_names().end()) return e;
    return InputError(SourceLocation{"", 0, it->second}, e.message());
}

}  // namespace freestand::python
