#pragma once
/// Internal: the 3D body's state, its Moreau-Jean step and the contact impulse problem
/// (docs/methods.md s.11).
#include <algorithm>
#include <cstddef>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dynamics/body3d.hpp"

namespace freestand::dynamics::detail {

/// A vertex slipping slower than this, m/s, was sticking: its cone is mu_s, else mu_k.
inline constexpr double stick_speed_mps = 1e-6;

/// One vertex on or below the floor at a step's midpoint.
struct VertexContact {
    std::size_t vertex = 0;     ///< index into the footprint
    Eigen::Vector3d r_m;        ///< from the CG to the vertex, world axes
    double mu = 0.0;            ///< cone radius
    double restitution = 0.0;   ///< Newton's coefficient
    double approach_mps = 0.0;  ///< normal velocity at the step's start (< 0: approaching)
    Eigen::Vector3d impulse_Ns = Eigen::Vector3d::Zero();  ///< the solution (warm start on entry)
    Eigen::Matrix3d delassus = Eigen::Matrix3d::Zero();    ///< set by solve_impulses

    /// Newton's floor on the normal velocity after the step: -e min(approach, 0), m/s.
    double newton_floor_mps() const { return -restitution * std::min(approach_mps, 0.0); }
};

/// Some contact arrives faster than resting_mps (an impact, not a contact resting on the floor).
inline bool has_impact(const std::vector<VertexContact>& contacts, double resting_mps) {
    return std::any_of(contacts.begin(), contacts.end(),
                       [&](const VertexContact& c) { return c.approach_mps < -resting_mps; });
}

/// The body's velocities, world axes: the CG's relative to the base and the angular one.
struct Twist {
    Eigen::Vector3d v_mps = Eigen::Vector3d::Zero();
    Eigen::Vector3d w_radps = Eigen::Vector3d::Zero();

    /// Velocity of the body point at r_m from the CG, m/s.
    Eigen::Vector3d at(const Eigen::Vector3d& r_m) const { return v_mps + w_radps.cross(r_m); }
};

/// The mass properties a step needs.
struct MassMatrix {
    double mass_kg = 1.0;
    Eigen::Matrix3d inverse_inertia = Eigen::Matrix3d::Identity();  ///< world axes, 1/(kg m^2)

    /// The velocity change of an impulse p_Ns applied at r_m.
    void apply(Twist& t, const Eigen::Vector3d& r_m, const Eigen::Vector3d& p_Ns) const {
        t.v_mps += p_Ns / mass_kg;
        t.w_radps += inverse_inertia * r_m.cross(p_Ns);
    }
    /// Delassus block of two contacts: the velocity at r_i per unit impulse at r_j,
    /// I / M - [r_i]x I^-1 [r_j]x.
    Eigen::Matrix3d delassus(const Eigen::Vector3d& r_i_m, const Eigen::Vector3d& r_j_m) const;
    /// Delassus block of a contact with itself.
    Eigen::Matrix3d delassus(const Eigen::Vector3d& r_m) const { return delassus(r_m, r_m); }
};

struct ImpulseSolve {
    std::size_t sweeps = 0;
    bool converged = false;
    bool sticking = false;  ///< solved directly, every loaded contact sticking
};

/// Solves the step's contact problem: Newton's law on each contact's normal velocity
/// (u_n + e min(approach, 0) >= 0, complementary to the normal impulse) and Coulomb's cone on
/// the tangential one (|p_t| <= mu p_n, opposing the slip when it slides), regularised by
/// regularization / M (Tikhonov: among impulses giving the same motion, the least-norm ones).
/// `twist` goes from free to final.
///  - Without an impact (no contact approaching faster than resting_mps) and with at most four
///    contacts, it first tries every loaded contact sticking: one linear solve, contacts with a
///    negative normal impulse released one by one; kept when the impulses lie in their cones
///    (friction shared by load if need be) and no released contact sinks.
///  - Otherwise projected Gauss-Seidel sweeps from the contacts' impulses (the warm start) until
///    a sweep changes no contact point's velocity by more than tol_mps: the motion is then unique
///    to that tolerance, while the impulses of more than three coplanar contacts are not.
ImpulseSolve solve_impulses(std::vector<VertexContact>& contacts, const MassMatrix& mass,
                            Twist& twist, double tol_mps, double resting_mps,
                            std::size_t max_sweeps, double regularization);

/// Position and velocities. The CG's position is relative to the base (its plan position at
/// rest is the origin, its height the CG height), the orientation body-to-world.
struct BodyState {
    Eigen::Vector3d p_m = Eigen::Vector3d::Zero();
    Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
    Twist twist;
};

/// The orientation turned by the world angular velocity w over dt_s.
Eigen::Quaterniond turned(const Eigen::Quaterniond& q, const Eigen::Vector3d& w_radps, double dt_s);

}  // namespace freestand::dynamics::detail
