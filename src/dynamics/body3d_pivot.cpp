// The 3D body's edge phases (docs/methods.md s.11): a rigid body rocking about a footprint edge
// whose two vertices stick turns about that fixed line, one degree of freedom, as the planar
// block turns about its corner (Housner 1963), here with the edge and the CG anywhere in the
// body. Its equation, its reactions and the limits of the phase follow.
#include "dynamics/body3d_phases_detail.hpp"

#include <algorithm>
#include <cmath>


namespace freestand::dynamics::detail {

namespace {

/// x turned by psi about the unit axis e: (x.e) e + cos psi x_perp + sin psi e x x.
Eigen::Vector3d turned_about(const Eigen::Vector3d& e, double psi, const Eigen::Vector3d& x) {
    const double along = x.dot(e);
    const Eigen::Vector3d perp = x - along * e;
    return along * e + std::cos(psi) * perp + std::sin(psi) * e.cross(x);
}

/// The inertia force of the base and the weight on a unit mass, (-a_x, -a_y, -G), m/s^2.
Eigen::Vector3d load_per_kg(const BiaxialSegment& seg, double t) {
    const auto a = seg.a(t);
    return {-a[0], -a[1], -seg.G(t)};
}

/// sqrt(a) for a >= 0, -sqrt(-a) below: a margin that keeps its sign and stays continuous.
double signed_root(double a) { return a >= 0.0 ? std::sqrt(a) : -std::sqrt(-a); }

}  // namespace

std::optional<EdgePivot> EdgePivot::start(const Body3dModel& model, const BodyState& s,
                                          std::size_t from, std::size_t to,
                                          const BiaxialSegment& seg, double t_s, double g_mps2) {
    const Body3d& body = model.body;
    const Eigen::Matrix3d R = s.q.toRotationMatrix();
    const auto vertex = [&](std::size_t i) { return vertex_body(body, i); };
    EdgePivot p;
    p.from_ = from;
    p.to_ = to;
    p.mass_kg_ = body.mass_kg;
    p.mu_s_ = model.mu_s;
    p.g_mps2_ = g_mps2;
    p.origin_m_ = s.p_m + R * vertex(from);
    const Eigen::Vector3d edge = R * (vertex(to) - vertex(from));
    p.length_m_ = edge.norm();
    p.axis_ = edge / p.length_m_;
    // The footprint's inward direction from the edge, b x e (b the body's vertical): turning
    // by +psi about e takes it towards b, lifting the footprint; its rise is the tilt.
    const Eigen::Vector3d inward = R.col(2).cross(p.axis_);
    p.lift0_rad_ = std::asin(std::clamp(inward.z(), -1.0, 1.0));
    p.q0_ = s.q;
    p.cg0_m_ = s.p_m - p.origin_m_;
    p.along_m_ = p.cg0_m_.dot(p.axis_);
    p.arm0_m_ = p.cg0_m_ - p.along_m_ * p.axis_;
    p.inertia0_ = R * body.inertia_cg_kgm2 * R.transpose() * p.axis_;
    p.inertia_axis_kgm2_ = p.axis_.dot(p.inertia0_) + body.mass_kg * p.arm0_m_.squaredNorm();
    p.t_s_ = t_s;
    p.x_ = {0.0, s.twist.w_radps.dot(p.axis_)};
    if (!all_hold(p.margins(seg, t_s, p.x_))) return std::nullopt;
    return p;
}

double EdgePivot::accel(const BiaxialSegment& seg, double t, double psi) const {
    // I_e psi'' = e . (d x M F) = M F . (e x d), e x d = cos psi (e x arm0) - sin psi arm0.
    const Eigen::Vector3d e_cross_d =
        std::cos(psi) * axis_.cross(arm0_m_) - std::sin(psi) * arm0_m_;
    return mass_kg_ * load_per_kg(seg, t).dot(e_cross_d) / inertia_axis_kgm2_;
}

std::array<Eigen::Vector3d, 2> EdgePivot::forces_at(const BiaxialSegment& seg, double t,
                                                    const X& x) const {
    const double psi = x[0], rate = x[1];
    const Eigen::Vector3d F = load_per_kg(seg, t);
    const Eigen::Vector3d arm = turned_about(axis_, psi, arm0_m_);
    const Eigen::Vector3d d = along_m_ * axis_ + arm;
    const double acc = accel(seg, t, psi);
    // Newton: M c'' = R + M F, c'' = psi'' e x d - psi'^2 arm.
    const Eigen::Vector3d cg_acc = acc * axis_.cross(d) - rate * rate * arm;
    const Eigen::Vector3d total = mass_kg_ * (cg_acc - F);
    // Euler about the origin (a fixed point): M_O = I_O e psi'' + psi'^2 e x I_O e - d x M F,
    // with I_O e = I e + M (|d|^2 e - d (d.e)).
    const Eigen::Vector3d I_e = turned_about(axis_, psi, inertia0_) +
                                mass_kg_ * (d.squaredNorm() * axis_ - d * d.dot(axis_));
    const Eigen::Vector3d moment =
        acc * I_e + rate * rate * axis_.cross(I_e) - mass_kg_ * d.cross(F);
    // The vertex at L e carries the moment's part normal to e (L e x f2 = M_O); the vertex at
    // the origin the rest of the force normal to e.
    const Eigen::Vector3d f_to = (moment / length_m_).cross(axis_);
    const double along_N = total.dot(axis_);
    const Eigen::Vector3d f_from = total - along_N * axis_ - f_to;
    const double n_sum = f_from.z() + f_to.z();
    const double share = n_sum > 0.0 ? f_from.z() / n_sum : 0.5;
    return {f_from + share * along_N * axis_, f_to + (1.0 - share) * along_N * axis_};
}

double EdgePivot::hold(const BiaxialSegment& seg, double t, const X& x) const {
    const auto f = forces_at(seg, t, x);
    // The force along the edge may be shared between its vertices at will: the edge holds when
    // each vertex's cone has room for its force normal to the edge and the two cones' spare
    // radii cover the force along it.
    double along_N = 0.0;
    std::array<double, 2> normal_N{}, spare_N{};
    for (std::size_t i = 0; i < 2; ++i) {
        along_N += f[i].dot(axis_);
        const Eigen::Vector3d across = f[i] - f[i].dot(axis_) * axis_;
        normal_N[i] = across.z();
        const double tangential_sq = across.squaredNorm() - normal_N[i] * normal_N[i];
        spare_N[i] = signed_root(mu_s_ * mu_s_ * normal_N[i] * normal_N[i] - tangential_sq);
    }
    const double least =
        std::min({normal_N[0], normal_N[1], spare_N[0], spare_N[1],
                  spare_N[0] + spare_N[1] - std::abs(along_N)});
    return least / (mass_kg_ * g_mps2_);
}

std::array<Eigen::Vector3d, 2> EdgePivot::vertex_forces_N(const BiaxialSegment& seg) const {
    return forces_at(seg, t_s_, x_);
}

BodyState EdgePivot::state() const {
    BodyState s;
    const Eigen::AngleAxisd turn(x_[0], axis_);
    s.q = (Eigen::Quaterniond(turn) * q0_).normalized();
    s.p_m = origin_m_ + turn * cg0_m_;
    s.twist.w_radps = x_[1] * axis_;
    s.twist.v_mps = s.twist.w_radps.cross(s.p_m - origin_m_);
    return s;
}

PhaseRun EdgePivot::advance(const BiaxialSegment& seg, double t_end_s) {
    const auto rhs = [&](const X& x, X& k, double t) {
        k[0] = x[1];
        k[1] = accel(seg, t, x[0]);
    };
    const auto margins_at = [&](double t, const X& x) { return margins(seg, t, x); };
    return advance_phase(t_s_, x_, h_try_s_, t_end_s, rhs, margins_at);
}

}  // namespace freestand::dynamics::detail
