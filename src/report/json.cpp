#include "report/json.hpp"

#include <nlohmann/json.hpp>
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>

#include "assess/verdict.hpp"
#include "core/file_io.hpp"
#include "dynamics/body3d.hpp"
#include "report/history_json.hpp"
#include "report/references.hpp"
#include "core/sha256.hpp"
#include "core/text_parse.hpp"
#include "core/version.hpp"

namespace freestand::report {

using nlohmann::ordered_json;
using namespace freestand::assess;

double round10(double v) {
    if (!std::isfinite(v) || v == 0.0) return v;
    // The 10-digit text of a value next to the ends of the double range reads back out of range
    // (1.797693135e+308 overflows); such a value is kept as it is.
    double rounded = v;
    return core::text::parse_double(fmt::format("{:.10g}", v), rounded) ? rounded : v;
}

ordered_json json_number(double v) {
    if (!std::isfinite(v)) return nullptr;
    return round10(v);
}

namespace {

ordered_json num(double v) { return json_number(v); }
ordered_json num(const std::optional<double>& v) { return v ? num(*v) : ordered_json(nullptr); }

ordered_json text_or_null(const std::string& s) {
    return s.empty() ? ordered_json(nullptr) : ordered_json(s);
}

ordered_json pair_json(const std::array<double, 2>& v) { return {num(v[0]), num(v[1])}; }

ordered_json verdict_json(const Verdict& v) {
    ordered_json j;
    j["verdict"] = verdict_text(v);
    j["kind"] = to_string(v.kind);
    j["failure"] = to_string(v.failure);
    j["no_motion"] = v.no_motion;
    // "no motion" is said instead of a ratio: no number that could be read as a margin.
    j["margin"] = num(v.margin);
    j["margin_basis"] = v.margin_basis;
    j["decided_by"] = to_string(v.decided_by);
    j["clearance_m"] = num(v.clearance_m);
    j["material"] = text_or_null(v.material);
    j["mechanism"] = text_or_null(v.mechanism);
    j["conditions"] = v.conditions;
    return j;
}

ordered_json level_ref_json(const Governing& g) {
    return {
        {"pga_g", num(g.pga_g)}, {"direction", to_string(g.direction)}, {"level_index", g.level}};
}

// A headline verdict with its one governing level; from_trial names the material whose trial
// the level belongs to (null: a level of the case's own base).
ordered_json headline_json(const Governing& g, const std::optional<std::string>& from_trial) {
    ordered_json j = verdict_json(g.verdict);
    ordered_json where = level_ref_json(g);
    where["from_material_trial"] = from_trial ? ordered_json(*from_trial) : ordered_json(nullptr);
    j["governing"] = where;
    return j;
}

ordered_json contact_json(const ContactBound& b) {
    return {{"mu_s", num(b.mu_s)},
            {"mu_k", num(b.mu_k)},
            {"restitution", num(b.restitution)},
            {"housner", b.housner}};
}

ordered_json bounds_json(const DirectionBounds& b) {
    return {{"sliding", contact_json(b.sliding)},
            {"rocking", contact_json(b.rocking)},
            {"restitution_lower", num(b.restitution_lower)}};
}

ordered_json check_json(const ScreenCheck& c) {
    return {{"applies", c.applies},
            {"passed", c.passed},
            {"text", c.text},
            {"margin", num(c.verdict.margin)},
            {"no_motion", c.verdict.no_motion}};
}

ordered_json screen_json(const Screen& s) {
    return {{"passed", s.passed},
            {"rest", check_json(s.rest)},
            {"slide", check_json(s.slide)},
            {"rock", check_json(s.rock)}};
}

ordered_json stats_json(const Stats& s) {
    return {{"mean", num(s.mean)}, {"p84", num(s.p84)}, {"max", num(s.max)}};
}

ordered_json exceedance_json(const Exceedance& e) {
    return {{"k", e.k}, {"n", e.n}, {"ci95", pair_json(e.ci95)}};
}

ordered_json rocking_runs_json(const std::optional<RockingRuns>& r, int histories) {
    if (!r) return nullptr;
    const bool standing = r->overturned < histories;
    return {{"bound", contact_json(r->bound)},
            {"rock_over_alpha", standing ? stats_json(r->over_alpha) : ordered_json(nullptr)},
            {"overturned", r->overturned}};
}

ordered_json settling_json(const std::optional<Settling>& s) {
    if (!s) return nullptr;
    return report::settling_json(*s);
}

ordered_json simulation_json(const std::optional<Simulation>& sim) {
    if (!sim) return nullptr;
    ordered_json j;
    j["histories"] = sim->histories;
    j["governing_statistic"] = "p84";
    j["bounds_differ"] = sim->bounds_differ;
    j["rocking_bound"] = contact_json(sim->rocking_bound);
    j["slide_m"] = stats_json(sim->slide_m);
    j["slide_residual_m"] = stats_json(sim->slide_residual_m);
    // Over the histories that stayed standing: none when every history overturned.
    const bool standing = sim->overturned < sim->histories;
    j["rock_over_alpha"] = standing ? stats_json(sim->rock_over_alpha) : ordered_json(nullptr);
    j["rock_rad"] = standing ? stats_json(sim->rock_rad) : ordered_json(nullptr);
    j["rocking_other_restitution"] = rocking_runs_json(sim->rocking_other, sim->histories);
    j["overturned"] = sim->overturned;
    j["overturn_ci"] = pair_json(sim->overturn_ci);
    j["slide_exceedances"] = exceedance_json(sim->slide_exceed);
    j["rock_exceedances"] = exceedance_json(sim->rock_exceed);
    j["amplification"] = stats_json(sim->amplification);
    j["governing_history"] = sim->governing_history;
    return j;
}

// Biaxial sliding of a simulated level (null when the level was not simulated); slide_m and
// ratio_to_planar are null when the biaxial model did not apply (reason says why).
ordered_json biaxial_json(const std::optional<BiaxialSlide>& b) {
    if (!b) return nullptr;
    return {{"ran", b->ran},
            {"reason", b->reason},
            {"slide_m", b->ran ? stats_json(b->slide_m) : ordered_json(nullptr)},
            {"planar_governing_m", b->ran ? num(b->planar_governing_m) : ordered_json(nullptr)},
            {"planar_direction", b->ran ? ordered_json(to_string(b->planar_direction))
                                        : ordered_json(nullptr)},
            {"ratio_to_planar", num(b->ratio)}};
}

// The rigid body in three dimensions at a simulated level (docs/methods.md s.11): null when the
// level was not simulated; the runs' fields null when it did not apply (reason says why).
ordered_json body3d_json(const std::optional<Body3dLevel>& b) {
    if (!b) return nullptr;
    ordered_json j;
    j["ran"] = b->ran;
    j["reason"] = b->reason;
    if (!b->ran) return j;
    j["dt_s"] = num(b->dt_s);
    j["unconverged_steps"] = b->unconverged_steps;
    j["step_check"] = nullptr;
    if (b->step_checked)
        j["step_check"] = {{"history", b->sim.governing_history + 1},
                           {"dt_s", num(b->dt_s)},
                           {"tilt_max_over_critical", num(b->run_tilt_over_critical)},
                           {"overturned", b->run_overturned},
                           {"slide_max_m", num(b->run_slide_m)},
                           {"check_dt_s", num(b->check_dt_s)},
                           {"check_tilt_max_over_critical", num(b->check_tilt_over_critical)},
                           {"check_overturned", b->check_overturned},
                           {"check_slide_max_m", num(b->check_slide_m)}};
    j["twist_rad"] = stats_json(b->twist_rad);
    j["flexible"] = b->flexible;
    j["mode"] = b->flexible ? ordered_json(b->mode_text) : ordered_json(nullptr);
    j["modal_m"] = b->flexible ? stats_json(b->modal_m) : ordered_json(nullptr);
    ordered_json states;
    for (std::size_t i = 0; i < b->time_in_state_s.size(); ++i)
        states[dynamics::to_string(static_cast<dynamics::ContactState>(i))] =
            num(b->time_in_state_s[i]);
    j["mean_time_in_state_s"] = states;
    j["planar_rock_over_alpha"] = num(b->planar_rock_over_alpha);
    j["planar_slide_m"] = num(b->planar_slide_m);
    j["rock_ratio_to_planar"] = num(b->rock_ratio);
    j["slide_ratio_to_planar"] = num(b->slide_ratio);
    j.update(simulation_json(b->sim));
    j.erase("amplification");  // not a 3D output
    j.erase("slide_residual_m");
    return j;
}

// The flexible-body simulation of a level (docs/methods.md s.10), null where it did not run.
ordered_json flexible_simulation_json(const std::optional<FlexibleSimulation>& f) {
    if (!f) return nullptr;
    ordered_json j;
    j["frequency_hz"] = num(f->frequency_hz);
    j["damping"] = num(f->damping);
    j["modal_mass_fraction"] = num(f->mass_fraction);
    j["modal_height_m"] = num(f->height_m);
    j["uplifted"] = f->uplifted;
    j["modal_m"] = stats_json(f->modal_m);
    j["modal_accel_g"] = stats_json(f->modal_accel_g);
    ordered_json sim = simulation_json(f->sim);
    sim.erase("amplification");  // the rigid top-corner measure; modal_accel_g replaces it
    j.update(sim);
    return j;
}

ordered_json level_json(const LevelResult& l) {
    ordered_json j;
    j["pga_g"] = num(l.pga_g);
    j["pga_v_g"] = num(l.pga_v_g);
    j["direction"] = to_string(l.direction);
    j["bounds"] = bounds_json(l.bounds);
    j["mode"] = to_string(l.initiation.mode);
    j["mode_lower_friction"] = to_string(l.initiation_lower.mode);
    j["a_ratio"] = num(l.initiation.a_ratio);
    j["mu_s"] = num(l.initiation.mu_s);
    j["tan_alpha"] = num(l.initiation.tan_alpha);
    j["mu_crit"] = num(l.initiation.mu_crit);
    j["flexible_flag"] = l.flexible.raised;
    j["flexible"] = {{"basis", l.flexible.basis},
                     {"band_lo_hz", num(l.flexible.band_lo_hz)},
                     {"band_hi_hz", num(l.flexible.band_hi_hz)},
                     {"peak_psa_in_band_g", num(l.flexible.peak_psa_in_band_g)},
                     {"uplift_a_g", num(l.flexible.uplift_a_g)},
                     {"reason", l.flexible.reason}};
    j["slide_mu_s"] = num(l.sliding.mu_s);
    j["mu_e"] = num(l.sliding.mu_e);
    j["c_s_mps2"] = num(l.sliding.c_s_mps2);
    j["f_es_hz"] = num(l.sliding.f_es_hz);
    j["delta_d_m"] = l.sliding.slide_energy_m ? num(l.sliding.delta_d_m) : ordered_json(nullptr);
    j["delta_d_source"] = l.sliding.delta_d_source;
    j["energy_highpass_hz"] = num(l.sliding.highpass_hz);
    j["slide_asce_m"] = num(l.sliding.slide_asce_m);
    j["slide_energy_m"] = num(l.sliding.slide_energy_m);
    j["sliding_reason"] = l.sliding.reason;
    j["amplification_estimate"] = num(l.rocking.amplification_estimate);
    const Rocking& rk = l.rocking;
    j["rocking"] = {{"alpha_rad", num(rk.alpha_rad)},
                    {"R_m", num(rk.R_m)},
                    {"p_radps", num(rk.p_radps)},
                    {"restitution", num(rk.restitution)},
                    {"uplift_a_g", num(rk.uplift_a_g)},
                    {"ishiyama_v_mps", num(rk.ishiyama_v_mps)},
                    {"pgv_mps", num(rk.pgv_mps)},
                    {"el_gate_exceeded", rk.gate_passed},
                    {"el_gate_g", num(rk.gate_g)},
                    {"el_theta_rad", num(rk.theta_rad)},
                    {"el_overturn_predicted", rk.overturn_predicted},
                    {"el_overturn_fs", num(rk.overturn_fs)},
                    {"el_spectral_margin", num(rk.spectral_margin)}};
    j["screen"] = screen_json(l.screen);
    j["simulated"] = l.simulation.has_value();
    j["simulation_reason"] = l.simulation_reason;
    j["model"] = l.model.empty() ? ordered_json(nullptr) : ordered_json(l.model);
    j["model_reason"] = l.model_reason.empty() ? ordered_json(nullptr) : ordered_json(l.model_reason);
    j["simulation"] = simulation_json(l.simulation);
    j["biaxial"] = biaxial_json(l.biaxial);
    j["body3d"] = body3d_json(l.body3d);
    j["flexible_simulation"] = flexible_simulation_json(l.flexible_simulation);
    j["n_sets"] = l.settling ? ordered_json(l.settling->n_sets) : ordered_json(nullptr);
    j["settled_fraction"] =
        l.settling ? num(l.settling->settled_fraction) : ordered_json(nullptr);
    j["settling"] = settling_json(l.settling);
    j["verdict"] = verdict_json(l.verdict);
    j["trail"] = l.trail;
    return j;
}

ordered_json upgrade_json(const Upgrade& up) {
    ordered_json j;
    j["needed"] = up.needed;
    j["recommended"] = up.recommended ? ordered_json(*up.recommended) : ordered_json(nullptr);
    ordered_json trials = ordered_json::array();
    for (const MaterialTrial& t : up.trials) {
        ordered_json tj;
        tj["material"] = t.material;
        tj["mu_s_range"] = pair_json(t.mu_s_range);
        tj["restitution"] = num(t.restitution);
        tj["passes"] = t.passes;
        tj["governing"] = level_ref_json(t.governing);
        tj["verdict"] = verdict_json(t.governing.verdict);
        trials.push_back(tj);
    }
    j["trials"] = trials;
    return j;
}

ordered_json case_json(const Case& c) {
    const Component& k = c.component;
    ordered_json comp;
    comp["name"] = k.name;
    comp["description"] = k.description;
    comp["mass_kg"] = num(k.mass_kg);
    comp["cg_height_m"] = num(k.cg_height_m);
    comp["height_m"] = num(k.body_height_m());
    comp["cg_to_edge_x_m"] = {num(k.x.b_left_m), num(k.x.b_right_m)};
    comp["cg_to_edge_y_m"] = {num(k.y.b_left_m), num(k.y.b_right_m)};
    comp["inertia_cg_x_kgm2"] = num(k.x.inertia_cg_kgm2);
    comp["inertia_cg_y_kgm2"] = num(k.y.inertia_cg_kgm2);
    comp["inertia_source"] = k.x.inertia_source;
    comp["uniform_block"] = k.uniform_block;
    comp["footprint"] = k.footprint;
    comp["fixed_base_frequency_hz"] = num(k.fixed_base_frequency_hz);
    comp["free_rocking_band_x_hz"] =
        k.x.free_rocking_band_hz ? pair_json(*k.x.free_rocking_band_hz) : ordered_json(nullptr);
    comp["free_rocking_band_y_hz"] =
        k.y.free_rocking_band_hz ? pair_json(*k.y.free_rocking_band_hz) : ordered_json(nullptr);
    comp["base_material"] =
        k.base.material.empty() ? ordered_json(nullptr) : ordered_json(k.base.material);
    comp["mu_s"] = num(k.base.mu_s);
    comp["mu_k"] = num(k.base.mu_k);
    comp["restitution"] = num(k.base.restitution);
    comp["mu_s_range"] = pair_json(k.base.mu_s_range);
    comp["mu_s_range_source"] = k.base.mu_s_range_source;
    comp["restitution_range"] =
        k.base.restitution_range ? pair_json(*k.base.restitution_range) : ordered_json(nullptr);
    comp["allowable_slide_m"] = num(k.allowable_slide_m);
    comp["allowable_relative_m"] = num(k.allowable_relative_m);
    comp["required_overturn_fs"] = num(k.required_overturn_fs);
    ordered_json site;
    site["design"] = c.site.design;
    ordered_json pga = ordered_json::array();
    for (double p : c.site.pga_g) pga.push_back(num(p));
    site["pga_g"] = pga;
    site["vertical_ratio"] = num(c.site.vertical_ratio);
    site["sliding_damping"] = num(c.site.sliding_damping);
    site["g_mps2"] = num(c.site.g_mps2);
    site["energy_highpass_hz"] =
        c.site.energy_table_displacement_m ? ordered_json(nullptr) : num(c.site.energy_highpass_hz);
    ordered_json table = ordered_json(nullptr);
    if (c.site.energy_table_displacement_m) {
        table = ordered_json::array();
        for (double v : *c.site.energy_table_displacement_m) table.push_back(num(v));
    }
    site["energy_table_displacement_m"] = table;
    ordered_json opt;
    opt["histories_per_level"] = c.options.histories_per_level;
    opt["seed"] = c.options.seed;
    ordered_json recs = ordered_json::array();
    for (const auto& p : c.options.seed_records) recs.push_back(p.filename().string());
    opt["seed_records"] = recs;
    opt["simulate"] = to_string(c.options.simulate);
    return ordered_json{{"component", comp}, {"site", site}, {"options", opt}};
}

}  // namespace

ordered_json settling_json(const Settling& s) {
    return {{"n_sets", s.n_sets},
            {"resamples", s.resamples},
            {"settled_fraction", num(s.settled_fraction)},
            {"settled", s.settled},
            {"batches", s.rounds},
            {"overturn_rate_upper",
             s.overturn_rate_upper ? num(*s.overturn_rate_upper) : ordered_json(nullptr)}};
}

std::vector<StampedInput> stamped_inputs(const Case& c) {
    std::vector<StampedInput> out;
    const std::filesystem::path dir = std::filesystem::path(c.file).parent_path();
    auto add = [&](const std::string& given, const std::filesystem::path& path) {
        out.push_back({given, core::sha256_hex(core::read_text_file(path))});
    };
    if (c.site.targets) {
        const UserTargets& u = *c.site.targets;
        auto target = [&](const TargetFile& t) {
            const std::filesystem::path p(t.given);
            add(t.given, p.is_absolute() ? p : dir / p);
        };
        target(u.h5);
        for (const auto* t : {&u.h10, &u.v, &u.y5, &u.y10})
            if (*t) target(**t);
    }
    for (const auto& r : c.options.seed_records) add(r.string(), r);
    return out;
}

ordered_json inputs_json(const std::vector<StampedInput>& inputs) {
    ordered_json out = ordered_json::array();
    for (const StampedInput& i : inputs) out.push_back({{"file", i.file}, {"sha256", i.sha256}});
    return out;
}

ordered_json stamp_json(const Stamp& stamp) {
    return {{"tool", "freestand"},
            {"version", stamp.tool_version},
            {"commit", stamp.commit},
            {"seed", stamp.seed},
            {"input_sha256", stamp.input_sha256},
            {"case_file", stamp.case_file},
            {"inputs", inputs_json(stamp.inputs)}};
}

Stamp stamp_from_json(const nlohmann::json& j) {
    Stamp s;
    s.tool_version = j.at("version").get<std::string>();
    s.commit = j.at("commit").get<std::string>();
    s.seed = j.at("seed").get<std::uint64_t>();
    s.input_sha256 = j.at("input_sha256").get<std::string>();
    s.case_file = j.at("case_file").get<std::string>();
    for (const auto& i : j.at("inputs"))
        s.inputs.push_back({i.at("file").get<std::string>(), i.at("sha256").get<std::string>()});
    return s;
}

Stamp make_stamp(const std::string& case_bytes, const std::string& case_file, std::uint64_t seed,
                 const std::string& commit) {
    return Stamp{core::version(), commit, core::sha256_hex(case_bytes), case_file, seed, {}};
}

ordered_json to_json(const AssessmentResult& r, const Stamp& stamp) {
    ordered_json j;
    j["verdict"] = verdict_text(r.overall.verdict);
    const std::optional<std::string> trial =
        r.overall_from_trial ? std::optional<std::string>(r.overall.verdict.material.empty()
                                                              ? r.upgrade.recommended.value_or("")
                                                              : r.overall.verdict.material)
                             : std::nullopt;
    j["overall"] = headline_json(r.overall, trial);
    j["own"] = headline_json(r.own, std::nullopt);
    ordered_json levels = ordered_json::array();
    for (const LevelResult& l : r.levels) levels.push_back(level_json(l));
    j["levels"] = levels;
    j["upgrade"] = upgrade_json(r.upgrade);
    j["histories_generated"] = r.histories_generated;
    j["simulations_run"] = r.simulations_run;
    ordered_json checks = ordered_json::array();
    for (const HistoryCheck& h : r.history_checks) {
        checks.push_back({{"history", h.history},
                          {"component", h.component},
                          {"method", h.method},
                          {"passed", h.acceptance.passed},
                          {"min_ratio", num(h.acceptance.min_ratio)},
                          {"max_ratio", num(h.acceptance.max_ratio)},
                          {"reason", h.acceptance.reason},
                          {"measures_at_1g", measures_json(h.acceptance)},
                          {"realism", realism_json(h.acceptance)}});
    }
    j["history_acceptance"] = checks;
    j["case"] = case_json(r.input);
    j["assumptions"] = r.assumptions;
    j["limits"] = r.limits;
    ordered_json refs = ordered_json::array();
    for (const Reference& ref : references())
        refs.push_back({{"key", ref.key}, {"text", ref.text}});
    j["references"] = refs;
    j["stamp"] = stamp_json(stamp);
    return j;
}

}  // namespace freestand::report
