// The 3D body's contact impulses at one step: projected Gauss-Seidel over the vertices on the
// floor, with Newton's impact law and Coulomb's cone at each (Moreau 1988; Jean 1999; the
// per-contact splitting of Siconos's nonsmooth Gauss-Seidel solver).
#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/Cholesky>

#include "dynamics/body3d_detail.hpp"

namespace freestand::dynamics::detail {

namespace {

/// One contact's Gauss-Seidel update given the body's current velocities: the new impulse.
Eigen::Vector3d updated_impulse(const VertexContact& c, const Eigen::Matrix3d& W, double eps,
                                const Eigen::Vector3d& u) {
    const Eigen::Vector3d& p = c.impulse_Ns;
    // Newton: the normal velocity to keep non-negative is u_n + e u_n^- (u_n^- the approach).
    const double target_n = u.z() - c.newton_floor_mps();
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

// Contacts the direct solve takes: a rectangle's four vertices (a 12 x 12 system).
constexpr std::size_t direct_max_contacts = 4;
using Square = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3 * direct_max_contacts,
                             3 * direct_max_contacts>;
using Column = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3 * direct_max_contacts, 1>;

// The contacts the direct solve keeps loaded, by index (fixed capacity: a step allocates nothing).
struct Active {
    std::array<std::size_t, direct_max_contacts> index{};
    std::size_t count = 0;

    std::size_t size() const { return count; }
    bool empty() const { return count == 0; }
    std::size_t operator[](std::size_t i) const { return index[i]; }
    void erase(std::size_t i) {
        std::copy(index.begin() + static_cast<std::ptrdiff_t>(i + 1),
                  index.begin() + static_cast<std::ptrdiff_t>(count),
                  index.begin() + static_cast<std::ptrdiff_t>(i));
        --count;
    }
    bool contains(std::size_t k) const {
        return std::find(index.begin(), index.begin() + static_cast<std::ptrdiff_t>(count), k) !=
               index.begin() + static_cast<std::ptrdiff_t>(count);
    }
};

// The impulses when every contact of `active` sticks and keeps its Newton velocity: the
// regularised system (W + eps I) P = target - u_free over the active contacts, W the Delassus
// matrix (W_ij = I / M - [r_i]x I^-1 [r_j]x). With four coplanar contacts W is singular and
// eps picks the least-norm impulses among those giving the same motion (Tikhonov).
Column sticking_impulses(const std::vector<VertexContact>& contacts,
                         const Active& active, const MassMatrix& mass,
                         const Twist& free, double eps) {
    const auto n = static_cast<Eigen::Index>(active.size());
    Square W(3 * n, 3 * n);
    Column rhs(3 * n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const VertexContact& ci = contacts[active[i]];
        for (Eigen::Index j = 0; j < n; ++j)
            W.block<3, 3>(3 * i, 3 * j) = mass.delassus(ci.r_m, contacts[active[j]].r_m);
        const Eigen::Vector3d target(0.0, 0.0, ci.newton_floor_mps());
        rhs.segment<3>(3 * i) = target - free.at(ci.r_m);
    }
    W.diagonal().array() += eps;
    return Eigen::LDLT<Square>(W).solve(rhs);
}

// The same wrench with the tangential impulses shared in proportion to the normal ones: among
// the tangential impulses with the same resultant force and moment (so the same motion), the
// one minimising sum |p_t,i|^2 / p_n,i. The least-norm impulses share friction evenly, which a
// vertex about to lift cannot carry although the body as a whole sticks.
void share_friction_by_load(const std::vector<VertexContact>& contacts,
                            const Active& active, Column& P) {
    const auto n = static_cast<Eigen::Index>(active.size());
    Eigen::Matrix<double, 5, Eigen::Dynamic, 0, 5, 2 * direct_max_contacts> A(5, 2 * n);
    Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 2 * direct_max_contacts, 1> load(2 * n), pt(2 * n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Vector3d& r = contacts[active[i]].r_m;
        // Rows: force x, y; moment x, y, z of (p_x, p_y, 0) at r.
        A.block<5, 2>(0, 2 * i) << 1.0, 0.0, 0.0, 1.0, 0.0, -r.z(), r.z(), 0.0, -r.y(), r.x();
        load.segment<2>(2 * i).setConstant(P(3 * i + 2));
        pt.segment<2>(2 * i) = P.segment<2>(3 * i);
    }
    const Eigen::Matrix<double, 5, 1> wrench = A * pt;
    Eigen::Matrix<double, 5, 5> S = A * load.asDiagonal() * A.transpose();
    S.diagonal().array() += 1e-12 * S.trace();
    const Eigen::Matrix<double, 5, 1> y = Eigen::LDLT<Eigen::Matrix<double, 5, 5>>(S).solve(wrench);
    pt = load.asDiagonal() * (A.transpose() * y);
    for (Eigen::Index i = 0; i < n; ++i) P.segment<2>(3 * i) = pt.segment<2>(2 * i);
}

bool inside_cones(const std::vector<VertexContact>& contacts,
                  const Active& active, const Column& P) {
    for (std::size_t i = 0; i < active.size(); ++i)
        if (P.segment<2>(3 * i).norm() > contacts[active[i]].mu * P(3 * i + 2)) return false;
    return true;
}

// The step's impulses when every contact carrying load sticks (rest, or rocking about a sticking
// edge or vertex: most steps). Contacts whose normal impulse comes out negative leave the
// active set one at a time, as in an active-set method. False, with nothing changed, when the
// answer leaves a cone or lets a released contact sink: the contact problem then needs the
// sweeps (slip).
bool solved_sticking(std::vector<VertexContact>& contacts, const MassMatrix& mass, Twist& twist,
                     double eps, double tol_mps, double resting_mps) {
    if (contacts.empty() || contacts.size() > direct_max_contacts) return false;
    // An impact (a vertex arriving faster than gravity moves it in a step) needs the sweeps:
    // with friction its solution need not be unique, and the sweeps reach Housner's one (the
    // arriving vertex takes the load, the pivot releases), which the checks verify.
    if (has_impact(contacts, resting_mps)) return false;
    Active active;
    for (std::size_t k = 0; k < contacts.size(); ++k) active.index[active.count++] = k;
    while (!active.empty()) {
        const Column sticking = sticking_impulses(contacts, active, mass, twist, eps);
        std::size_t worst = active.size();
        for (std::size_t i = 0; i < active.size(); ++i)
            if (sticking(3 * i + 2) < 0.0 &&
                (worst == active.size() || sticking(3 * i + 2) < sticking(3 * worst + 2)))
                worst = i;
        if (worst != active.size()) {
            active.erase(worst);
            continue;
        }
        Column P = sticking;
        if (!inside_cones(contacts, active, P)) {
            if (active.size() < 2) return false;
            share_friction_by_load(contacts, active, P);
            if (!inside_cones(contacts, active, P)) return false;
        }
        Twist after = twist;
        for (std::size_t i = 0; i < active.size(); ++i)
            mass.apply(after, contacts[active[i]].r_m, P.segment<3>(3 * i));
        for (std::size_t k = 0; k < contacts.size(); ++k) {
            const VertexContact& c = contacts[k];
            if (active.contains(k)) continue;
            if (after.at(c.r_m).z() < c.newton_floor_mps() - tol_mps) return false;
        }
        for (auto& c : contacts) c.impulse_Ns.setZero();
        for (std::size_t i = 0; i < active.size(); ++i)
            contacts[active[i]].impulse_Ns = P.segment<3>(3 * i);
        twist = after;
        return true;
    }
    return false;
}

}  // namespace

Eigen::Matrix3d MassMatrix::delassus(const Eigen::Vector3d& r_i_m,
                                     const Eigen::Vector3d& r_j_m) const {
    if (inverse_generalized) {
        // [1, -[r_i]x] B [1; [r_j]x], B the inverse's (v, w) block: the impulses' Jacobians
        // have no q' column.
        Eigen::Matrix<double, 3, 6> H_i;
        H_i << Eigen::Matrix3d::Identity(), -cross_matrix(r_i_m);
        Eigen::Matrix<double, 6, 3> H_j_T;
        H_j_T << Eigen::Matrix3d::Identity(), cross_matrix(r_j_m);
        return H_i * inverse_generalized->topRows<6>() * H_j_T;
    }
    return Eigen::Matrix3d::Identity() / mass_kg -
           cross_matrix(r_i_m) * inverse_inertia * cross_matrix(r_j_m);
}

ImpulseSolve solve_impulses(std::vector<VertexContact>& contacts, const MassMatrix& mass,
                            Twist& twist, double tol_mps, double resting_mps,
                            std::size_t max_sweeps, double regularization) {
    const double eps = regularization / mass.mass_kg;
    ImpulseSolve out;
    if (solved_sticking(contacts, mass, twist, eps, tol_mps, resting_mps)) {
        out.converged = true;
        out.sticking = true;
        return out;
    }
    for (auto& c : contacts) {
        c.delassus = mass.delassus(c.r_m);
        mass.apply(twist, c.r_m, c.impulse_Ns);  // the warm start
    }
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
