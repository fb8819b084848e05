// `freestand simulate --motion-y / --sine-y`: biaxial sliding's output (docs/methods.md s.10).
#include "cli/simulate_biaxial.hpp"

#include <fmt/format.h>
#include <iostream>

#include "cli/options.hpp"
#include "cli/series_label.hpp"
#include "core/errors.hpp"
#include "cli/usage_error.hpp"

namespace freestand::cli {
namespace simulate_biaxial_detail {

// "0.8g" -> 0.8 with suffix "g"; throws UsageError naming the option otherwise.
double with_suffix(std::string text, const std::string& suffix, const std::string& option) {
    if (text.size() > suffix.size() &&
        text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0)
        text.resize(text.size() - suffix.size());
    return parse_double(text, option);
}

}  // namespace simulate_biaxial_detail

std::string biaxial_series_csv(const api::BiaxialRun& run, const std::string& label) {
    const dynamics::BiaxialResult& r = run.result;
    std::string out = fmt::format(
        "# freestand simulate (biaxial sliding): {} integrator, excitation {}\n"
        "# units: time s, slip m, slip velocity m/s (relative to the base)\n"
        "time_s,slip_x_m,slip_y_m,v_x_mps,v_y_mps,mode\n",
        r.summary.integrator, one_line_label(label));
    for (const auto& s : r.series)
        out += fmt::format("{:.6f},{:.9g},{:.9g},{:.9g},{:.9g},{}\n", s.time_s, s.slip_x_m,
                           s.slip_y_m, s.v_x_mps, s.v_y_mps, dynamics::to_string(s.mode));
    return out;
}

void print_biaxial(const api::BiaxialRun& run) {
    const dynamics::BiaxialSummary& s = run.result.summary;
    const dynamics::BiaxialModel& m = run.model;
    std::cout << fmt::format(
        "model                 biaxial sliding (no rocking)\n"
        "integrator            {}\n"
        "peak slide |u|        {:.4g} m (x {:.4g} m, y {:.4g} m)\n"
        "residual slide        {:.4g} m (x {:.4g} m, y {:.4g} m)\n"
        "mode changes          {}\n"
        "peak |a_g|            {:.4g} g\n"
        "friction mu_s/mu_k    {} / {}\n"
        "steps                 {} (rejected {})\n"
        "wall time             {:.4g} s\n",
        s.integrator, s.slide_max_m, s.slide_max_x_m, s.slide_max_y_m, s.slide_residual_m,
        s.slide_residual_x_m, s.slide_residual_y_m, s.mode_changes, s.pga_g, m.mu_s, m.mu_k,
        s.steps, s.rejected_steps, s.wall_s);
}

dynamics::SineSpec parse_sine_spec(const std::string& text, const std::string& option,
                                   bool allow_phase) {
    const std::vector<std::string> parts = split_list(text);
    const std::string form = allow_phase ? "A g,f Hz,T s[,ramp=t s][,phase=DEG]"
                                         : "A g,f Hz,T s[,ramp=t s]";
    if (parts.size() < 3 || parts.size() > (allow_phase ? 5u : 4u))
        throw UsageError(fmt::format("{}: expected {}; got \"{}\"", option, form, text));
    using simulate_biaxial_detail::with_suffix;
    dynamics::SineSpec spec;
    spec.amplitude_g = with_suffix(parts[0], "g", option + " amplitude (g)");
    spec.frequency_hz = with_suffix(parts[1], "Hz", option + " frequency (Hz)");
    spec.duration_s = with_suffix(parts[2], "s", option + " duration (s)");
    const std::vector<std::string> tail(parts.begin() + 3, parts.end());
    const auto named = parse_key_texts(
        tail, option,
        allow_phase ? std::vector<std::string>{"ramp", "phase"} : std::vector<std::string>{"ramp"});
    if (const auto ramp = named.find("ramp"); ramp != named.end())
        spec.ramp_s = with_suffix(ramp->second, "s", option + " ramp (s)");
    if (const auto phase = named.find("phase"); phase != named.end())
        spec.phase_deg = parse_double(phase->second, option + " phase (degrees)");
    return spec;
}

}  // namespace freestand::cli
