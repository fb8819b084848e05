// `freestand simulate --model 3d`: the 3D body's output (docs/methods.md s.11).
#include "cli/simulate_body3d.hpp"

#include <fmt/format.h>
#include <iostream>

#include "cli/options.hpp"
#include "cli/series_label.hpp"
#include "cli/usage_error.hpp"

namespace freestand::cli {

api::Body3dSpec body3d_from_options(const std::string& block, double dt_s) {
    const auto keys = parse_key_values(block, "--block",
                                       {"b", "d", "h", "m", "height", "cgx", "cgy", "ixx", "iyy",
                                        "izz"});
    for (const char* k : {"b", "d", "h"})
        if (!keys.count(k))
            throw UsageError(fmt::format("--block: the 3D body needs b (half-width along x), d "
                                         "(half-width along y) and h (CG height); {} is missing",
                                         k));
    api::Body3dSpec spec;
    spec.half_x_m = keys.at("b");
    spec.half_y_m = keys.at("d");
    spec.cg_height_m = keys.at("h");
    if (keys.count("m")) spec.mass_kg = keys.at("m");
    if (keys.count("height")) spec.total_height_m = keys.at("height");
    if (keys.count("cgx")) spec.cg_x_m = keys.at("cgx");
    if (keys.count("cgy")) spec.cg_y_m = keys.at("cgy");
    const int inertia_keys =
        static_cast<int>(keys.count("ixx") + keys.count("iyy") + keys.count("izz"));
    if (inertia_keys == 3)
        spec.inertia_cg_kgm2 = std::array<double, 3>{keys.at("ixx"), keys.at("iyy"), keys.at("izz")};
    else if (inertia_keys != 0)
        throw UsageError("--block: give the inertia about the CG as all three of ixx, iyy and izz "
                         "(kg m^2), or none for the uniform box");
    spec.dt_s = dt_s;
    return spec;
}

std::string body3d_series_csv(const api::Body3dRun& run, const std::string& label) {
    std::string out = fmt::format(
        "# freestand simulate (3D body): Moreau-Jean, dt {} s, excitation {}\n"
        "# units: time s, slide m (footprint centre relative to the base), angles rad\n"
        "time_s,slide_x_m,slide_y_m,tilt_rad,tilt_over_critical,twist_rad,state{}\n",
        run.options.dt_s, one_line_label(label), run.model.mode ? ",modal_x_m,modal_y_m" : "");
    for (const auto& s : run.result.series)
        out += fmt::format("{:.6f},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{}{}\n", s.time_s, s.slide_x_m,
                           s.slide_y_m, s.tilt_rad, s.tilt_over_critical, s.twist_rad,
                           dynamics::to_string(s.state),
                           run.model.mode ? fmt::format(",{:.9g},{:.9g}", s.modal_x_m, s.modal_y_m)
                                          : std::string());
    return out;
}

void print_body3d(const api::Body3dRun& run) {
    const dynamics::Body3dSummary& s = run.result.summary;
    const auto& mode = run.model.mode;
    std::cout << fmt::format(
        "model                 3D {} (Moreau-Jean, dt {} s)\n"
        "peak tilt             {:.4g} rad = {:.3g} x critical\n"
        "overturned            {}\n"
        "peak slide |u|        {:.4g} m\n"
        "peak twist            {:.4g} rad\n"
        "peak |a_g|            {:.4g} g\n"
        "friction mu_s/mu_k    {} / {}\n"
        "steps                 {} (unconverged {})\n"
        "wall time             {:.4g} s\n",
        mode ? fmt::format("body with a mode along x and y: f {} / {} Hz, zeta {}, modal mass {} "
                           "M at {:.4g} m; peak |q| {:.4g} m",
                           mode->frequency_x_hz, mode->frequency_y_hz, mode->damping,
                           mode->mass_fraction, mode->height_m, s.modal_max_m)
             : std::string("rigid body"),
        run.options.dt_s, s.tilt_max_rad, s.tilt_max_over_critical,
        s.overturned ? fmt::format("yes, at {:.4f} s", *s.overturn_time_s) : std::string("no"),
        s.slide_max_m, s.twist_max_rad, s.pga_g, run.model.mu_s, run.model.mu_k, s.steps,
        s.unconverged_steps, s.wall_s);
    std::cout << "phases taken whole   ";
    for (std::size_t i = 0; i < dynamics::phase_kind_count; ++i)
        std::cout << fmt::format(" {} {:.3f} s", dynamics::to_string(static_cast<dynamics::Phase>(i)),
                                 s.phase_time_s[i]);
    std::cout << "\n";
    std::cout << "time in state        ";
    for (std::size_t i = 0; i < dynamics::contact_state_count; ++i)
        std::cout << fmt::format(" {} {:.3f} s",
                                 dynamics::to_string(static_cast<dynamics::ContactState>(i)),
                                 s.time_in_state_s[i]);
    std::cout << "\n";
}

}  // namespace freestand::cli
