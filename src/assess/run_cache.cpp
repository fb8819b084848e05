#include "assess/run_cache.hpp"

#include "core/bytes.hpp"
#include "core/sha256.hpp"
#include "motion/fingerprint.hpp"

namespace freestand::assess {

namespace {

// Raised when a key's or an encoding's layout below changes (old entries are then unused).
constexpr std::uint64_t format_version = 3;

// A field added to one of these must join its key or its encoding below: the sizes catch it.
static_assert(sizeof(block::Block) == 40, "block::Block changed: update write_model");
static_assert(sizeof(dynamics::BlockModel) == 80, "BlockModel changed: update write_model");
static_assert(sizeof(dynamics::FlexibleModel) == 128, "FlexibleModel changed: update its key");
static_assert(sizeof(dynamics::BiaxialModel) == 16, "BiaxialModel changed: update its key");
static_assert(sizeof(dynamics::Options) == 104, "dynamics::Options changed: update write_options");
static_assert(sizeof(dynamics::Summary) == 216, "Summary changed: update encode_summary");
static_assert(sizeof(dynamics::FlexibleSummary) == 256,
              "FlexibleSummary changed: update encode_flexible_summary");
static_assert(sizeof(dynamics::Body3d) == 112, "Body3d changed: update write_body3d_model");
static_assert(sizeof(dynamics::Body3dModel) == 200, "Body3dModel changed: update its key");
static_assert(sizeof(dynamics::Body3dOptions) == 88, "Body3dOptions changed: update its key");
static_assert(sizeof(dynamics::Body3dSummary) == 168,
              "Body3dSummary changed: update encode_body3d_summary");

void write_head(core::ByteWriter& w, std::string_view kind) {
    w.text("freestand run");
    w.u64(format_version);
    w.text(kind);
    w.text(engine_version);
    motion::append_build_fingerprint(w);
}

void write_model(core::ByteWriter& w, const dynamics::BlockModel& m) {
    const block::Block& b = m.block;
    for (double v : {b.mass_kg, b.b_left_m, b.b_right_m, b.h_m, b.inertia_cg_kgm2, m.mu_s, m.mu_k,
                     m.top_height_m})
        w.f64(v);
    w.opt_f64(m.restitution);
}

void write_options(core::ByteWriter& w, const dynamics::Options& o) {
    w.u64(static_cast<std::uint64_t>(o.integrator));
    for (double v : {o.cd_dt_s, o.rel_tol, o.abs_tol, o.max_contact_step_s, o.settle_rebound_rad,
                     o.settle_interval_s, o.flat_landing_window_s, o.tail_s, o.initial_rotation_rad,
                     o.initial_slide_velocity_mps, o.g_mps2})
        w.f64(v);
    w.flag(o.record_series);
}

void write_summary(core::ByteWriter& w, const dynamics::Summary& s) {
    w.text(s.integrator);
    for (double v : {s.slide_max_m, s.slide_residual_m, s.rock_max_rad, s.rock_max_over_alpha,
                     s.top_accel_max_g, s.pga_g, s.amplification, s.end_time_s, s.wall_s})
        w.f64(v);
    w.flag(s.overturned);
    w.opt_f64(s.overturn_time_s);
    w.flag(s.overturn_mode.has_value());
    w.i64(s.overturn_mode.value_or(0));
    w.u64(static_cast<std::uint64_t>(s.overturn_criterion));
    for (std::size_t n : {s.impacts, s.mode_changes, s.settlements, s.steps}) w.u64(n);
    for (double t : s.time_in_mode_s) w.f64(t);
}

dynamics::Summary read_summary(core::ByteReader& r) {
    dynamics::Summary s;
    s.integrator = r.text();
    for (double* v : {&s.slide_max_m, &s.slide_residual_m, &s.rock_max_rad, &s.rock_max_over_alpha,
                      &s.top_accel_max_g, &s.pga_g, &s.amplification, &s.end_time_s, &s.wall_s})
        *v = r.f64();
    s.overturned = r.flag();
    s.overturn_time_s = r.opt_f64();
    const bool has_mode = r.flag();
    const std::int64_t mode = r.i64();
    if (has_mode) s.overturn_mode = static_cast<int>(mode);
    s.overturn_criterion = static_cast<dynamics::OverturnCriterion>(r.u64());
    for (std::size_t* n : {&s.impacts, &s.mode_changes, &s.settlements, &s.steps})
        *n = static_cast<std::size_t>(r.u64());
    for (double& t : s.time_in_mode_s) t = r.f64();
    return s;
}

void write_body3d_model(core::ByteWriter& w, const dynamics::Body3dModel& m) {
    const dynamics::Body3d& b = m.body;
    w.f64(b.mass_kg);
    w.u64(b.footprint_m.size());
    for (const Eigen::Vector2d& v : b.footprint_m) {
        w.f64(v.x());
        w.f64(v.y());
    }
    w.f64(b.h_m);
    for (Eigen::Index i = 0; i < 9; ++i) w.f64(b.inertia_cg_kgm2(i));
    for (double v : {m.mu_s, m.mu_k, m.normal_restitution}) w.f64(v);
    w.opt_f64(m.angular_restitution);
    w.flag(m.mode.has_value());
    if (const auto& mode = m.mode)
        for (double v : {mode->frequency_x_hz, mode->frequency_y_hz, mode->damping,
                         mode->mass_fraction, mode->height_m})
            w.f64(v);
}

void write_body3d_options(core::ByteWriter& w, const dynamics::Body3dOptions& o) {
    for (double v : {o.dt_s, o.solver_tol, o.regularization, o.tail_s, o.initial_tilt_rad,
                     o.initial_lean_rad, o.max_step_p, o.g_mps2})
        w.f64(v);
    w.u64(o.max_sweeps);
    w.u64(o.arrival_substeps);
    w.flag(o.phases);
    w.flag(o.record_series);
}

template <class T>
T stored(const core::ContentStore* store, const std::string& key,
         std::optional<T> (*decode)(std::string_view), std::string (*encode)(const T&),
         const auto& make) {
    if (const std::optional<std::string> bytes = store->get(key))
        if (std::optional<T> hit = decode(*bytes)) return *hit;
    T made = make();
    store->put(key, encode(made));
    return made;
}

std::optional<double> decode_peak(std::string_view bytes) {
    core::ByteReader r(bytes);
    if (r.u64() != format_version) return std::nullopt;
    const double v = r.f64();
    if (r.failed() || !r.at_end()) return std::nullopt;
    return v;
}

std::string encode_peak(const double& v) {
    core::ByteWriter w;
    w.u64(format_version);
    w.f64(v);
    return w.take();
}

}  // namespace

std::string excitation_key(const dynamics::Excitation& ex) {
    core::ByteWriter w;
    w.text("planar excitation");
    w.f64(ex.dt_s);
    w.f64s(ex.horizontal_mps2);
    w.f64s(ex.vertical_mps2);
    return core::sha256_hex(w.bytes());
}

std::string excitation_key(const dynamics::BiaxialExcitation& ex) {
    core::ByteWriter w;
    w.text("biaxial excitation");
    w.f64(ex.dt_s);
    w.f64s(ex.x_mps2);
    w.f64s(ex.y_mps2);
    w.f64s(ex.vertical_mps2);
    return core::sha256_hex(w.bytes());
}

std::string rigid_run_key(const dynamics::BlockModel& model, const std::string& ex_key,
                          const dynamics::Options& opt) {
    core::ByteWriter w;
    write_head(w, "rigid planar block");
    write_model(w, model);
    write_options(w, opt);
    w.text(ex_key);
    return core::sha256_hex(w.bytes());
}

std::string flexible_run_key(const dynamics::FlexibleModel& model, const std::string& ex_key,
                             const dynamics::Options& opt) {
    core::ByteWriter w;
    write_head(w, "flexible body");
    write_model(w, model.rigid);
    for (double v : {model.frequency_hz, model.damping, model.mass_fraction, model.height_m,
                     model.impact_duration_s})
        w.f64(v);
    w.flag(model.mass_fraction_default);
    w.flag(model.height_default);
    write_options(w, opt);
    w.text(ex_key);
    return core::sha256_hex(w.bytes());
}

std::string biaxial_run_key(const dynamics::BiaxialModel& model, const std::string& ex_key,
                            const dynamics::Options& opt) {
    core::ByteWriter w;
    write_head(w, "biaxial block, peak |u|");
    w.f64(model.mu_s);
    w.f64(model.mu_k);
    write_options(w, opt);
    w.text(ex_key);
    return core::sha256_hex(w.bytes());
}

std::string body3d_run_key(const dynamics::Body3dModel& model, const std::string& ex_key,
                           const dynamics::Body3dOptions& opt) {
    core::ByteWriter w;
    write_head(w, "3D body");
    write_body3d_model(w, model);
    write_body3d_options(w, opt);
    w.text(ex_key);
    return core::sha256_hex(w.bytes());
}

std::string encode_summary(const dynamics::Summary& s) {
    core::ByteWriter w;
    w.u64(format_version);
    write_summary(w, s);
    return w.take();
}

std::optional<dynamics::Summary> decode_summary(std::string_view bytes) {
    core::ByteReader r(bytes);
    if (r.u64() != format_version) return std::nullopt;
    dynamics::Summary s = read_summary(r);
    if (r.failed() || !r.at_end()) return std::nullopt;
    return s;
}

std::string encode_flexible_summary(const dynamics::FlexibleSummary& s) {
    core::ByteWriter w;
    w.u64(format_version);
    write_summary(w, s.base);
    for (double v : {s.modal_max_m, s.modal_drift_max, s.modal_accel_max_g}) w.f64(v);
    w.flag(s.uplifted);
    w.flag(s.rigid_handover);
    w.u64(s.rejected_steps);
    return w.take();
}

std::optional<dynamics::FlexibleSummary> decode_flexible_summary(std::string_view bytes) {
    core::ByteReader r(bytes);
    if (r.u64() != format_version) return std::nullopt;
    dynamics::FlexibleSummary s;
    s.base = read_summary(r);
    for (double* v : {&s.modal_max_m, &s.modal_drift_max, &s.modal_accel_max_g}) *v = r.f64();
    s.uplifted = r.flag();
    s.rigid_handover = r.flag();
    s.rejected_steps = static_cast<std::size_t>(r.u64());
    if (r.failed() || !r.at_end()) return std::nullopt;
    return s;
}

std::string encode_body3d_summary(const dynamics::Body3dSummary& s) {
    core::ByteWriter w;
    w.u64(format_version);
    for (double v : {s.tilt_max_rad, s.tilt_max_over_critical, s.slide_max_m, s.twist_max_rad,
                     s.modal_max_m, s.end_time_s, s.pga_g, s.wall_s})
        w.f64(v);
    w.flag(s.overturned);
    w.opt_f64(s.overturn_time_s);
    for (double t : s.time_in_state_s) w.f64(t);
    for (double t : s.phase_time_s) w.f64(t);
    w.u64(s.steps);
    w.u64(s.unconverged_steps);
    return w.take();
}

std::optional<dynamics::Body3dSummary> decode_body3d_summary(std::string_view bytes) {
    core::ByteReader r(bytes);
    if (r.u64() != format_version) return std::nullopt;
    dynamics::Body3dSummary s;
    for (double* v : {&s.tilt_max_rad, &s.tilt_max_over_critical, &s.slide_max_m,
                      &s.twist_max_rad, &s.modal_max_m, &s.end_time_s, &s.pga_g, &s.wall_s})
        *v = r.f64();
    s.overturned = r.flag();
    s.overturn_time_s = r.opt_f64();
    for (double& t : s.time_in_state_s) t = r.f64();
    for (double& t : s.phase_time_s) t = r.f64();
    s.steps = static_cast<std::size_t>(r.u64());
    s.unconverged_steps = static_cast<std::size_t>(r.u64());
    if (r.failed() || !r.at_end()) return std::nullopt;
    return s;
}

dynamics::Summary rigid_run(const core::ContentStore* store, const dynamics::BlockModel& model,
                            const dynamics::Excitation& ex, const std::string& ex_key,
                            const dynamics::Options& opt) {
    const auto make = [&] { return dynamics::simulate(model, ex, opt).summary; };
    if (!store || opt.record_series) return make();
    return stored<dynamics::Summary>(store, rigid_run_key(model, ex_key, opt), decode_summary,
                                     encode_summary, make);
}

dynamics::FlexibleSummary flexible_run(const core::ContentStore* store,
                                       const dynamics::FlexibleModel& model,
                                       const dynamics::Excitation& ex, const std::string& ex_key,
                                       const dynamics::Options& opt) {
    const auto make = [&] { return dynamics::simulate_flexible(model, ex, opt).summary; };
    if (!store || opt.record_series) return make();
    return stored<dynamics::FlexibleSummary>(store, flexible_run_key(model, ex_key, opt),
                                             decode_flexible_summary, encode_flexible_summary,
                                             make);
}

double biaxial_peak_run(const core::ContentStore* store, const dynamics::BiaxialModel& model,
                        const dynamics::BiaxialExcitation& ex, const std::string& ex_key,
                        const dynamics::Options& opt) {
    const auto make = [&] {
        return dynamics::simulate_biaxial(model, ex, opt).summary.slide_max_m;
    };
    if (!store || opt.record_series) return make();
    return stored<double>(store, biaxial_run_key(model, ex_key, opt), decode_peak, encode_peak,
                          make);
}

dynamics::Body3dSummary body3d_run(const core::ContentStore* store,
                                   const dynamics::Body3dModel& model,
                                   const dynamics::BiaxialExcitation& ex,
                                   const std::string& ex_key, const dynamics::Body3dOptions& opt) {
    const auto make = [&] { return dynamics::simulate_body3d(model, ex, opt).summary; };
    if (!store || opt.record_series) return make();
    return stored<dynamics::Body3dSummary>(store, body3d_run_key(model, ex_key, opt),
                                           decode_body3d_summary, encode_body3d_summary, make);
}

}  // namespace freestand::assess
