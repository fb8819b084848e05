// `simulate --json`'s documents, one per model (api/simulate.hpp).
#include <fmt/format.h>

#include <array>
#include <initializer_list>

#include "api/simulate.hpp"

namespace freestand::api {
namespace simulate_json_detail {

/// Seconds spent in each of `modes`, keyed by the mode's name.
json time_in_mode_json(const std::array<double, dynamics::mode_count>& time_in_mode_s,
                       std::initializer_list<dynamics::Mode> modes) {
    json t;
    for (dynamics::Mode m : modes)
        t[dynamics::to_string(m)] = time_in_mode_s[static_cast<std::size_t>(m)];
    return t;
}

json biaxial_json(const dynamics::BiaxialSummary& s) {
    json j;
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
    // Biaxial sliding never rocks: its summary has no rock or slide-rock time.
    j["time_in_mode_s"] = time_in_mode_json(
        s.time_in_mode_s, {dynamics::Mode::rest, dynamics::Mode::slide, dynamics::Mode::flight});
    j["pga_g"] = s.pga_g;
    j["steps"] = s.steps;
    j["rejected_steps"] = s.rejected_steps;
    j["end_time_s"] = s.end_time_s;
    return j;
}

json flexible_json(const FlexibleRun& run, const std::string& top_height_name) {
    const dynamics::FlexibleSummary& s = run.result.summary;
    const dynamics::FlexibleModel& model = run.model;
    json j;
    j["model"] = s.rigid_handover ? "rigid" : "flexible";
    j["model_reason"] = model_reason(run);
    j["rigid_above_hz"] = run.rigid_above_hz;
    // The rigid top-corner acceleration does not apply: the modal mass's is given instead.
    json base = to_json(s.base);
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
    j["assumptions"] = assumptions(run, top_height_name);
    return j;
}

json pair_json(const PairRun& run) {
    const dynamics::PairResult& r = run.result;
    json j;
    j["relative_max_m"] = r.relative_max_m;
    j["relative_max_time_s"] = r.relative_max_time_s;
    j["relative_residual_m"] = r.relative_residual_m;
    j["tunnel_height_m"] = run.tunnel_height_m;
    j["overturned"] = r.overturned;
    j["sampled_at"] = "the input samples";
    j["model"] = "two rigid planar blocks under the same base motion (docs/methods.md s.10)";
    j["unit1"] = to_json(r.units[0]);
    j["unit2"] = to_json(r.units[1]);
    return j;
}

json body3d_json(const Body3dRun& run) {
    const dynamics::Body3dSummary& s = run.result.summary;
    json j;
    j["model"] = "3d";
    j["integrator"] = "moreau-jean";
    j["dt_s"] = run.options.dt_s;
    j["phases"] = run.options.phases;
    j["tilt_max_rad"] = s.tilt_max_rad;
    j["tilt_max_over_critical"] = s.tilt_max_over_critical;
    j["overturned"] = s.overturned;
    j["overturn_time_s"] = number_or_null(s.overturn_time_s);
    j["slide_max_m"] = s.slide_max_m;
    j["twist_max_rad"] = s.twist_max_rad;
    if (const auto& mode = run.model.mode) {
        j["mode"] = {{"frequency_x_hz", mode->frequency_x_hz},
                     {"frequency_y_hz", mode->frequency_y_hz},
                     {"damping", mode->damping},
                     {"mass_fraction", mode->mass_fraction},
                     {"height_m", mode->height_m}};
        j["modal_max_m"] = s.modal_max_m;
    } else {
        j["mode"] = nullptr;
        j["modal_max_m"] = nullptr;
    }
    json t;
    for (std::size_t i = 0; i < dynamics::contact_state_count; ++i)
        t[dynamics::to_string(static_cast<dynamics::ContactState>(i))] = s.time_in_state_s[i];
    j["time_in_state_s"] = t;
    j["pga_g"] = s.pga_g;
    j["steps"] = s.steps;
    j["unconverged_steps"] = s.unconverged_steps;
    json phases;
    for (std::size_t i = 0; i < dynamics::phase_kind_count; ++i)
        phases[dynamics::to_string(static_cast<dynamics::Phase>(i))] = s.phase_time_s[i];
    j["phase_time_s"] = phases;
    j["end_time_s"] = s.end_time_s;
    j["wall_s"] = s.wall_s;
    j["friction"] = {{"mu_s", run.model.mu_s}, {"mu_k", run.model.mu_k}};
    return j;
}

}  // namespace simulate_json_detail

json to_json(const dynamics::Summary& s) {
    json j;
    j["slide_max_m"] = s.slide_max_m;
    j["slide_residual_m"] = s.slide_residual_m;
    j["rock_max_rad"] = s.rock_max_rad;
    j["rock_max_over_alpha"] = s.rock_max_over_alpha;
    j["overturned"] = s.overturned;
    j["overturn_time_s"] = number_or_null(s.overturn_time_s);
    j["overturn_mode"] = s.overturn_mode ? json(*s.overturn_mode) : json(nullptr);
    j["impacts"] = s.impacts;
    j["mode_changes"] = s.mode_changes;
    j["top_accel_max_g"] = s.top_accel_max_g;
    j["amplification"] = s.amplification;
    j["wall_s"] = s.wall_s;
    j["integrator"] = s.integrator;
    j["overturn_criterion"] = dynamics::overturn_criterion_name(s.overturn_criterion);
    static_assert(dynamics::mode_count == 5, "every mode is listed below");
    j["time_in_mode_s"] = simulate_json_detail::time_in_mode_json(
        s.time_in_mode_s, {dynamics::Mode::rest, dynamics::Mode::slide, dynamics::Mode::rock,
                           dynamics::Mode::slide_rock, dynamics::Mode::flight});
    j["pga_g"] = s.pga_g;
    j["settlements"] = s.settlements;
    j["steps"] = s.steps;
    j["end_time_s"] = s.end_time_s;
    return j;
}

std::string model_reason(const FlexibleRun& run) {
    const double f_hz = run.model.frequency_hz;
    if (run.result.summary.rigid_handover)
        return fmt::format("the mode at {} Hz moves with the base (from {:.4g} Hz): the rigid "
                           "block ran", f_hz, run.rigid_above_hz);
    return fmt::format("the mode at {} Hz is below {:.4g} Hz, where it would move with the "
                       "base: the flexible body ran", f_hz, run.rigid_above_hz);
}

std::vector<std::string> assumptions(const FlexibleRun& run, const std::string& top_height_name) {
    const dynamics::FlexibleModel& model = run.model;
    std::vector<std::string> out;
    if (model.mass_fraction_default)
        out.push_back(fmt::format("modal mass {} M: first mode of a uniform cantilever",
                                  model.mass_fraction));
    if (model.height_default)
        out.push_back(fmt::format(
            "modal height {:.4g} m: {} of the body's height, taken as the top height {:.4g} m "
            "({}; 2 x the CG height when not given)",
            model.height_m, dynamics::cantilever_modal_height_ratio, model.rigid.top_height_m,
            top_height_name));
    return out;
}

json to_json(const SimulateResult& result, const std::string& top_height_name) {
    using namespace simulate_json_detail;
    struct Visitor {
        const std::string& top_name;
        json operator()(const PlanarRun& r) const { return to_json(r.result.summary); }
        json operator()(const BiaxialRun& r) const { return biaxial_json(r.result.summary); }
        json operator()(const FlexibleRun& r) const { return flexible_json(r, top_name); }
        json operator()(const PairRun& r) const { return pair_json(r); }
        json operator()(const Body3dRun& r) const { return body3d_json(r); }
    };
    return std::visit(Visitor{top_height_name}, result.run);
}

}  // namespace freestand::api
