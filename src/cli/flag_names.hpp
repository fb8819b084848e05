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
        // api::FragilityRequest and api::CacheRequest, behind the run options
        {"threads", "--threads"},
        {"shard", "--shard"},
        {"sets", "--sets"},
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
        // sliding::BoxSpec (api requests' box), behind --block, --cg and --inertia
        {"box.half_width_m", "--block b (half-width, m)"},
        {"box.half_height_m", "--block h (half-height, m)"},
        {"box.mass_kg", "--block m (mass, kg)"},
        {"box.cg_offset_m", "--cg x (right of the base's centre, m)"},
        {"box.cg_height_m", "--cg h (height, m)"},
        {"box.inertia_cg_kgm2", "--inertia"},
        {"block b", "--block b"},
        {"block h", "--block h"},
        // api::SimulateRequest's second unit, behind --block2 .. --tunnel-height
        {"unit2.box.half_width_m", "--block2 b (half-width, m)"},
        {"unit2.box.half_height_m", "--block2 h (half-height, m)"},
        {"unit2.box.mass_kg", "--block2 m (mass, kg)"},
        {"unit2.box.cg_offset_m", "--cg2 x (right of the base's centre, m)"},
        {"unit2.box.cg_height_m", "--cg2 h (height, m)"},
        {"unit2.box.inertia_cg_kgm2", "--inertia2"},
        {"unit2.block b", "--block2 b"},
        {"unit2.block h", "--block2 h"},
        {"unit2.mu_s", "--mu2"},
        {"unit2.mu_k", "--mu-k2 (at most --mu2)"},
        {"unit2.restitution", "--restitution2"},
        {"tunnel_height_m", "--tunnel-height (m)"},
        // api::SimulateRequest's excitation and models
        {"sine_y.amplitude_g", "--sine-y amplitude (g)"},
        {"sine_y.frequency_hz", "--sine-y frequency (Hz)"},
        {"sine_y.duration_s", "--sine-y duration (s)"},
        {"sine_y.ramp_s", "--sine-y ramp (s)"},
        {"sine_y.dt_s", "--sine-y dt (s)"},
        {"sine_y.phase_deg", "--sine-y phase (degrees)"},
        {"sine_y", "--sine-y"},
        {"motion_y", "--motion-y"},
        {"flexible.f", "--flexible f"},
        {"flexible.zeta", "--flexible zeta"},
        {"flexible.mass", "--flexible mass"},
        {"flexible.height", "--flexible height"},
        {"integrator", "--integrator"},
        // api::Body3dSpec, behind --model 3d's --block and --dt
        {"body3d", "--model 3d"},
        {"body3d.half_x_m", "--block b (half-width along x, m)"},
        {"body3d.half_y_m", "--block d (half-width along y, m)"},
        {"body3d.h_m", "--block h (CG height, m)"},
        {"body3d.mass_kg", "--block m (mass, kg)"},
        {"body3d.total_height_m", "--block height (total height, m)"},
        {"body3d.cg_x_m", "--block cgx (CG offset along x from the footprint's centre, m)"},
        {"body3d.cg_y_m", "--block cgy (CG offset along y from the footprint's centre, m)"},
        {"body3d.inertia_cg_kgm2", "--block ixx, iyy, izz (inertia about the CG, kg m^2)"},
        {"body3d.dt_s", "--dt"},
        // api::SlideRequest and api::RockRequest
        {"pgd_m", "--pgd-m"},
        {"pga_h_g", "--pga-g"},
        {"fes_hz", "--fes-hz"},
        {"v_ratio", "--v-ratio"},
        {"pgv_mps", "--pgv-mps"},
        {"fs_required", "--fs-required"},
        {"fixed_base_hz", "--fn-hz"},
        {"rock_band_hz", "--rock-band-hz"},
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
