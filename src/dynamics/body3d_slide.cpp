// The 3D body sliding flat (docs/methods.md s.11): on its whole footprint, not turning, the
// body is the biaxial sliding block, M u'' = -M a - mu_k M G u'/|u'| (docs/methods.md s.4),
// as long as the floor's pressure stays inside the footprint: with no rotation the floor's
// force has no moment about the CG, so its centre of pressure lies mu_k h ahead of the CG's
// plan position along the slip (h the CG's height).
#include <algorithm>
#include <cmath>

#include "dynamics/body3d_phases_detail.hpp"

namespace freestand::dynamics::detail {

std::optional<FlatSlide> FlatSlide::start(const Body3dModel& model, const BodyState& s,
                                          const BiaxialSegment& seg, double t_s, double g_mps2,
                                          double slow_mps) {
    FlatSlide p;
    p.mu_k_ = model.mu_k;
    p.g_mps2_ = g_mps2;
    p.slow_mps_ = slow_mps;
    p.q_ = s.q;
    p.height_m_ = s.p_m.z();
    const Eigen::Matrix3d R = s.q.toRotationMatrix();
    for (const FootprintEdge& e : footprint_edges(model.body)) {
        const Eigen::Vector2d n_world =
            (R * Eigen::Vector3d(e.normal.x(), e.normal.y(), 0.0)).head<2>();
        p.edges_.emplace_back(n_world.normalized(), e.distance_m);
    }
    p.t_s_ = t_s;
    p.x_ = {s.p_m.x(), s.p_m.y(), s.twist.v_mps.x(), s.twist.v_mps.y()};
    if (!all_hold(p.margins(seg, t_s, p.x_))) return std::nullopt;
    return p;
}

std::array<double, 3> FlatSlide::margins(const BiaxialSegment& seg, double t, const X& x) const {
    const Eigen::Vector2d u(x[2], x[3]);
    const double speed = u.norm();
    double pressure = 1.0;
    if (speed > 0.0) {
        const Eigen::Vector2d ahead = mu_k_ * height_m_ / speed * u;
        for (const auto& [normal, distance_m] : edges_)
            pressure = std::min(pressure, (distance_m - normal.dot(ahead)) / distance_m);
    }
    return {(speed - slow_mps_) / slow_mps_, seg.G(t) / g_mps2_, pressure};
}

PhaseRun FlatSlide::advance(const BiaxialSegment& seg, double t_end_s) {
    const auto rhs = [&](const X& x, X& k, double t) {
        const auto a = seg.a(t);
        const double speed = std::hypot(x[2], x[3]);
        const double friction = speed > 0.0 ? mu_k_ * seg.G(t) / speed : 0.0;
        k = {x[2], x[3], -a[0] - friction * x[2], -a[1] - friction * x[3]};
    };
    const auto margins_at = [&](double t, const X& x) { return margins(seg, t, x); };
    return advance_phase(t_s_, x_, h_try_s_, t_end_s, rhs, margins_at);
}

BodyState FlatSlide::state() const {
    BodyState s;
    s.q = q_;
    s.p_m = Eigen::Vector3d(x_[0], x_[1], height_m_);
    s.twist.v_mps = Eigen::Vector3d(x_[2], x_[3], 0.0);
    return s;
}

Eigen::Vector2d FlatSlide::slip_direction() const {
    const Eigen::Vector2d u(x_[2], x_[3]);
    return u.norm() > 0.0 ? Eigen::Vector2d(u.normalized()) : Eigen::Vector2d::Zero();
}

}  // namespace freestand::dynamics::detail
