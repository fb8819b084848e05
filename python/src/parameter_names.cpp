#include "parameter_names.hpp"

namespace freestand::python {

const std::map<std::string, std::string>& keyword_names() {
    static const std::map<std::string, std::string> names{
        // api::ClassifyRequest (and mu_s, av_g of the other requests)
        {"mu_s", "mu"},
        {"a_h_g", "a_g"},
        {"av_g", "av_g"},
        // api::FragilityRequest (its pga_g is the binding's to name: fragility's keyword is pga)
        {"samples", "samples"},
        {"pool", "pool"},
        {"seed", "seed"},
        {"threads", "threads"},
        {"cache", "cache"},
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
        {"box.half_width_m", "block['b']"},
        {"box.half_height_m", "block['h']"},
        {"box.mass_kg", "block['m']"},
        {"box.cg_offset_m", "cg['x']"},
        {"box.cg_height_m", "cg['h']"},
        {"box.inertia_cg_kgm2", "inertia"},
        // api::SimulateRequest
        {"mu_k", "mu_k"},
        {"restitution", "restitution"},
        {"top_height_m", "top"},
        {"cd_dt_s", "dt"},
        {"integrator", "integrator"},
        // api::SlideRequest and api::RockRequest
        {"pgd_m", "pgd_m"},
        {"pga_h_g", "pga_g"},
        {"fes_hz", "fes_hz"},
        {"v_ratio", "v_ratio"},
        {"pgv_mps", "pgv_mps"},
        {"fs_required", "fs_required"},
        {"fixed_base_hz", "fn_hz"},
        {"rock_band_hz", "rock_band_hz"},
        // api::AssessRequest's levels (assess::with_pga_levels)
        {"pga_levels", "pga_g"},
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
