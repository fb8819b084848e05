#pragma once
/// Internal: the 3D body's state, its Moreau-Jean step and the contact impulse problem
/// (docs/methods.md s.11).
#include <algorithm>
#include <cstddef>
#include <optional>
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

/// The body's velocities, world axes: the CG's relative to the base (with a mode: the body
/// point where the CG is at q = 0) and the angular one; with a mode, the modal rates q' (body
/// axes x, y).
struct Twist {
    Eigen::Vector3d v_mps = Eigen::Vector3d::Zero();
    Eigen::Vector3d w_radps = Eigen::Vector3d::Zero();
    Eigen::Vector2d q_mps = Eigen::Vector2d::Zero();

    /// Velocity of the body point at r_m from the CG, m/s.
    Eigen::Vector3d at(const Eigen::Vector3d& r_m) const { return v_mps + w_radps.cross(r_m); }
};

/// [r]x: the matrix of r x (.).
inline Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& r) {
    Eigen::Matrix3d m;
    m << 0.0, -r.z(), r.y(), r.z(), 0.0, -r.x(), -r.y(), r.x(), 0.0;
    return m;
}

using Matrix8d = Eigen::Matrix<double, 8, 8>;
using Vector8d = Eigen::Matrix<double, 8, 1>;
using Vector6d = Eigen::Matrix<double, 6, 1>;

/// The mass properties a step needs.
struct MassMatrix {
    double mass_kg = 1.0;
    Eigen::Matrix3d inverse_inertia = Eigen::Matrix3d::Identity();  ///< world axes, 1/(kg m^2)
    /// With a mode: the first six columns of the inverse of the generalised mass matrix over
    /// (v, w, q') (the impulses act on v and w only); it then stands for mass_kg and
    /// inverse_inertia in apply and delassus.
    std::optional<Eigen::Matrix<double, 8, 6>> inverse_generalized;

    /// The velocity change of an impulse p_Ns applied at r_m.
    void apply(Twist& t, const Eigen::Vector3d& r_m, const Eigen::Vector3d& p_Ns) const {
        if (inverse_generalized) {
            Vector6d force;
            force << p_Ns, r_m.cross(p_Ns);
            const Vector8d du = *inverse_generalized * force;
            t.v_mps += du.head<3>();
            t.w_radps += du.segment<3>(3);
            t.q_mps += du.tail<2>();
            return;
        }
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
    Eigen::Vector2d modal_m = Eigen::Vector2d::Zero();  ///< q_x, q_y of the mode, body axes
    Twist twist;
};

/// A body with a mode split into its rigid rest and the modal mass (Body3dMode), body axes
/// from the CG at q = 0.
struct ModalSplit {
    double rest_kg = 0.0, modal_kg = 0.0;
    Eigen::Vector3d rest_cg_m = Eigen::Vector3d::Zero();    ///< the rigid rest's CG, c_r
    Eigen::Vector3d modal_rest_m = Eigen::Vector3d::Zero(); ///< the modal mass at q = 0, a_s
    Eigen::Matrix3d rest_inertia_kgm2 = Eigen::Matrix3d::Zero();  ///< about c_r
    Eigen::Vector2d omega_radps = Eigen::Vector2d::Zero();  ///< fixed-base, x and y
    double zeta = 0.0;
};
/// The split of model.mode (which must be set): m_s = fraction M, a_s = (0, 0, h_s - h),
/// c_r = -m_s a_s / (M - m_s), I_r = I - m_s (|a_s|^2 1 - a_s a_s^T) - (M - m_s)(|c_r|^2 1 -
/// c_r c_r^T) (parallel axes).
ModalSplit modal_split(const Body3dModel& model);

/// Generalised mass matrix over (v, w, q') at orientation R (body to world) and modal
/// displacement q: M_r J_r^T J_r + m_s J_s^T J_s + diag(0, R I_r R^T, 0), with the velocity
/// Jacobians of the rest's CG, J_r = [1, -[R c_r]x, 0], and of the modal mass,
/// J_s = [1, -[R (a_s + E q)]x, R E] (E the body's x and y axes).
Matrix8d generalized_mass(const ModalSplit& split, const Eigen::Matrix3d& R,
                          const Eigen::Vector2d& q_m);

/// Generalised force over (v, w, q') (Kane's equations): gravity G and the base's
/// acceleration a on both masses, less the velocity terms of their accelerations
/// (w x (w x rho) for each, 2 w x R E q' for the modal mass, w x I_r w for the rest), and the
/// modal springs and dampers -m_s (omega^2 q + 2 zeta omega q').
Vector8d generalized_force(const ModalSplit& split, const Eigen::Matrix3d& R,
                           const Eigen::Vector2d& q_m, const Twist& u,
                           const Eigen::Vector2d& a_mps2, double G_mps2);

/// (v, w, q') as one vector, and back.
Vector8d pack(const Twist& t);
Twist unpack(const Vector8d& u);

/// Footprint vertex i in body axes from the CG (z = -h).
inline Eigen::Vector3d vertex_body(const Body3d& body, std::size_t i) {
    return {body.footprint_m[i].x(), body.footprint_m[i].y(), -body.h_m};
}
/// Every footprint vertex in body axes from the CG, counter-clockwise.
std::vector<Eigen::Vector3d> vertices_body(const Body3d& body);
/// A footprint edge, from vertex i to i + 1, in plan, body axes: its outward unit normal and its
/// distance from the CG's plan position.
struct FootprintEdge {
    Eigen::Vector2d normal;
    double distance_m = 0.0;
};
std::vector<FootprintEdge> footprint_edges(const Body3d& body);

/// The orientation turned by the world angular velocity w over dt_s.
Eigen::Quaterniond turned(const Eigen::Quaterniond& q, const Eigen::Vector3d& w_radps, double dt_s);

}  // namespace freestand::dynamics::detail
