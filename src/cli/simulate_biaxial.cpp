// `freestand simulate --motion-y / --sine-y`: biaxial sliding (docs/methods.md s.10).
#include "cli/simulate_biaxial.hpp"

#include <fmt/format.h>
#include <iostream>
#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/readers.hpp"

namespace freestand::cli {
namespace {

// "0.8g" -> 0.8 with suffix "g"; throws UsageError naming the option otherwise.
double with_suffix(std::string text, const std::string& suffix, const std::string& option) {
    if (text.size() > suffix.size() &&
        text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0)
        text.resize(text.size() - suffix.size());
    return parse_double(text, option);
}

dynamics::BiaxialExcitation excitation_of(const po::variables_map& vm) {
    if (vm.count("sine-y")) {
        const dynamics::SineSpec spec =
            parse_sine_spec(vm["sine-y"].as<std::string>(), "--sine-y", true);
        try {
            return dynamics::biaxial_sine_excitation(spec, spec.phase_deg);
        } catch (const InputError& e) {
            // The library names sine.amplitude_g etc.; here they came from --sine-y.
            const std::string& field = e.where().field;
            if (!e.where().file.empty() || field.rfind("sine.", 0) != 0) throw;
            throw InputError({"", 0, "--sine-y " + field.substr(5)}, e.message());
        }
    }
    const std::vector<std::string> files = split_list(vm["motion"].as<std::string>());
    if (files.size() > 2 || files[0].empty() || (files.size() == 2 && files[1].empty()))
        throw UsageError(fmt::format("--motion: expected FILE[,VERTICAL_FILE]; got \"{}\"",
                                     vm["motion"].as<std::string>()));
    const std::string y_file = vm["motion-y"].as<std::string>();
    if (y_file.empty()) throw UsageError("--motion-y: expected a record FILE; got \"\"");
    const core::Record x = core::read_record(files[0]);
    const core::Record y = core::read_record(y_file);
    const double scale = vm["scale"].as<double>();
    if (files.size() == 1) return dynamics::biaxial_excitation_from_records(x, y, scale);
    const core::Record v = core::read_record(files[1]);
    return dynamics::biaxial_excitation_from_records(x, y, scale, &v);
}

std::string series_csv(const dynamics::BiaxialResult& r, const std::string& label) {
    std::string out = fmt::format(
        "# freestand simulate (biaxial sliding): {} integrator, excitation {}\n"
        "# units: time s, slip m, slip velocity m/s (relative to the base)\n"
        "time_s,slip_x_m,slip_y_m,v_x_mps,v_y_mps,mode\n",
        r.summary.integrator, label);
    for (const auto& s : r.series)
        out += fmt::format("{:.6f},{:.9g},{:.9g},{:.9g},{:.9g},{}\n", s.time_s, s.slip_x_m,
                           s.slip_y_m, s.v_x_mps, s.v_y_mps, dynamics::mode_name(s.mode));
    return out;
}

nlohmann::ordered_json summary_json(const dynamics::BiaxialSummary& s) {
    nlohmann::ordered_json j;
    j["model"] = "biaxial_sliding";
    j["slide_max_m"] = s.slide_max_m;
    j["slide_max_x_m"] = s.slide_max_x_m;
    j["slide_max_y_m"] = s.slide_max_y_m;
    j["slide_residual_m"] = s.slide_residual_m;
    j["slide_residual_x_m"] = s.slide_residual_x_m;
    j["slide_residual_y_m"] = s.slide_residual_y_m;
    j["mode_changes"] = s.mode_changes;
    j["wall_s"] = s.wall_s;
    j["integrator"] = s.integrator;
    nlohmann::ordered_json t;
    for (auto m : {dynamics::Mode::rest, dynamics::Mode::slide, dynamics::Mode::flight})
        t[dynamics::mode_name(m)] = s.time_in_mode_s[static_cast<std::size_t>(m)];
    j["time_in_mode_s"] = t;
    j["pga_g"] = s.pga_g;
    j["steps"] = s.steps;
    j["rejected_steps"] = s.rejected_steps;
    j["end_time_s"] = s.end_time_s;
    return j;
}

void print_text(const dynamics::BiaxialSummary& s, const dynamics::BiaxialModel& m) {
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

}  // namespace

dynamics::SineSpec parse_sine_spec(const std::string& text, const std::string& option,
                                   bool allow_phase) {
    const std::vector<std::string> parts = split_list(text);
    const std::string form = allow_phase ? "A g,f Hz,T s[,ramp=t s][,phase=DEG]"
                                         : "A g,f Hz,T s[,ramp=t s]";
    if (parts.size() < 3 || parts.size() > (allow_phase ? 5u : 4u))
        throw UsageError(fmt::format("{}: expected {}; got \"{}\"", option, form, text));
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

int run_biaxial_simulation(const po::variables_map& vm, const block::Block& block,
                           const dynamics::Options& options) {
    for (const char* flag : {"restitution", "top"})
        if (vm.count(flag))
            throw UsageError(fmt::format("--{}: not used by the biaxial model (--motion-y, "
                                         "--sine-y), which has no rocking",
                                         flag));
    std::optional<double> mu_k;
    if (vm.count("mu-k")) mu_k = vm["mu-k"].as<double>();
    const dynamics::BiaxialModel model = dynamics::make_biaxial_model(vm["mu"].as<double>(), mu_k);
    const dynamics::BiaxialExcitation exc = excitation_of(vm);
    // Refuse rather than warn: a block that rocks is outside the model, whose sliding answer
    // would then be wrong on the unsafe side (docs/methods.md s.10).
    if (const auto why = dynamics::biaxial_rocking_reason(block, model, exc, options.g_mps2))
        throw InputError({"", 0, vm.count("sine-y") ? "--sine-y" : "--motion-y"},
                         fmt::format("the biaxial model has no rocking and this block (--block, "
                                     "--mu, --mu-k) would rock: {}; simulate each direction with "
                                     "the planar model (--motion or --sine)",
                                     *why));
    const dynamics::BiaxialResult res = dynamics::simulate_biaxial(model, exc, options);
    if (vm.count("out"))
        core::write_file_atomic(vm["out"].as<std::string>(), series_csv(res, exc.label));
    if (vm["json"].as<bool>()) {
        std::cout << summary_json(res.summary).dump(2) << "\n";
    } else {
        print_text(res.summary, model);
    }
    return 0;
}

}  // namespace freestand::cli
