// The 3D body's time stepping (docs/methods.md s.11): Moreau-Jean's midpoint scheme, the
// contact states it passes through, the samples and the summary.
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <optional>
#include <variant>

#include "core/errors.hpp"
#include "core/limits.hpp"
#include "core/steps.hpp"
#include "dynamics/biaxial_detail.hpp"
#include "dynamics/body3d_detail.hpp"
#include "dynamics/body3d_phases_detail.hpp"
#include "dynamics/flexible_detail.hpp"

namespace freestand::dynamics {

namespace {

using detail::BodyState;
using detail::VertexContact;

/// Fastest free rocking frequency parameter of the body, rad/s: sqrt(M g R / I) about each
/// footprint edge (R the CG's distance from it, I the inertia about it) and each vertex (R its
/// distance, I the least about an axis through it).
double fastest_rocking_radps(const Body3d& b, double g_mps2) {
    double p = 0.0;
    const auto& f = b.footprint_m;
    const double least_inertia_kgm2 =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(b.inertia_cg_kgm2).eigenvalues().minCoeff();
    for (std::size_t i = 0; i < f.size(); ++i) {
        const Eigen::Vector3d a(f[i].x(), f[i].y(), -b.h_m);
        const Eigen::Vector2d& next = f[(i + 1) % f.size()];
        const Eigen::Vector3d n = (Eigen::Vector3d(next.x(), next.y(), -b.h_m) - a).normalized();
        const double R = (a - a.dot(n) * n).norm();
        const double I_edge = n.dot(b.inertia_cg_kgm2 * n) + b.mass_kg * R * R;
        p = std::max(p, std::sqrt(b.mass_kg * g_mps2 * R / I_edge));
        const double R_v = a.norm();
        p = std::max(p, std::sqrt(b.mass_kg * g_mps2 * R_v /
                                  (least_inertia_kgm2 + b.mass_kg * R_v * R_v)));
    }
    return p;
}

void require_options(const Body3dModel& m, const BiaxialExcitation& e, const Body3dOptions& o) {
    require_positive(o.dt_s, {"", 0, "dt_s"});
    require_positive(o.solver_tol, {"", 0, "solver_tol"});
    require_positive(o.regularization, {"", 0, "regularization"});
    require_positive(o.max_step_p, {"", 0, "max_step_p"});
    if (o.max_sweeps == 0) throw InputError({"", 0, "max_sweeps"}, "must be at least 1");
    if (o.arrival_substeps == 0 || o.arrival_substeps > 1024)
        throw InputError({"", 0, "arrival_substeps"},
                         fmt::format("must be in [1, 1024]; got {}", o.arrival_substeps));
    if (!std::isfinite(o.initial_tilt_rad) || o.initial_tilt_rad < 0.0 ||
        o.initial_tilt_rad >= 0.5 * units::pi)
        throw InputError({"", 0, "initial_tilt_rad"},
                         fmt::format("must be in [0, pi/2) rad; got {}", o.initial_tilt_rad));
    if (!std::isfinite(o.initial_lean_rad))
        throw InputError({"", 0, "initial_lean_rad"}, "must be finite");
    if (!std::isfinite(o.tail_s) || o.tail_s < 0.0)
        throw InputError({"", 0, "tail_s"}, fmt::format("must be >= 0 s; got {}", o.tail_s));
    const double p = fastest_rocking_radps(m.body, o.g_mps2);
    if (o.dt_s * p > o.max_step_p)
        throw InputError({"", 0, "dt_s"},
                         fmt::format("{} s is too coarse for this body: its fastest rocking has "
                                     "p = {:.4g} rad/s, and a step must keep dt p <= {} "
                                     "(dt <= {:.3g} s)",
                                     o.dt_s, p, o.max_step_p, o.max_step_p / p));
    const double modal_step_s = body3d_modal_stable_step_s(m);
    if (o.dt_s >= modal_step_s)
        throw InputError({"", 0, "dt_s"},
                         fmt::format("{} s would amplify the body's elastic mode: the scheme is "
                                     "stable below {:.4g} s for these modes against the free "
                                     "body (docs/methods.md s.11)",
                                     o.dt_s, modal_step_s));
    const double steps = (e.duration_s() + o.tail_s) / o.dt_s;
    core::limits::require_within(steps, core::limits::max_fixed_steps, {"", 0, "dt_s"},
                                 "3D steps (duration / dt)");
}

using Edge = detail::FootprintEdge;

/// The planar engine's settling tilt (docs/methods.md s.3), rad.
constexpr double settle_tilt_rad = 1e-7;

/// What a step needs from the body that does not change.
struct Fixed {
    const Body3dModel& model;
    Eigen::Matrix3d inverse_inertia_body;
    std::vector<Eigen::Vector3d> vertices_body;  ///< from the CG, body axes
    std::vector<Edge> edges;                     ///< from vertex i to i + 1 (counter-clockwise)
    Eigen::Vector3d footprint_centre_body;
    const Body3dOptions& options;
    /// With a restitution r: the part of a plastic impact's energy loss an impact keeps,
    /// (1 - r^2) / (1 - r_H^2) (Body3dModel::angular_restitution).
    double impact_loss_ratio = 1.0;
    /// With a mode: its split, and the largest modal force amplitude, N, at which a body at
    /// rest after the excitation stays so (half of what slides it or tips it about the nearest
    /// edge, from the modal mass's height).
    std::optional<detail::ModalSplit> split;
    double quiet_modal_force_N = 0.0;
    /// The input's sample step, s, and with a mode each axis's exact oscillator over it.
    double segment_s = 0.0;
    /// The step, s (a split step's substeps keep its sweep tolerance, solver_tol g step_s).
    double step_s = 0.0;
    /// The slowest arrival a step is split for, m/s: a vertex landing slower than this would
    /// rebound the body by less than settle_tilt_rad about its nearest edge (sqrt(2 g c
    /// settle_tilt_rad), c the least distance from the CG's plan position to an edge), the
    /// tilt below which the planar engine settles a block (docs/methods.md s.3).
    double arrival_mps = 0.0;
    std::array<detail::OscillatorStep, 2> held_segment{};
};

Fixed fixed_of(const Body3dModel& m, const Body3dOptions& o, double segment_s, double step_s) {
    Fixed f{m, m.body.inertia_cg_kgm2.inverse(), {}, {}, Eigen::Vector3d::Zero(), o, 1.0,
            std::nullopt, 0.0, segment_s, step_s, {}};
    if (m.mode) {
        f.split = detail::modal_split(m);
        for (std::size_t i = 0; i < 2; ++i)
            f.held_segment[i] = detail::OscillatorStep(
                {f.split->omega_radps(static_cast<Eigen::Index>(i)), f.split->zeta}, segment_s);
        double reach_m = std::numeric_limits<double>::infinity();
        for (int k = 0; k < 8; ++k) reach_m = std::min(reach_m, m.body.reach_m(k * units::pi / 4.0));
        f.quiet_modal_force_N = 0.5 * m.body.mass_kg * o.g_mps2 *
                                std::min(m.mu_s, reach_m / m.mode->height_m);
    }
    if (m.angular_restitution) {
        const double r = *m.angular_restitution;
        const double r_housner = housner_restitution(m.body);
        f.impact_loss_ratio = (1.0 - r * r) / (1.0 - r_housner * r_housner);
    }
    f.vertices_body = detail::vertices_body(m.body);
    f.edges = detail::footprint_edges(m.body);
    for (const Eigen::Vector3d& v : f.vertices_body) f.footprint_centre_body += v;
    f.footprint_centre_body /= static_cast<double>(f.vertices_body.size());
    double nearest_edge_m = std::numeric_limits<double>::infinity();
    for (const Edge& e : f.edges) nearest_edge_m = std::min(nearest_edge_m, e.distance_m);
    f.arrival_mps = std::sqrt(2.0 * o.g_mps2 * nearest_edge_m * settle_tilt_rad);
    return f;
}

/// What one step did, for the recorder.
struct StepOutcome {
    ContactState state = ContactState::rest;
    bool converged = true;
    /// Not taken, the state unchanged: a vertex reaches the floor (Stepper::arrives) and the
    /// caller asked for such a step to be split.
    bool split = false;
    /// Taken, with a vertex reaching the floor in it.
    bool landed = false;
};

class Stepper {
public:
    explicit Stepper(const Fixed& f) : f_(f), impulses_(f.vertices_body.size(), Eigen::Vector3d::Zero()),
                                       slipping_(f.vertices_body.size(), false),
                                       touching_(f.vertices_body.size(), false) {}

    /// The vertices on the floor in the initial state (touching_ before the first step).
    void start(const BodyState& s) {
        const Eigen::Matrix3d R = s.q.toRotationMatrix();
        for (std::size_t i = 0; i < f_.vertices_body.size(); ++i)
            touching_[i] = height_m(s, R, f_.vertices_body[i]) <= 0.0;
    }

    /// One Moreau-Jean step of dt_s from the state, under the base's a (horizontal) and
    /// G = g + yg'' at the step's midpoint; with split_arrivals, a step in which a vertex
    /// reaches the floor is left for the caller to split.
    StepOutcome step(BodyState& s, const Eigen::Vector2d& a_mps2, double G_mps2, double dt_s,
                     bool split_arrivals) {
        if (f_.split) return step_modal(s, a_mps2, G_mps2, dt_s, split_arrivals);
        if (stays_at_rest(s, a_mps2, G_mps2)) {
            held_ = true;
            return {ContactState::rest, true};
        }
        // The step that moves a held body starts from the static impulses of its loads.
        if (held_) hold_warm_start(s, a_mps2, G_mps2, dt_s);
        held_ = false;
        const double h = dt_s;
        const Midpoint mid = midpoint_of(s, h);
        const Eigen::Matrix3d& R = mid.R;
        detail::MassMatrix mass{f_.model.body.mass_kg,
                                R * f_.inverse_inertia_body * R.transpose(), std::nullopt};
        const Eigen::Matrix3d I_world = R * f_.model.body.inertia_cg_kgm2 * R.transpose();
        fill_contacts(mid.p_m, R, s.twist);
        const bool landed = arrives();
        if (split_arrivals && landed) return {ContactState::rest, true, true, false};
        // The free motion: gravity and the base's inertia force (the body's frame moves with the
        // base), and the gyroscopic moment.
        detail::Twist t = s.twist;
        t.v_mps += h * Eigen::Vector3d(-a_mps2.x(), -a_mps2.y(), -G_mps2);
        const Eigen::Vector3d& w = s.twist.w_radps;
        t.w_radps += h * (mass.inverse_inertia * (-w.cross(I_world * w)));
        const detail::Twist arriving = s.twist;
        const auto solve = solve_contacts(mass, t, h);
        if (f_.model.angular_restitution && detail::has_impact(contacts_, f_.options.g_mps2 * h))
            leave_at(f_.impact_loss_ratio, arriving, t, mass.mass_kg, I_world);
        return close_step(s, t, mid, solve, h, landed);
    }

    /// The footprint edge a rigid body rocks on at the end of the last step: exactly two
    /// contacts carry and they are neighbours. Its vertices counter-clockwise, and whether
    /// both stick, both slip or one of each (at the step's midpoint, as remember() finds).
    enum class EdgeSlip { sticking, slipping, mixed };
    struct EdgeContacts {
        std::array<std::size_t, 2> vertices{};
        EdgeSlip slip = EdgeSlip::mixed;
    };
    std::optional<EdgeContacts> edge_contacts() const {
        if (f_.split) return std::nullopt;
        std::array<std::size_t, 2> v{};
        std::size_t carrying = 0;
        for (const auto& c : contacts_) {
            if (c.impulse_Ns.z() <= 0.0) continue;
            if (carrying == 2) return std::nullopt;
            v[carrying++] = c.vertex;
        }
        if (carrying != 2) return std::nullopt;
        const std::size_t n = f_.vertices_body.size();
        if ((v[1] + 1) % n == v[0]) std::swap(v[0], v[1]);
        if ((v[0] + 1) % n != v[1]) return std::nullopt;
        const bool a = slipping_[v[0]], b = slipping_[v[1]];
        return EdgeContacts{v, a != b ? EdgeSlip::mixed : a ? EdgeSlip::slipping : EdgeSlip::sticking};
    }

    /// The steps go on from an edge phase's end: its two vertices on the floor, sticking or
    /// slipping, with the impulses of its forces over a step as the warm start.
    void resume_from(const std::array<std::size_t, 2>& vertices,
                     const std::array<Eigen::Vector3d, 2>& forces_N, bool slipping) {
        forget_contacts();
        for (std::size_t k = 0; k < 2; ++k) {
            touching_[vertices[k]] = true;
            slipping_[vertices[k]] = slipping;
            impulses_[vertices[k]] = f_.step_s * forces_N[k];
        }
        held_ = false;
    }

    /// Whether a rigid body slides flat at the end of the last step: every vertex a carrying
    /// contact, every one slipping, and no contact point moving off the body's translation by
    /// more than stick_speed_mps (no turning).
    bool sliding_flat(const BodyState& s) const {
        if (f_.split || contacts_.size() != f_.vertices_body.size() ||
            std::abs(s.twist.v_mps.z()) > detail::stick_speed_mps)
            return false;
        return std::all_of(contacts_.begin(), contacts_.end(), [&](const VertexContact& c) {
            return c.impulse_Ns.z() > 0.0 && slipping_[c.vertex] &&
                   (s.twist.at(c.r_m) - s.twist.v_mps).norm() <= detail::stick_speed_mps;
        });
    }

    /// The steps go on from a flat slide's end: every vertex on the floor, slipping along
    /// `slip` (world plan axes), with the impulses over a step of the weight under G, its
    /// centre of pressure mu_k h ahead along the slip, and the friction as the warm start.
    void resume_sliding(const BodyState& s, const Eigen::Vector2d& slip, double G_mps2) {
        const double N_dt = f_.model.body.mass_kg * std::max(G_mps2, 0.0) * f_.step_s;
        std::fill(impulses_.begin(), impulses_.end(), Eigen::Vector3d::Zero());
        if (N_dt > 0.0) {
            const Eigen::Vector2d ahead = f_.model.mu_k * s.p_m.z() * slip;
            warm_start_from(s.q.toRotationMatrix(),
                            Eigen::Vector3d(N_dt, N_dt * ahead.x(), N_dt * ahead.y()),
                            -f_.model.mu_k * N_dt * slip);
        }
        std::fill(slipping_.begin(), slipping_.end(), true);
        std::fill(touching_.begin(), touching_.end(), true);
        held_ = false;
    }

    /// A held body with a mode through a whole input segment, on which the base's acceleration
    /// and G are linear: the modes advanced exactly over it (the fixed-base oscillators of
    /// each axis, Nigam & Jennings 1969), kept when the body lies flat and still and the floor
    /// holds it at the segment's start and end (floor_holds), as the planar flexible body's
    /// rest phase checks its margin. False, with nothing changed, otherwise: the segment's
    /// steps then run.
    bool holds_modal_segment(BodyState& s, const detail::BiaxialSegment& seg) {
        const double t_end = seg.tk + f_.segment_s;
        if (!(seg.G(seg.tk) > 0.0) || !(seg.G(t_end) > 0.0)) return false;
        const Eigen::Matrix3d R = s.q.toRotationMatrix();
        if (!flat_and_still(s, R)) return false;
        const auto holds_at = [&](double t, const Eigen::Vector2d& q_m, const Eigen::Vector2d& q_mps) {
            const auto a = seg.a(t);
            const Eigen::Vector2d a_mps2(a[0], a[1]);
            const Eigen::Vector2d q_acc = held_modal_accel(in_body(R, a_mps2), q_m, q_mps);
            return floor_holds(held_load(s, R, a_mps2, seg.G(t), q_acc, q_m), R);
        };
        if (!holds_at(seg.tk, s.modal_m, s.twist.q_mps)) return false;
        const Eigen::Vector2d a0_body = in_body(R, {seg.a0[0], seg.a0[1]});
        const Eigen::Vector2d a1_body = in_body(R, {seg.a1[0], seg.a1[1]});
        Eigen::Vector2d q_m = s.modal_m, q_mps = s.twist.q_mps;
        for (int i = 0; i < 2; ++i)
            f_.held_segment[static_cast<std::size_t>(i)].apply(q_m(i), q_mps(i), a0_body(i),
                                                               a1_body(i));
        if (!holds_at(t_end, q_m, q_mps)) return false;
        s.modal_m = q_m;
        s.twist.q_mps = q_mps;
        held_ = true;
        return true;
    }

private:
    /// The step of a body with a mode: the same scheme over (v, w, q'), the generalised mass
    /// and forces at the midpoint (body3d_modal.cpp), the impulses acting on the rigid rest's
    /// vertices. The modal mass keeps its velocity through an impact (a mode slow against the
    /// contact pulse, as body3d_modal_stable_step_s bounds it), and the restitution's loss is
    /// taken from the rest's velocities.
    StepOutcome step_modal(BodyState& s, const Eigen::Vector2d& a_mps2, double G_mps2,
                           double dt_s, bool split_arrivals) {
        if (stays_held_modal(s, a_mps2, G_mps2, dt_s)) {
            held_ = true;
            return {ContactState::rest, true};
        }
        if (held_) {
            const HeldModal held = held_modal(s, s.q.toRotationMatrix(), a_mps2, G_mps2, dt_s);
            const FloorLoad& load = held.load;
            if (load.force_N.z() > 0.0)
                warm_start_from(s.q.toRotationMatrix(),
                                dt_s * Eigen::Vector3d(load.force_N.z(), -load.moment_Nm.y(),
                                                       load.moment_Nm.x()),
                                dt_s * load.force_N.head<2>());
            held_ = false;
        }
        const double h = dt_s;
        const Midpoint mid = midpoint_of(s, h);
        const detail::Matrix8d M = detail::generalized_mass(*f_.split, mid.R, mid.modal_m);
        // The fixed-size inverse (partial-pivot LU) costs two thirds of an LDLT solve against
        // the identity, whose blocked matrix path is slow at 8 x 8.
        const detail::Matrix8d M_inv = M.inverse();
        detail::MassMatrix mass{f_.model.body.mass_kg, Eigen::Matrix3d::Identity(),
                                M_inv.leftCols<6>()};
        fill_contacts(mid.p_m, mid.R, s.twist);
        const bool landed = arrives();
        if (split_arrivals && landed) return {ContactState::rest, true, true, false};
        detail::Twist t = detail::unpack(
            detail::pack(s.twist) + h * M_inv * detail::generalized_force(*f_.split, mid.R,
                                                                           mid.modal_m, s.twist,
                                                                           a_mps2, G_mps2));
        const detail::Twist arriving = s.twist;
        const auto solve = solve_contacts(mass, t, h);
        if (f_.model.angular_restitution && detail::has_impact(contacts_, f_.options.g_mps2 * h))
            leave_modal_at(f_.impact_loss_ratio, arriving, t, M);
        return close_step(s, t, mid, solve, h, landed);
    }

    /// The positions at a step's midpoint, from the step's starting velocities.
    struct Midpoint {
        Eigen::Vector3d p_m;
        Eigen::Quaterniond q;
        Eigen::Vector2d modal_m;
        Eigen::Matrix3d R;  ///< q's rotation
    };
    static Midpoint midpoint_of(const BodyState& s, double h) {
        Midpoint m{s.p_m + 0.5 * h * s.twist.v_mps, detail::turned(s.q, s.twist.w_radps, 0.5 * h),
                   s.modal_m + 0.5 * h * s.twist.q_mps, Eigen::Matrix3d::Identity()};
        m.R = m.q.toRotationMatrix();
        return m;
    }

    /// The step's impulse problem over contacts_, from the free velocities t to the final ones.
    detail::ImpulseSolve solve_contacts(const detail::MassMatrix& mass, detail::Twist& t,
                                        double h) {
        return detail::solve_impulses(contacts_, mass, t,
                                      f_.options.solver_tol * f_.options.g_mps2 * f_.step_s,
                                      f_.options.g_mps2 * h, f_.options.max_sweeps,
                                      f_.options.regularization);
    }

    /// The end of a step: the contacts remembered for the next, the state, and the positions
    /// advanced from the midpoint with the final velocities t.
    StepOutcome close_step(BodyState& s, detail::Twist t, const Midpoint& mid,
                           const detail::ImpulseSolve& solve, double h, bool landed) {
        remember(contacts_, t);
        const ContactState state = state_of(contacts_, t);
        // Three or more carrying contacts solved as sticking fix the rest's six velocities at
        // zero: what is left is the regularisation's creep, and exact zeros let the next steps
        // take stays_at_rest (the modal rates move on).
        if (solve.sticking && state == ContactState::rest) {
            t.v_mps.setZero();
            t.w_radps.setZero();
        }
        s.twist = t;
        s.p_m = mid.p_m + 0.5 * h * t.v_mps;
        s.q = detail::turned(mid.q, t.w_radps, 0.5 * h);
        s.modal_m = mid.modal_m + 0.5 * h * t.q_mps;
        return {state, solve.converged, false, landed};
    }

    /// The floor's force and its moment about the footprint's plane below the body's
    /// reference point (x, y), N and N m, that hold a body with a mode still: the weight and
    /// the base's inertia force on both masses and the modal mass's q'' (body axes), with the
    /// modal mass at q.
    struct FloorLoad {
        Eigen::Vector3d force_N;
        Eigen::Vector2d moment_Nm;
    };
    FloorLoad held_load(const BodyState& s, const Eigen::Matrix3d& R, const Eigen::Vector2d& a_mps2,
                        double G_mps2, const Eigen::Vector2d& q_acc, const Eigen::Vector2d& q_m) const {
        const detail::ModalSplit& m = *f_.split;
        const Eigen::Vector3d base(a_mps2.x(), a_mps2.y(), G_mps2);
        const Eigen::Vector3d up(0.0, 0.0, s.p_m.z());
        const Eigen::Vector3d rest_force = m.rest_kg * base;
        const Eigen::Vector3d modal_force = m.modal_kg * (base + R.leftCols<2>() * q_acc);
        const Eigen::Vector3d rho_r = up + R * m.rest_cg_m;
        const Eigen::Vector3d rho_s =
            up + R * (m.modal_rest_m + Eigen::Vector3d(q_m.x(), q_m.y(), 0.0));
        return {rest_force + modal_force,
                (rho_r.cross(rest_force) + rho_s.cross(modal_force)).head<2>()};
    }

    /// Whether the floor can carry a held load: the force within mu_s, the centre of pressure
    /// inside the footprint.
    bool floor_holds(const FloorLoad& load, const Eigen::Matrix3d& R) const {
        const Eigen::Vector3d& F = load.force_N;
        if (!(F.z() > 0.0) || F.head<2>().norm() > f_.model.mu_s * F.z()) return false;
        const Eigen::Vector2d pressure(-load.moment_Nm.y() / F.z(), load.moment_Nm.x() / F.z());
        const Eigen::Vector2d pressure_body =
            (R.transpose() * Eigen::Vector3d(pressure.x(), pressure.y(), 0.0)).head<2>();
        return std::all_of(f_.edges.begin(), f_.edges.end(), [&](const Edge& e) {
            return e.normal.dot(pressure_body) <= e.distance_m;
        });
    }

    /// The base's plan acceleration in body axes.
    static Eigen::Vector2d in_body(const Eigen::Matrix3d& R, const Eigen::Vector2d& a_mps2) {
        return (R.transpose() * Eigen::Vector3d(a_mps2.x(), a_mps2.y(), 0.0)).head<2>();
    }

    /// The modes' accelerations on a held base, body axes: q'' = -a_body - 2 zeta omega q' -
    /// omega^2 q.
    Eigen::Vector2d held_modal_accel(const Eigen::Vector2d& a_body, const Eigen::Vector2d& q_m,
                                     const Eigen::Vector2d& q_mps) const {
        const detail::ModalSplit& m = *f_.split;
        const Eigen::Array2d omega = m.omega_radps.array();
        return -a_body -
               (2.0 * m.zeta * omega * q_mps.array() + omega.square() * q_m.array()).matrix();
    }

    /// A held body with a mode through one step: its modal state at the step's end (the
    /// fixed-base oscillators of each axis, as the full step gives them when the impulses hold
    /// the rest still: its q' row then carries no impulse, q'' = -a_body - 2 zeta omega q' -
    /// omega^2 q_mid), and the floor's load that holds it, at the step's mid modal position.
    struct HeldModal {
        Eigen::Vector2d q_m, q_mps;
        FloorLoad load;
    };
    HeldModal held_modal(const BodyState& s, const Eigen::Matrix3d& R,
                         const Eigen::Vector2d& a_mps2, double G_mps2, double dt_s) const {
        const Eigen::Vector2d mid = s.modal_m + 0.5 * dt_s * s.twist.q_mps;
        const Eigen::Vector2d q_acc = held_modal_accel(in_body(R, a_mps2), mid, s.twist.q_mps);
        HeldModal out;
        out.q_mps = s.twist.q_mps + dt_s * q_acc;
        out.q_m = mid + 0.5 * dt_s * out.q_mps;
        out.load = held_load(s, R, a_mps2, G_mps2, q_acc, 0.5 * (s.modal_m + out.q_m));
        return out;
    }

    /// The height above the floor of the body point v (body axes, from the CG), m.
    static double height_m(const BodyState& s, const Eigen::Matrix3d& R, const Eigen::Vector3d& v) {
        return s.p_m.z() + R.row(2).dot(v);
    }

    /// Whether the body lies flat on its whole footprint with its rest's velocities at zero.
    bool flat_and_still(const BodyState& s, const Eigen::Matrix3d& R) const {
        if (!s.twist.v_mps.isZero(0.0) || !s.twist.w_radps.isZero(0.0)) return false;
        return std::none_of(f_.vertices_body.begin(), f_.vertices_body.end(),
                            [&](const Eigen::Vector3d& v) { return height_m(s, R, v) > 0.0; });
    }

    /// stays_at_rest for a body with a mode: held flat on its whole footprint, it stays so
    /// through the step when the floor's load the step needs (held_modal) is one the floor
    /// can carry (floor_holds); the step then moves only the modes.
    bool stays_held_modal(BodyState& s, const Eigen::Vector2d& a_mps2, double G_mps2,
                          double dt_s) const {
        if (!(G_mps2 > 0.0)) return false;
        const Eigen::Matrix3d R = s.q.toRotationMatrix();
        if (!flat_and_still(s, R)) return false;
        const HeldModal held = held_modal(s, R, a_mps2, G_mps2, dt_s);
        if (!floor_holds(held.load, R)) return false;
        s.modal_m = held.q_m;
        s.twist.q_mps = held.q_mps;
        return true;
    }

    /// leave_at for a body with a mode: the rest's velocities (v, w) scale by the factor that
    /// makes the impact lose loss_ratio times the plastic impact's loss of the whole kinetic
    /// energy 1/2 u^T M u, the modal rates kept.
    static void leave_modal_at(double loss_ratio, const detail::Twist& arriving, detail::Twist& t,
                               const detail::Matrix8d& M) {
        const auto energy = [&](const detail::Twist& x) {
            const detail::Vector8d u = detail::pack(x);
            return 0.5 * u.dot(M * u);
        };
        const double leaving_J = energy(t);
        const double plastic_loss_J = energy(arriving) - leaving_J;
        if (plastic_loss_J <= 0.0) return;
        const double target_J = std::max(0.0, leaving_J + (1.0 - loss_ratio) * plastic_loss_J);
        // E(k) = a k^2 + b k + c over the scale k of (v, w).
        detail::Vector8d rigid = detail::pack(t), modal = rigid;
        rigid.tail<2>().setZero();
        modal.head<6>().setZero();
        const double a = 0.5 * rigid.dot(M * rigid), b = rigid.dot(M * modal),
                     c = 0.5 * modal.dot(M * modal);
        if (a <= 0.0) return;
        const double disc = b * b - 4.0 * a * (c - target_J);
        const double k = std::max(0.0, (-b + std::sqrt(std::max(disc, 0.0))) / (2.0 * a));
        t.v_mps *= k;
        t.w_radps *= k;
    }

    /// Whether a body at rest on its whole footprint stays so through the step, which then
    /// changes nothing: the base's force needs at most mu_s of the weight, and the line of the
    /// weight and the inertia force, from the CG, meets the floor inside the footprint (every
    /// vertex then carries a non-negative share). The step's sticking solve gives the same
    /// zero velocities; this skips it for the long still stretches of a standing body.
    bool stays_at_rest(const BodyState& s, const Eigen::Vector2d& a_mps2, double G_mps2) const {
        if (!(G_mps2 > 0.0) || a_mps2.norm() > f_.model.mu_s * G_mps2) return false;
        const Eigen::Matrix3d R = s.q.toRotationMatrix();
        if (!flat_and_still(s, R)) return false;
        // Where the resultant's line meets the floor, from the CG's plan position, body axes.
        const Eigen::Vector2d meets = -s.p_m.z() / G_mps2 * in_body(R, a_mps2);
        for (const Edge& e : f_.edges)
            if (e.normal.dot(meets) > e.distance_m) return false;
        return true;
    }

    /// The warm start of the step that moves a held body: the least-norm normal impulses that
    /// carry the weight and balance the base's force about the CG under the step's loads, each
    /// vertex taking its load's share of the friction (what the sticking solve gives a body at
    /// rest).
    void hold_warm_start(const BodyState& s, const Eigen::Vector2d& a_mps2, double G_mps2,
                         double dt_s) {
        const double M_dt = f_.model.body.mass_kg * dt_s;
        const double h_m = s.p_m.z();
        warm_start_from(s.q.toRotationMatrix(),
                        Eigen::Vector3d(G_mps2 * M_dt, -h_m * a_mps2.x() * M_dt,
                                        -h_m * a_mps2.y() * M_dt),
                        Eigen::Vector2d(a_mps2.x() * M_dt, a_mps2.y() * M_dt));
    }

    /// Impulses of a held body from the floor's load over the step: load = (sum N_i,
    /// sum N_i x_i, sum N_i y_i) (the normal impulse and its centre of pressure, world plan
    /// axes from the body's reference point), met by the least-norm normal impulses, and the
    /// tangential impulse `friction` shared among the vertices as their normal ones.
    void warm_start_from(const Eigen::Matrix3d& R, const Eigen::Vector3d& load,
                         const Eigen::Vector2d& friction) {
        const auto n = static_cast<Eigen::Index>(f_.vertices_body.size());
        Eigen::Matrix<double, 3, Eigen::Dynamic> A(3, n);
        for (Eigen::Index i = 0; i < n; ++i) {
            const Eigen::Vector3d r = R * f_.vertices_body[static_cast<std::size_t>(i)];
            A.col(i) << 1.0, r.x(), r.y();
        }
        const Eigen::VectorXd normal = A.transpose() * (A * A.transpose()).ldlt().solve(load);
        for (Eigen::Index i = 0; i < n; ++i) {
            const double share = normal(i) / load.x();
            impulses_[static_cast<std::size_t>(i)] =
                Eigen::Vector3d(friction.x() * share, friction.y() * share, normal(i));
        }
        std::fill(slipping_.begin(), slipping_.end(), false);
        std::fill(touching_.begin(), touching_.end(), true);
    }

    /// A vertex reaches the floor: a contact of this step that was none of the last step's,
    /// approaching faster than Fixed::arrival_mps.
    bool arrives() const {
        return std::any_of(contacts_.begin(), contacts_.end(), [&](const VertexContact& c) {
            return !touching_[c.vertex] && c.approach_mps < -f_.arrival_mps;
        });
    }

    /// The vertices on or below the floor at the step's midpoint, into contacts_ (reused from
    /// step to step: a step allocates nothing).
    void fill_contacts(const Eigen::Vector3d& p_mid, const Eigen::Matrix3d& R,
                       const detail::Twist& twist) {
        auto& out = contacts_;
        out.clear();
        for (std::size_t i = 0; i < f_.vertices_body.size(); ++i) {
            const Eigen::Vector3d r = R * f_.vertices_body[i];
            if (p_mid.z() + r.z() > 0.0) continue;
            VertexContact c;
            c.vertex = i;
            c.r_m = r;
            c.mu = slipping_[i] ? f_.model.mu_k : f_.model.mu_s;
            c.restitution = f_.model.normal_restitution;
            c.approach_mps = twist.at(r).z();
            c.impulse_Ns = impulses_[i];
            out.push_back(c);
        }
    }

    /// The plastic impact's velocities scaled so that the impact loses loss_ratio times the
    /// kinetic energy (relative to the base) the plastic impact took, never going below zero.
    /// Every contact point's velocity scales with them, so a contact the impact stopped stays
    /// stopped.
    static void leave_at(double loss_ratio, const detail::Twist& arriving, detail::Twist& t,
                         double mass_kg, const Eigen::Matrix3d& inertia_kgm2) {
        const auto energy = [&](const detail::Twist& x) {
            return 0.5 * mass_kg * x.v_mps.squaredNorm() +
                   0.5 * x.w_radps.dot(inertia_kgm2 * x.w_radps);
        };
        const double leaving_J = energy(t);
        const double plastic_loss_J = energy(arriving) - leaving_J;
        if (leaving_J == 0.0 || plastic_loss_J <= 0.0) return;
        const double target_J = std::max(0.0, leaving_J + (1.0 - loss_ratio) * plastic_loss_J);
        const double scale = std::sqrt(target_J / leaving_J);
        t.v_mps *= scale;
        t.w_radps *= scale;
    }

    /// No vertex on the floor, none slipping, no impulse to start from.
    void forget_contacts() {
        std::fill(impulses_.begin(), impulses_.end(), Eigen::Vector3d::Zero());
        std::fill(slipping_.begin(), slipping_.end(), false);
        std::fill(touching_.begin(), touching_.end(), false);
    }

    void remember(const std::vector<VertexContact>& contacts, const detail::Twist& t) {
        forget_contacts();
        for (const auto& c : contacts) {
            touching_[c.vertex] = true;
            impulses_[c.vertex] = c.impulse_Ns;
            slipping_[c.vertex] = t.at(c.r_m).head<2>().norm() > detail::stick_speed_mps;
        }
    }

    ContactState state_of(const std::vector<VertexContact>& contacts, const detail::Twist& t) const {
        std::size_t carrying = 0;
        bool moving = false;
        for (const auto& c : contacts) {
            if (c.impulse_Ns.z() <= 0.0) continue;
            ++carrying;
            moving = moving || t.at(c.r_m).norm() > detail::stick_speed_mps;
        }
        if (carrying == 0) return ContactState::flight;
        if (carrying == 1) return ContactState::vertex;
        if (carrying == 2) return ContactState::edge;
        return moving ? ContactState::slide : ContactState::rest;
    }

    const Fixed& f_;
    std::vector<Eigen::Vector3d> impulses_;  ///< last step's, per vertex (the warm start)
    std::vector<bool> slipping_;             ///< per vertex, at the last step's end
    std::vector<bool> touching_;             ///< per vertex, a contact of the last step
    bool held_ = false;                      ///< the last step was stays_at_rest's
    std::vector<VertexContact> contacts_;    ///< this step's
};

/// A rigid body's smooth phase taken whole (body3d_phases_detail.hpp).
/// Its alternatives in the order of Phase.
using WholePhase = std::variant<detail::EdgePivot, detail::EdgeSlide, detail::FlatSlide>;

ContactState state_in(const WholePhase& p) {
    return std::holds_alternative<detail::FlatSlide>(p) ? ContactState::slide : ContactState::edge;
}

/// The phase a step's end starts, if its contacts make one and its margins hold there: an
/// edge whose two vertices stick or slip, or the whole footprint slipping without turning.
std::optional<WholePhase> phase_after_step(const Body3dModel& model, const Stepper& stepper,
                                      const BodyState& s, ContactState state,
                                      const detail::BiaxialSegment& seg, double t_s,
                                      double g_mps2, double slow_mps) {
    std::optional<WholePhase> out;
    if (state == ContactState::edge) {
        const auto edge = stepper.edge_contacts();
        if (!edge) return out;
        const auto [from, to] = edge->vertices;
        if (edge->slip == Stepper::EdgeSlip::sticking) {
            if (auto p = detail::EdgePivot::start(model, s, from, to, seg, t_s, g_mps2)) out = *p;
        } else if (edge->slip == Stepper::EdgeSlip::slipping) {
            if (auto p = detail::EdgeSlide::start(model, s, from, to, seg, t_s, g_mps2, slow_mps))
                out = *p;
        }
    } else if (state == ContactState::slide && stepper.sliding_flat(s)) {
        if (auto p = detail::FlatSlide::start(model, s, seg, t_s, g_mps2, slow_mps)) out = *p;
    }
    return out;
}

/// The steps' contact memory at a phase's end (their warm start).
void resume_after(Stepper& stepper, const WholePhase& phase, const BodyState& s,
                  const detail::BiaxialSegment& seg, double t_s) {
    if (const auto* p = std::get_if<detail::EdgePivot>(&phase))
        stepper.resume_from(p->vertices(), p->vertex_forces_N(seg), false);
    else if (const auto* e = std::get_if<detail::EdgeSlide>(&phase))
        stepper.resume_from(e->vertices(), e->vertex_forces_N(seg), true);
    else
        stepper.resume_sliding(s, std::get<detail::FlatSlide>(phase).slip_direction(),
                               seg.G(t_s));
}

/// Tilt, tilt over the critical tilt in the direction of the lean, twist and slide of a state.
Body3dSample sample_of(const BodyState& s, const Fixed& f, double t_s, ContactState state) {
    const Eigen::Matrix3d R = s.q.toRotationMatrix();
    Body3dSample out;
    out.time_s = t_s;
    out.state = state;
    out.tilt_rad = std::acos(std::clamp(R(2, 2), -1.0, 1.0));
    // The world's vertical in body axes leans away from the body's lean.
    const Eigen::Vector3d up_body = R.transpose() * Eigen::Vector3d::UnitZ();
    if (out.tilt_rad > 0.0) {
        const double psi = std::atan2(-up_body.y(), -up_body.x());
        out.tilt_over_critical = out.tilt_rad / f.model.body.critical_tilt_rad(psi);
    }
    // Swing-twist decomposition about the vertical.
    out.twist_rad = 2.0 * std::atan2(s.q.z(), s.q.w());
    if (out.twist_rad > units::pi) out.twist_rad -= units::two_pi;
    if (out.twist_rad < -units::pi) out.twist_rad += units::two_pi;
    const Eigen::Vector3d centre = s.p_m + R * f.footprint_centre_body;
    out.slide_x_m = centre.x() - f.footprint_centre_body.x();
    out.slide_y_m = centre.y() - f.footprint_centre_body.y();
    out.modal_x_m = s.modal_m.x();
    out.modal_y_m = s.modal_m.y();
    return out;
}

/// A body with a mode is quiet when the mode's force amplitude, m_s omega^2 sqrt(q^2 +
/// (q' / omega)^2) per axis, is below Fixed::quiet_modal_force_N; a rigid body always is.
bool mode_quiet(const BodyState& s, const Fixed& f) {
    if (!f.split) return true;
    for (int i = 0; i < 2; ++i) {
        const double omega = f.split->omega_radps(i);
        const double amplitude_m = std::hypot(s.modal_m(i), s.twist.q_mps(i) / omega);
        if (f.split->modal_kg * omega * omega * amplitude_m > f.quiet_modal_force_N) return false;
    }
    return true;
}

/// Whether a body at rest, flat on its footprint, stays at rest under the base's a and
/// G = g + yg'' (docs/methods.md s.2 in three dimensions; strict inequalities leave rest): the
/// base does not fall away (G > 0), friction holds (|a| <= mu_s G), and the line of the weight
/// and the inertia force through the CG meets the floor inside the footprint
/// (n_e . (-h R^T a) <= c_e G for every edge, n_e its outward normal and c_e its distance from
/// the CG's plan position). Each condition is linear in a and G, so holding at both ends of an
/// input segment it holds throughout it.
bool holds_at_rest(const Fixed& f, const Eigen::Matrix3d& R, const Eigen::Vector2d& a_mps2,
                   double G_mps2) {
    if (G_mps2 <= 0.0 || a_mps2.norm() > f.model.mu_s * G_mps2) return false;
    const Eigen::Vector3d a_body = R.transpose() * Eigen::Vector3d(a_mps2.x(), a_mps2.y(), 0.0);
    const Eigen::Vector2d offset = -f.model.body.h_m * a_body.head<2>();
    return std::all_of(f.edges.begin(), f.edges.end(), [&](const Edge& e) {
        return e.normal.dot(offset) <= e.distance_m * G_mps2;
    });
}

/// Whether a body at rest stays so through the whole input segment: for the rigid body,
/// holds_at_rest at both ends (linear in the load, so throughout); with a mode,
/// Stepper::holds_modal_segment, which then advances the modes over it.
bool rests_through(const Fixed& f, Stepper& stepper, BodyState& s,
                   const detail::BiaxialSegment& seg) {
    if (f.split) return stepper.holds_modal_segment(s, seg);
    const Eigen::Matrix3d R = s.q.toRotationMatrix();
    const double t_end = seg.tk + f.segment_s;
    const auto a0 = seg.a(seg.tk), a1 = seg.a(t_end);
    return holds_at_rest(f, R, {a0[0], a0[1]}, seg.G(seg.tk)) &&
           holds_at_rest(f, R, {a1[0], a1[1]}, seg.G(t_end));
}

void take_peaks(Body3dSummary& sum, const Body3dSample& x) {
    sum.tilt_max_rad = std::max(sum.tilt_max_rad, x.tilt_rad);
    sum.tilt_max_over_critical = std::max(sum.tilt_max_over_critical, x.tilt_over_critical);
    sum.twist_max_rad = std::max(sum.twist_max_rad, std::abs(x.twist_rad));
    sum.slide_max_m = std::max(sum.slide_max_m, std::hypot(x.slide_x_m, x.slide_y_m));
    sum.modal_max_m = std::max(sum.modal_max_m, std::hypot(x.modal_x_m, x.modal_y_m));
}

// At rest, flat, or leaning by the initial tilt about the support line in the lean's direction:
// the rotation's axis lies in the plan, normal to the lean, through the point at the footprint's
// reach along it, which stays where it was on the floor.
BodyState initial_state(const Body3d& body, const Body3dOptions& o) {
    BodyState s;
    const double psi = o.initial_lean_rad;
    const double reach = body.reach_m(psi);
    const Eigen::Vector3d pivot(reach * std::cos(psi), reach * std::sin(psi), -body.h_m);
    const Eigen::Vector3d axis(-std::sin(psi), std::cos(psi), 0.0);
    s.q = Eigen::Quaterniond(Eigen::AngleAxisd(o.initial_tilt_rad, axis));
    s.p_m = Eigen::Vector3d(pivot.x(), pivot.y(), 0.0) - s.q.toRotationMatrix() * pivot;
    return s;
}

}  // namespace

Body3dResult simulate_body3d(const Body3dModel& model, const BiaxialExcitation& excitation,
                             const Body3dOptions& options) {
    detail::require_biaxial_excitation(excitation);
    require_options(model, excitation, options);
    const auto wall0 = std::chrono::steady_clock::now();
    const detail::BiaxialBase base(excitation, options.g_mps2);
    const double n_sub = std::max(1.0, core::steps_covering(excitation.dt_s / options.dt_s));
    const double h = excitation.dt_s / n_sub;
    const Fixed fixed = fixed_of(model, options, excitation.dt_s, h);
    Stepper stepper(fixed);
    BodyState s = initial_state(model.body, options);
    stepper.start(s);

    Body3dResult out;
    auto& sum = out.summary;
    sum.pga_g = excitation.pga_mps2() / options.g_mps2;
    const auto first = sample_of(s, fixed, 0.0, ContactState::rest);
    if (options.record_series) out.series.push_back(first);
    const std::size_t segments = base.segments(options.tail_s);
    // The state at the last segment's end (a body released leaning is on its support line).
    ContactState state = options.initial_tilt_rad > 0.0 ? ContactState::edge : ContactState::rest;
    // The phase the body is in, if any (it may run on through several segments), and the
    // slip below which a flat slide is left to the steps: what gravity adds in a step.
    std::optional<WholePhase> phase;
    const double slow_mps = options.g_mps2 * h;
    for (std::size_t k = 0; k < segments && !sum.overturned; ++k) {
        const auto seg = base.segment(k);
        // A body at rest that the segment's load cannot move skips the segment's steps, as
        // the planar engine's rest runs do; a body with a mode advances its modes exactly.
        const double t_end = seg.tk + excitation.dt_s;
        const bool skip = state == ContactState::rest && rests_through(fixed, stepper, s, seg);
        if (skip) sum.time_in_state_s[0] += excitation.dt_s;
        // One step from t0_s, and what it did (split: not taken).
        const auto take = [&](double t0_s, double dt_s, bool split_arrivals) {
            const double t_mid = t0_s + 0.5 * dt_s;
            const auto a = seg.a(t_mid);
            const auto step = stepper.step(s, {a[0], a[1]}, seg.G(t_mid), dt_s, split_arrivals);
            if (step.split) return step;
            state = step.state;
            ++sum.steps;
            if (!step.converged) ++sum.unconverged_steps;
            sum.time_in_state_s[static_cast<std::size_t>(state)] += dt_s;
            return step;
        };
        // Steps over [t0, t0 + dt]: one, or with a vertex landing in it, substeps up to the one
        // it lands in and the rest of the step as one.
        const std::size_t m = options.arrival_substeps;
        const auto steps_over = [&](double t0, double dt) {
            if (!take(t0, dt, m > 1).split) return;
            const double sub = dt / static_cast<double>(m);
            for (std::size_t i = 0; i < m; ++i) {
                if (!take(t0 + static_cast<double>(i) * sub, sub, false).landed) continue;
                if (i + 1 < m)
                    take(t0 + static_cast<double>(i + 1) * sub,
                         dt - static_cast<double>(i + 1) * sub, false);
                break;
            }
        };
        double t = seg.tk;
        while (!skip && t < t_end) {
            if (phase) {
                const detail::PhaseRun run = std::visit(
                    [&](auto& p) { return p.advance(seg, t_end); }, *phase);
                const ContactState phase_state = state_in(*phase);
                sum.steps += run.steps;
                sum.time_in_state_s[static_cast<std::size_t>(phase_state)] += run.t_s - t;
                sum.phase_time_s[phase->index()] += run.t_s - t;
                s = std::visit([](const auto& p) { return p.state(); }, *phase);
                state = phase_state;
                t = run.t_s;
                if (!run.ended) break;
                resume_after(stepper, *phase, s, seg, t);
                phase.reset();
            }
            // Steps of h on the grid from the segment's start. After a phase, a step up to the
            // grid, a remainder below a hundredth of h joining the next step (or, at the
            // segment's end, taken as it is; within rounding of the end there is none).
            if (t_end - t < 1e-9 * h) break;
            const double j = std::floor((t - seg.tk) / h + 1e-9);
            double t_next = seg.tk + (j + 1.0) * h;
            double dt = h;
            if (std::abs(t - (seg.tk + j * h)) > 1e-9 * h) {
                if (t_next - t < 0.01 * h) t_next += h;
                dt = t_next - t;
            }
            if (j + 1.0 >= n_sub || t_end - t_next < 0.01 * h) {
                t_next = t_end;
                if (dt != h) dt = t_end - t;
            }
            steps_over(t, dt);
            t = t_next;
            if (options.phases) phase = phase_after_step(model, stepper, s, state, seg, t,
                                                         options.g_mps2, slow_mps);
        }
        // At rest (three or more contacts, every contact point still to stick_speed_mps): the
        // velocities are set to 0 so that the next segment may skip.
        if (state == ContactState::rest) {
            s.twist.v_mps.setZero();
            s.twist.w_radps.setZero();
        }
        const auto x = sample_of(s, fixed, t_end, state);
        take_peaks(sum, x);
        if (options.record_series) out.series.push_back(x);
        sum.end_time_s = t_end;
        if (x.tilt_rad >= 0.5 * units::pi) {
            sum.overturned = true;
            sum.overturn_time_s = t_end;
        }
        // Once the base is quiet, a body at rest stays there.
        if (t_end >= base.quiet_from_s() && state == ContactState::rest && mode_quiet(s, fixed))
            break;
    }
    sum.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    return out;
}

}  // namespace freestand::dynamics
