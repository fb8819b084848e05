#include "api/simulate.hpp"

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/limits.hpp"

namespace freestand::api {
namespace simulate_detail {

SourceLocation field(const std::string& name) { return SourceLocation{"", 0, name}; }

bool biaxial(const SimulateExcitation& e) { return e.horizontal_y || e.sine_y; }

// One source of base motion, and the models that take it (docs/methods.md s.10: the biaxial
// model has no rocking; the flexible body and the joined pair are planar).
void require_consistent(const SimulateRequest& r) {
    const SimulateExcitation& e = r.excitation;
    const int sources = (e.horizontal ? 1 : 0) + (e.sine ? 1 : 0) + (e.sine_y ? 1 : 0);
    if (sources != 1)
        throw InputError(field("excitation"),
                         "expected exactly one of a horizontal record, sine and sine_y");
    if ((e.vertical || e.horizontal_y) && !e.horizontal)
        throw InputError(field("excitation"), "a vertical or y record needs the horizontal one");
    if (r.flexible && ((biaxial(e) && !r.body3d) || r.unit2))
        throw InputError(field("flexible"),
                         "the planar flexible body runs alone (no y component, no second unit; "
                         "the 3D body carries the mode under both)");
    if (r.unit2 && biaxial(e))
        throw InputError(field("unit2"), "the joined pair is planar (no y component)");
    if (r.unit2 && r.record_series)
        throw InputError(field("unit2"), "the joined pair records no series");
    if (biaxial(e) && r.restitution)
        throw InputError(field("restitution"), "not used by the biaxial model (no rocking)");
    if (biaxial(e) && r.top_height_m)
        throw InputError(field("top_height_m"), "not used by the biaxial model (no rocking)");
}

dynamics::Options run_options(const SimulateRequest& r) {
    dynamics::Options o = biaxial(r.excitation) ? dynamics::biaxial_options() : dynamics::Options{};
    o.integrator = r.integrator;
    o.cd_dt_s = r.cd_dt_s;
    require_positive(o.cd_dt_s, field("cd_dt_s"));
    o.record_series = r.record_series;
    return o;
}

dynamics::Excitation planar_excitation(const SimulateExcitation& e) {
    if (e.sine) return dynamics::sine_excitation(*e.sine);
    return dynamics::excitation_from_record(*e.horizontal, e.scale,
                                            e.vertical ? &*e.vertical : nullptr, e.scale);
}

// The biaxial sine's checks name sine.*: here the request's sine_y.
dynamics::BiaxialExcitation biaxial_excitation(const SimulateExcitation& e) {
    if (!e.sine_y)
        return dynamics::biaxial_excitation_from_records(
            *e.horizontal, *e.horizontal_y, e.scale, e.vertical ? &*e.vertical : nullptr);
    try {
        return dynamics::biaxial_sine_excitation(*e.sine_y, e.sine_y->phase_deg);
    } catch (const InputError& err) {
        const std::string& f = err.where().field;
        if (!err.where().file.empty() || f.rfind("sine.", 0) != 0) throw;
        throw InputError(field("sine_y." + f.substr(5)), err.message());
    }
}

SimulateResult run_biaxial(const SimulateRequest& r, const block::Block& blk,
                           const dynamics::Options& options) {
    const dynamics::BiaxialModel model = dynamics::make_biaxial_model(r.mu_s, r.mu_k);
    const dynamics::BiaxialExcitation exc = biaxial_excitation(r.excitation);
    // Refuse rather than warn: a block that rocks is outside the model, whose sliding answer
    // would then be wrong on the unsafe side (docs/methods.md s.10).
    if (const auto why = dynamics::biaxial_rocking_reason(blk, model, exc, options.g_mps2))
        throw InputError(field(r.excitation.sine_y ? "sine_y" : "motion_y"),
                         fmt::format("the biaxial model has no rocking and this block would rock "
                                     "at its friction: {}; simulate each direction with the "
                                     "planar model",
                                     *why));
    return {exc.label, BiaxialRun{model, dynamics::simulate_biaxial(model, exc, options)}};
}

// Central difference diverges once its step exceeds the elastic mode's stability limit
// (dynamics::cd_stable_step_s): refused before the run.
void require_stable_cd(const dynamics::FlexibleModel& model, const dynamics::Excitation& excitation,
                       const dynamics::Options& options) {
    if (options.integrator != dynamics::Integrator::central_difference) return;
    if (model.frequency_hz >= dynamics::rigid_limit_hz(model, excitation)) return;
    const double h_s = dynamics::central_difference_step_s(excitation.dt_s, options.cd_dt_s);
    const double limit_s = dynamics::cd_stable_step_s(model, options.g_mps2);
    if (h_s <= limit_s) return;
    throw NumericalError(fmt::format(
        "the central-difference step {:.3g} s (a step of {:.3g} s on the input's samples) "
        "exceeds the stability limit {:.3g} s of the elastic mode at f = {} Hz (2 (sqrt(1 + "
        "4 zeta^2) - 2 zeta) / omega, the mode against the base where it is fastest); use the "
        "event integrator or a step <= {:.3g} s",
        options.cd_dt_s, h_s, limit_s, model.frequency_hz, limit_s));
}

SimulateResult run_flexible(const dynamics::FlexibleMode& mode, const dynamics::BlockModel& rigid,
                            const dynamics::Excitation& exc, const dynamics::Options& options) {
    const dynamics::FlexibleModel model = dynamics::make_flexible_model(rigid, mode);
    // The case key's limit (component.fixed_base_frequency_hz): a mode above it is not a
    // flexible body.
    core::limits::require_within(model.frequency_hz, core::limits::max_frequency_hz,
                                 field("flexible.f"), "fixed-base frequency (Hz)");
    require_stable_cd(model, exc, options);
    FlexibleRun run{model, dynamics::simulate_flexible(model, exc, options),
                    dynamics::rigid_limit_hz(model, exc)};
    return {exc.label, std::move(run)};
}

// make()'s result, its errors about a request field renamed prefix + field (a part of the
// request with a name of its own: unit2.*, body3d.*).
template <class Make>
auto with_field_prefix(const std::string& prefix, Make make) {
    try {
        return make();
    } catch (const InputError& e) {
        if (!e.where().file.empty()) throw;
        throw InputError(field(prefix + e.where().field), e.message());
    }
}

// The second unit, its errors named unit2.* (the first unit's ranges, which are a case's).
dynamics::BlockModel second_unit(const JoinedUnit& u) {
    const block::Block blk = with_field_prefix("unit2.", [&] { return sliding::make_block(u.box); });
    core::limits::require_in(u.mu_s, core::limits::friction, field("unit2.mu_s"));
    if (u.mu_k) require_in_range(*u.mu_k, 0.0, u.mu_s, field("unit2.mu_k"));
    if (u.restitution)
        core::limits::require_in(*u.restitution, core::limits::restitution,
                                 field("unit2.restitution"));
    return dynamics::make_block_model(blk, u.mu_s, u.mu_k, u.restitution);
}

SimulateResult run_pair(const JoinedUnit& u, const dynamics::BlockModel& unit1,
                        const dynamics::Excitation& exc, const dynamics::Options& options) {
    const dynamics::BlockModel unit2 = second_unit(u);
    dynamics::PairOptions pair;
    pair.tunnel_height_m = u.tunnel_height_m;
    require_in_range(pair.tunnel_height_m, 0.0, 1e3, field("tunnel_height_m"));
    PairRun run{{unit1, unit2}, pair.tunnel_height_m,
                dynamics::simulate_pair({unit1, unit2}, exc, pair, options)};
    return {exc.label, std::move(run)};
}

// The 3D body's base motion: the biaxial excitation when a y component is given, else x (and
// the vertical) with y at rest.
dynamics::BiaxialExcitation body3d_excitation(const SimulateExcitation& e) {
    if (biaxial(e)) return biaxial_excitation(e);
    const dynamics::Excitation x = planar_excitation(e);
    return dynamics::biaxial_excitation(x, std::vector<double>(x.horizontal_mps2.size(), 0.0));
}

void require_body3d_request(const SimulateRequest& r) {
    if (r.restitution)
        core::limits::require_in(*r.restitution, core::limits::restitution, field("restitution"));
    if (r.top_height_m) throw InputError(field("top_height_m"), "not used by the 3D body");
    if (r.unit2) throw InputError(field("body3d"), "the 3D body runs alone (no second unit)");
    if (r.integrator != dynamics::Integrator::event)
        throw InputError(field("integrator"), "the 3D body has one integrator (Moreau-Jean)");
}

// The body's errors named body3d.*.
dynamics::Body3d body_of(const Body3dSpec& b) {
    dynamics::Body3d body = with_field_prefix("body3d.", [&] {
        return dynamics::box_body(b.half_x_m, b.half_y_m, b.cg_height_m, b.mass_kg,
                                  b.total_height_m);
    });
    // The CG off the footprint's middle: the footprint, measured from the CG, shifts the other
    // way; the CG must stay strictly inside it.
    const std::array<std::pair<double, double>, 2> offsets{
        {{b.cg_x_m, b.half_x_m}, {b.cg_y_m, b.half_y_m}}};
    const std::array<const char*, 2> names{"body3d.cg_x_m", "body3d.cg_y_m"};
    for (std::size_t i = 0; i < 2; ++i) {
        const auto [offset_m, half_m] = offsets[i];
        if (!std::isfinite(offset_m) || std::abs(offset_m) >= half_m)
            throw InputError(field(names[i]),
                             fmt::format("{} m; the CG must stand inside the footprint: "
                                         "|offset| < {} m",
                                         offset_m, half_m));
    }
    for (Eigen::Vector2d& v : body.footprint_m) v -= Eigen::Vector2d(b.cg_x_m, b.cg_y_m);
    if (b.inertia_cg_kgm2) {
        for (const double I : *b.inertia_cg_kgm2)
            if (!std::isfinite(I) || !(I > 0.0))
                throw InputError(field("body3d.inertia_cg_kgm2"),
                                 fmt::format("{} kg m^2; expected three moments > 0", I));
        const auto& I = *b.inertia_cg_kgm2;
        body.inertia_cg_kgm2 = Eigen::Vector3d(I[0], I[1], I[2]).asDiagonal();
    }
    return body;
}

// The flexible body's mode as the 3D body carries it (docs/methods.md s.11): the one fixed-base
// frequency along x and y, and the planar model's defaults (the uniform cantilever's modal mass
// 0.613 M at 0.726 of the body's height).
dynamics::Body3dMode body3d_mode_of(const dynamics::FlexibleMode& f, const Body3dSpec& b) {
    const double height_m = b.total_height_m.value_or(2.0 * b.cg_height_m);
    return {f.frequency_hz, f.frequency_hz, f.damping,
            f.mass_fraction.value_or(dynamics::cantilever_modal_mass_fraction),
            f.height_m.value_or(dynamics::cantilever_modal_height_ratio * height_m)};
}

SimulateResult run_body3d(const SimulateRequest& r) {
    require_body3d_request(r);
    // Restitution on angular velocity, as the planar block takes it; absent: the plastic
    // impact (Housner's rule generalised, docs/methods.md s.11).
    dynamics::Body3dModel model =
        dynamics::make_body3d_model(body_of(*r.body3d), r.mu_s, r.mu_k, 0.0, r.restitution);
    if (r.flexible) {
        try {
            model = dynamics::with_mode(model, body3d_mode_of(*r.flexible, *r.body3d));
        } catch (const InputError& e) {
            // The one frequency is the request's flexible.f, not a per-axis one.
            if (e.where().field != "flexible.f_x") throw;
            throw InputError(field("flexible.f"), e.message());
        }
    }
    dynamics::Body3dOptions options;
    options.dt_s = r.body3d->dt_s;
    options.phases = r.body3d->phases;
    options.record_series = r.record_series;
    const dynamics::BiaxialExcitation exc = body3d_excitation(r.excitation);
    try {
        return {exc.label, Body3dRun{model, options, dynamics::simulate_body3d(model, exc, options)}};
    } catch (const InputError& e) {
        if (!e.where().file.empty() || e.where().field != "dt_s") throw;
        throw InputError(field("body3d.dt_s"), e.message());
    }
}

}  // namespace simulate_detail

std::optional<dynamics::Integrator> integrator_named(const std::string& name) {
    for (auto i : {dynamics::Integrator::event, dynamics::Integrator::central_difference})
        if (name == dynamics::integrator_name(i)) return i;
    return std::nullopt;
}

SimulateResult simulate(const SimulateRequest& r) {
    using namespace simulate_detail;
    require_consistent(r);
    if (r.body3d) return run_body3d(r);
    const block::Block blk = sliding::make_block(r.box);
    const dynamics::Options options = run_options(r);
    if (biaxial(r.excitation)) return run_biaxial(r, blk, options);
    const dynamics::BlockModel model =
        dynamics::make_block_model(blk, r.mu_s, r.mu_k, r.restitution, r.top_height_m);
    const dynamics::Excitation exc = planar_excitation(r.excitation);
    if (r.unit2) return run_pair(*r.unit2, model, exc, options);
    if (r.flexible) return run_flexible(*r.flexible, model, exc, options);
    return {exc.label, PlanarRun{model, dynamics::simulate(model, exc, options)}};
}

}  // namespace freestand::api
