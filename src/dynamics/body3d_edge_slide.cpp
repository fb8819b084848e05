// The 3D body rocking on a footprint edge whose two vertices slip (docs/methods.md s.11): the
// rigid body's Newton-Euler equations with the floor's force n_i (z - mu_k s_i) at each vertex
// (s_i the unit direction of its slip), the two normal forces fixed by the vertices' vertical
// accelerations being zero (a 2 x 2 system: the sliding block's, Shenton & Jones 1991, on
// each vertex of the edge). With friction the system is not symmetric, and it may lose its one
// non-negative solution (Painleve's paradox) where a diagonal entry or the determinant falls to
// zero: that ends the phase, as a normal force falling to zero does.
#include <algorithm>
#include <cmath>

#include "dynamics/body3d_phases_detail.hpp"

namespace freestand::dynamics::detail {

namespace {

Eigen::Quaterniond orientation(const std::array<double, 13>& x) {
    return Eigen::Quaterniond(x[3], x[4], x[5], x[6]).normalized();
}

/// The plan direction of a slip velocity, or zero.
Eigen::Vector3d slip_direction(const Eigen::Vector3d& u) {
    const double speed = std::hypot(u.x(), u.y());
    return speed > 0.0 ? Eigen::Vector3d(u.x() / speed, u.y() / speed, 0.0)
                       : Eigen::Vector3d::Zero();
}

}  // namespace

std::optional<EdgeSlide> EdgeSlide::start(const Body3dModel& model, const BodyState& s,
                                          std::size_t from, std::size_t to,
                                          const BiaxialSegment& seg, double t_s, double g_mps2,
                                          double slow_mps) {
    const Body3d& body = model.body;
    EdgeSlide p;
    p.from_ = from;
    p.to_ = to;
    p.mass_kg_ = body.mass_kg;
    p.mu_k_ = model.mu_k;
    p.g_mps2_ = g_mps2;
    p.slow_mps_ = slow_mps;
    p.inertia_body_ = body.inertia_cg_kgm2;
    p.inverse_inertia_body_ = body.inertia_cg_kgm2.inverse();
    p.vertices_body_ = vertices_body(body);
    for (const Eigen::Vector3d& v : p.vertices_body_) p.reach_m_ = std::max(p.reach_m_, v.norm());
    p.t_s_ = t_s;
    const auto& q = s.q;
    p.x_ = {s.p_m.x(),        s.p_m.y(),        s.p_m.z(),        q.w(), q.x(), q.y(), q.z(),
            s.twist.v_mps.x(), s.twist.v_mps.y(), s.twist.v_mps.z(),
            s.twist.w_radps.x(), s.twist.w_radps.y(), s.twist.w_radps.z()};
    if (!all_hold(p.margins(seg, t_s, p.x_))) return std::nullopt;
    return p;
}

EdgeSlide::Derivatives EdgeSlide::derivatives(const BiaxialSegment& seg, double t,
                                              const X& x) const {
    const Eigen::Quaterniond q = orientation(x);
    const Eigen::Matrix3d R = q.toRotationMatrix();
    const Eigen::Vector3d v(x[7], x[8], x[9]), w(x[10], x[11], x[12]);
    const Eigen::Matrix3d inverse_inertia = R * inverse_inertia_body_ * R.transpose();
    const auto a = seg.a(t);
    const Eigen::Vector3d load_per_kg(-a[0], -a[1], -seg.G(t));
    // Free of the floor: the load and the gyroscopic moment.
    const Eigen::Vector3d w_dot_free =
        inverse_inertia * (-w.cross(R * inertia_body_ * R.transpose() * w));
    const std::array<Eigen::Vector3d, 2> r{R * vertices_body_[from_], R * vertices_body_[to_]};
    std::array<Eigen::Vector3d, 2> unit_force{};  // the floor's force per newton of normal force
    for (std::size_t j = 0; j < 2; ++j)
        unit_force[j] = Eigen::Vector3d::UnitZ() - mu_k_ * slip_direction(v + w.cross(r[j]));
    // Vertical acceleration of vertex i: b_i + sum_j A_ij n_j = 0.
    Eigen::Matrix2d A;
    Eigen::Vector2d b;
    for (std::size_t i = 0; i < 2; ++i) {
        const auto ii = static_cast<Eigen::Index>(i);
        b(ii) = load_per_kg.z() + w_dot_free.cross(r[i]).z() + w.cross(w.cross(r[i])).z();
        for (std::size_t j = 0; j < 2; ++j)
            A(ii, static_cast<Eigen::Index>(j)) =
                unit_force[j].z() / mass_kg_ +
                (inverse_inertia * r[j].cross(unit_force[j])).cross(r[i]).z();
    }
    Derivatives out;
    const double det = A.determinant();
    // A's entries are of the order of 1 / M: scaled by M they are of the order of 1.
    out.well_posed = {A(0, 0) * mass_kg_, A(1, 1) * mass_kg_, det * mass_kg_ * mass_kg_};
    const Eigen::Vector2d n = det != 0.0 ? Eigen::Vector2d(A.inverse() * -b) : Eigen::Vector2d::Zero();
    out.normal_N = {n(0), n(1)};
    Eigen::Vector3d force_N = mass_kg_ * load_per_kg, moment_Nm = Eigen::Vector3d::Zero();
    for (std::size_t j = 0; j < 2; ++j) {
        const Eigen::Vector3d f = n(static_cast<Eigen::Index>(j)) * unit_force[j];
        force_N += f;
        moment_Nm += r[j].cross(f);
    }
    const Eigen::Vector3d v_dot = force_N / mass_kg_;
    const Eigen::Vector3d w_dot = w_dot_free + inverse_inertia * moment_Nm;
    // q' = (0, w) q / 2.
    const Eigen::Quaterniond q_dot = Eigen::Quaterniond(0.0, w.x(), w.y(), w.z()) * q;
    out.dx = {v.x(),          v.y(),          v.z(),          0.5 * q_dot.w(), 0.5 * q_dot.x(),
              0.5 * q_dot.y(), 0.5 * q_dot.z(), v_dot.x(),     v_dot.y(),       v_dot.z(),
              w_dot.x(),      w_dot.y(),      w_dot.z()};
    return out;
}

std::array<double, 8> EdgeSlide::margins(const BiaxialSegment& seg, double t, const X& x) const {
    const Derivatives d = derivatives(seg, t, x);
    const Eigen::Matrix3d R = orientation(x).toRotationMatrix();
    const Eigen::Vector3d p(x[0], x[1], x[2]), v(x[7], x[8], x[9]), w(x[10], x[11], x[12]);
    std::array<double, 8> out{};
    const double weight_N = mass_kg_ * g_mps2_;
    out[0] = d.normal_N[0] / weight_N;
    out[1] = d.normal_N[1] / weight_N;
    const std::array<std::size_t, 2> edge{from_, to_};
    for (std::size_t i = 0; i < 2; ++i) {
        const Eigen::Vector3d u = v + w.cross(R * vertices_body_[edge[i]]);
        out[2 + i] = (std::hypot(u.x(), u.y()) - slow_mps_) / slow_mps_;
    }
    out[4] = d.well_posed[0];
    out[5] = d.well_posed[1];
    out[6] = d.well_posed[2];
    // The other vertices' least height over the footprint's reach.
    double lowest_m = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < vertices_body_.size(); ++k)
        if (k != from_ && k != to_)
            lowest_m = std::min(lowest_m, p.z() + R.row(2).dot(vertices_body_[k]));
    out[7] = lowest_m / reach_m_;
    return out;
}

PhaseRun EdgeSlide::advance(const BiaxialSegment& seg, double t_end_s) {
    const auto rhs = [&](const X& x, X& k, double t) { k = derivatives(seg, t, x).dx; };
    const auto margins_at = [&](double t, const X& x) { return margins(seg, t, x); };
    return advance_phase(t_s_, x_, h_try_s_, t_end_s, rhs, margins_at);
}

BodyState EdgeSlide::state() const {
    BodyState s;
    s.p_m = Eigen::Vector3d(x_[0], x_[1], x_[2]);
    s.q = orientation(x_);
    s.twist.v_mps = Eigen::Vector3d(x_[7], x_[8], x_[9]);
    s.twist.w_radps = Eigen::Vector3d(x_[10], x_[11], x_[12]);
    return s;
}

std::array<Eigen::Vector3d, 2> EdgeSlide::vertex_forces_N(const BiaxialSegment& seg) const {
    const Derivatives d = derivatives(seg, t_s_, x_);
    const BodyState s = state();
    const Eigen::Matrix3d R = s.q.toRotationMatrix();
    std::array<Eigen::Vector3d, 2> out{};
    const std::array<std::size_t, 2> edge{from_, to_};
    for (std::size_t j = 0; j < 2; ++j)
        out[j] = d.normal_N[j] *
                 (Eigen::Vector3d::UnitZ() -
                  mu_k_ * slip_direction(s.twist.at(R * vertices_body_[edge[j]])));
    return out;
}

}  // namespace freestand::dynamics::detail
