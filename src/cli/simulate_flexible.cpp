// `freestand simulate --flexible`: the reduced-order flexible body (docs/methods.md s.10).
#include "cli/simulate_flexible.hpp"

#include <fmt/format.h>
#include <iostream>

#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/limits.hpp"

namespace freestand::cli {
namespace {

std::string series_csv(const dynamics::FlexibleResult& r, const std::string& label) {
    std::string out = fmt::format(
        "# freestand simulate (flexible body): {} integrator, excitation {}\n"
        "# units: time s, slide m (contact point relative to the base), rotation rad (+ on the "
        "right edge), modal displacement m (relative to the base, along the body)\n"
        "time_s,slide_m,rotation_rad,modal_m,mode\n",
        r.summary.base.integrator, label);
    for (const auto& s : r.series)
        out += fmt::format("{:.6f},{:.9g},{:.9g},{:.9g},{}\n", s.time_s, s.slide_m,
                           s.rotation_rad, s.modal_m, dynamics::mode_name(s.mode));
    return out;
}

// Central difference diverges once its step exceeds the elastic mode's stability limit
// (dynamics::cd_stable_step_s): refused before the run, in the options' own names.
void require_stable_cd(const dynamics::FlexibleModel& model, const dynamics::Excitation& excitation,
                       const dynamics::Options& options) {
    if (options.integrator != dynamics::Integrator::central_difference) return;
    if (model.frequency_hz >= dynamics::rigid_limit_hz(model, excitation)) return;
    const double h_s = dynamics::central_difference_step_s(excitation.dt_s, options.cd_dt_s);
    const double limit_s = dynamics::cd_stable_step_s(model, options.g_mps2);
    if (h_s <= limit_s) return;
    throw NumericalError(fmt::format(
        "--integrator cd: --dt {:.3g} s (a step of {:.3g} s on the input's samples) exceeds the "
        "stability limit {:.3g} s of the elastic mode at f = {} Hz (2 (sqrt(1 + 4 zeta^2) - "
        "2 zeta) / omega, the mode against the base where it is fastest); use --integrator event "
        "or --dt <= {:.3g}",
        options.cd_dt_s, h_s, limit_s, model.frequency_hz, limit_s));
}

// The model that ran and why (docs/methods.md s.10).
std::string model_reason(const dynamics::FlexibleModel& model, const dynamics::FlexibleSummary& s,
                         double rigid_hz) {
    if (s.rigid_handover)
        return fmt::format("the mode at {} Hz moves with the base (from {:.4g} Hz): the rigid "
                           "block ran", model.frequency_hz, rigid_hz);
    return fmt::format("the mode at {} Hz is below {:.4g} Hz, where it would move with the "
                       "base: the flexible body ran", model.frequency_hz, rigid_hz);
}

}  // namespace

dynamics::FlexibleMode parse_flexible_mode(const std::string& text) {
    const auto kv = parse_key_values(text, "--flexible", {"f", "zeta", "mass", "height"});
    if (!kv.count("f"))
        throw UsageError(fmt::format(
            "--flexible: expected f=HZ[,zeta=RATIO][,mass=FRACTION][,height=M]; got \"{}\"", text));
    dynamics::FlexibleMode m;
    m.frequency_hz = kv.at("f");
    if (kv.count("zeta")) m.damping = kv.at("zeta");
    if (kv.count("mass")) m.mass_fraction = kv.at("mass");
    if (kv.count("height")) m.height_m = kv.at("height");
    return m;
}

int run_flexible_simulation(const po::variables_map& vm, const dynamics::BlockModel& rigid,
                            const dynamics::Excitation& excitation,
                            const dynamics::Options& options) {
    dynamics::FlexibleModel model;
    try {
        model = dynamics::make_flexible_model(rigid, parse_flexible_mode(vm["flexible"].as<std::string>()));
    } catch (const InputError& e) {
        // The library names flexible.f etc.; here they came from --flexible.
        const std::string& field = e.where().field;
        if (field.rfind("flexible.", 0) != 0) throw;
        throw InputError({"", 0, "--flexible " + field.substr(9)}, e.message());
    }
    // The case key's limit (component.fixed_base_frequency_hz): a mode above it is not a
    // flexible body.
    core::limits::require_within(model.frequency_hz, core::limits::max_frequency_hz,
                                 {"", 0, "--flexible f"}, "fixed-base frequency (Hz)");
    require_stable_cd(model, excitation, options);
    const dynamics::FlexibleResult res = dynamics::simulate_flexible(model, excitation, options);
    const double rigid_hz = dynamics::rigid_limit_hz(model, excitation);
    if (vm.count("out"))
        core::write_file_atomic(vm["out"].as<std::string>(), series_csv(res, excitation.label));
    const dynamics::FlexibleSummary& s = res.summary;
    std::vector<std::string> assumptions;
    if (model.mass_fraction_default)
        assumptions.push_back(fmt::format(
            "modal mass {} M: first mode of a uniform cantilever", model.mass_fraction));
    if (model.height_default)
        assumptions.push_back(fmt::format(
            "modal height {:.4g} m: {} of the body's height, taken as the top height {:.4g} m "
            "(--top; 2 x the CG height when not given)",
            model.height_m, dynamics::cantilever_modal_height_ratio, rigid.top_height_m));
    if (vm["json"].as<bool>()) {
        nlohmann::ordered_json j;
        j["model"] = s.rigid_handover ? "rigid" : "flexible";
        j["model_reason"] = model_reason(model, s, rigid_hz);
        j["rigid_above_hz"] = rigid_hz;
        // The rigid top-corner acceleration does not apply: the modal mass's is given instead.
        nlohmann::ordered_json base = summary_json(s.base);
        base.erase("top_accel_max_g");
        base.erase("amplification");
        j.update(base);
        j["uplifted"] = s.uplifted;
        j["modal_max_m"] = s.modal_max_m;
        j["modal_drift_max"] = s.modal_drift_max;
        j["modal_accel_max_g"] = s.modal_accel_max_g;
        j["rejected_steps"] = s.rejected_steps;
        j["flexible_mode"] = {{"frequency_hz", model.frequency_hz},
                              {"damping", model.damping},
                              {"mass_fraction", model.mass_fraction},
                              {"height_m", model.height_m}};
        j["assumptions"] = assumptions;
        std::cout << j.dump(2) << "\n";
        return 0;
    }
    std::cout << fmt::format(
        "model                 flexible body: f {} Hz, zeta {}, modal mass {} M at {:.4g} m\n"
        "                      {}\n"
        "integrator            {}\n"
        "base uplifted         {}\n"
        "peak modal drift      {:.4g} m = {:.4g} of the modal height\n"
        "peak modal accel      {:.4g} g (PGA {:.4g} g)\n"
        "peak slide            {:.4g} m (residual {:.4g} m)\n"
        "peak rotation         {:.4g} rad = {:.3g} alpha\n"
        "overturned            {}\n"
        "impacts               {}\n"
        "wall time             {:.4g} s\n",
        model.frequency_hz, model.damping, model.mass_fraction, model.height_m,
        model_reason(model, s, rigid_hz), s.base.integrator, s.uplifted ? "yes" : "no", s.modal_max_m, s.modal_drift_max,
        s.modal_accel_max_g,
        s.base.pga_g, s.base.slide_max_m, s.base.slide_residual_m, s.base.rock_max_rad,
        s.base.rock_max_over_alpha,
        s.base.overturned
            ? fmt::format("yes, at {:.4f} s, mode {} ({})", *s.base.overturn_time_s,
                          *s.base.overturn_mode,
                          dynamics::overturn_criterion_name(s.base.overturn_criterion))
            : "no",
        s.base.impacts, s.base.wall_s);
    for (const auto& a : assumptions) std::cout << "assumption            " << a << "\n";
    return 0;
}

}  // namespace freestand::cli
