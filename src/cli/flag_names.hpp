#pragma once
/// The one place that maps a library parameter named in an InputError to the command-line
/// option a user typed, so that the libraries name parameters and never command-line flags.
#include <map>
#include <string>

#include "core/errors.hpp"

namespace freestand::cli {

/// Library parameter -> command-line option.
inline const std::map<std::string, std::string>& flag_names() {
    static const std::map<std::string, std::string> names{
        {"mu_s", "--mu"},
        {"a_h_g", "--a-g"},
        {"av_g", "--av-g"},
        {"mu_k", "--mu-k"},
        {"restitution", "--restitution"},
        {"top_height_m", "--top"},
        {"sine.amplitude_g", "--sine amplitude (g)"},
        {"sine.frequency_hz", "--sine frequency (Hz)"},
        {"sine.duration_s", "--sine duration (s)"},
        {"sine.ramp_s", "--sine ramp (s)"},
        {"sine.dt_s", "--sine dt (s)"},
        {"cd_dt_s", "--dt"},
        {"pga_levels", "--pga"},
        // fragility::Config, behind fragility's options; spectra's design levels, behind --pga
        {"pga_g", "--pga"},
        {"samples", "--samples"},
        {"pool", "--pool"},
        // motion::GenerateOptions, behind generate's options
        {"dt_s", "--dt"},
        {"duration_s", "--duration"},
        {"components", "--components"},
        {"seed_records", "--seed-record"},
        {"frequency_hz", "--frequencies"},
        {"damping", "--damping"},
        // api::TargetRequest and api::GenerateRequest: the design and its values
        {"design", "--design"},
        {"target", "--target"},
        {"target_file", "--target-file"},
        {"vertical", "--vertical"},
        {"sds_g", "--sds"},
        {"sd1_g", "--sd1"},
        {"tl_s", "--tl"},
        {"ag_g", "--ag"},
        {"type", "--type"},
        {"ground", "--ground"},
        {"soil", "--soil"},
        // motion::RealismLimits, behind generate's realism options
        {"va_range_mps_per_g", "--va-range"},
        {"adv2_range", "--adv2-range"},
        {"da_max_m_per_g", "--da-max"},
        {"vertical_ratio", "--vertical-ratio"},
        // spectra::log_frequencies, behind --fmin, --fmax and --per-decade
        {"fmin_hz", "--fmin"},
        {"fmax_hz", "--fmax"},
        {"per_decade", "--per-decade"},
        // block::Block and sliding::box_spec, behind --block, --cg and --inertia
        {"b (half-width, m)", "--block b (half-width, m)"},
        {"h (half-height, m)", "--block h (half-height, m)"},
        {"h (CG height, m)", "--block h (CG height, m)"},
        {"m (mass, kg)", "--block m (mass, kg)"},
        {"m", "--block m (mass, kg)"},
        {"block b", "--block b"},
        {"block h", "--block h"},
        {"cg x", "--cg x (right of the base's centre, m)"},
        {"cg h", "--cg h (height, m)"},
        {"inertia", "--inertia"},
        {"I_c (inertia about CG, kg m^2)", "--inertia (I_c about the CG, kg m^2)"},
        {"b_left (CG to left edge, m)", "--cg (CG to the left edge, m)"},
        {"b_right (CG to right edge, m)", "--cg (CG to the right edge, m)"},
    };
    return names;
}

/// The error as the command line should show it: a location-less parameter renamed to its
/// option; anything else unchanged.
inline InputError on_command_line(const InputError& e) {
    const SourceLocation& w = e.where();
    if (!w.file.empty() || w.line != 0) return e;
    const auto it = flag_names().find(w.field);
    if (it == flag_names().end()) return e;
    return InputError(SourceLocation{"", 0, it->second}, e.message());
}

}  // namespace freestand::cli
