// The 3D body's contact impulses at one step: projected Gauss-Seidel over the vertices on the
// floor, with Newton's impact law and Coulomb's cone at each (Moreau 1988; Jean 1999; the
// per-contact splitting of Siconos's nonsmooth Gauss-Seidel solver).
#include <algorithm>
#include <cmath>

#include "dynamics/body3d_detail.hpp"

namespace freestand::dynamics::detail {

namespace {

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& r) {
    Eigen::Matrix3d m;
    m << 0.0, -r.z(), r.y(), r.z(), 0.0, -r.x(), -r.y(), r.x(), 0.0;
    return m;
}

/// One contact's Gauss-Seidel update given the body's current velocities: the new impulse.
Eigen::Vector3d updated_impulse(const VertexContact& c, const Eigen::Matrix3d& W, double eps,
                                const Eigen::Vector3d& u) {
    const Eigen::Vector3d& p = c.impulse_Ns;
    // Newton: the normal velocity to keep non-negative is u_n + e u_n^- (u_n^- the approach).
    const double target_n = u.z() + c.restitution * std::min(c.approach_mps, 0.0);
    const double pn = std::max(0.0, p.z() - (target_n + eps * p.z()) / (W(2, 2) + eps));
    // The tangential impulse: a step against the slip, then the projection onto the cone. The
    // step is a scalar multiple of the slip so that the fixed point's friction opposes the slip
    // exactly (a matrix step would tilt it by W's anisotropy); 1 / mean(W_tt) keeps it stable.
    const Eigen::Vector2d u_t = u.head<2>() + W.block<2, 1>(0, 2) * (pn - p.z());
    const double rho = 2.0 / (W(0, 0) + W(1, 1) + 2.0 * eps);
    Eigen::Vector2d pt = p.head<2>() - rho * (u_t + eps * p.head<2>());
    const double limit = c.mu * pn;
    const double norm = pt.norm();
    if (norm > limit) pt *= (norm > 0.0 ? limit / norm : 0.0);
    return {pt.x(), pt.y(), pn};
}

}  // namespace

Eigen::Matrix3d MassMatrix::delassus(const Eigen::Vector3d& r_m) const {
    const Eigen::Matrix3d rx = cross_matrix(r_m);
    return Eigen::Matrix3d::Identity() / mass_kg - rx * inverse_inertia * rx;
}

ImpulseSolve solve_impulses(std::vector<VertexContact>& contacts, const MassMatrix& mass,
                            Twist& twist, double tol_mps, std::size_t max_sweeps,
                            double regularization) {
    const double eps = regularization / mass.mass_kg;
    for (auto& c : contacts) {
        c.delassus = mass.delassus(c.r_m);
        mass.apply(twist, c.r_m, c.impulse_Ns);  // the warm start
    }
    ImpulseSolve out;
    while (out.sweeps < max_sweeps) {
        ++out.sweeps;
        const Twist before = twist;
        for (auto& c : contacts) {
            const Eigen::Vector3d p = updated_impulse(c, c.delassus, eps, twist.at(c.r_m));
            mass.apply(twist, c.r_m, p - c.impulse_Ns);
            c.impulse_Ns = p;
        }
        // Converged when a sweep no longer changes the velocity of any contact point: the
        // motion is unique, while the impulses of four coplanar contacts need not be.
        double change_mps = 0.0;
        for (const auto& c : contacts)
            change_mps = std::max(change_mps, (twist.at(c.r_m) - before.at(c.r_m)).norm());
        if (change_mps <= tol_mps) {
            out.converged = true;
            break;
        }
    }
    return out;
}

Eigen::Quaterniond turned(const Eigen::Quaterniond& q, const Eigen::Vector3d& w_radps, double dt_s) {
    const double angle = w_radps.norm() * dt_s;
    if (angle == 0.0) return q;
    const Eigen::Quaterniond dq(Eigen::AngleAxisd(angle, w_radps.normalized()));
    return (dq * q).normalized();
}

}  // namespace freestand::dynamics::detail
