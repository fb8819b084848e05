// The 3D body's elastic modes (docs/methods.md s.11): the split into a rigid rest and a modal
// mass, the generalised mass matrix and forces over (v, w, q') (Kane's method), and the step
// limit of the scheme that integrates them.
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "core/errors.hpp"
#include "core/units.hpp"
#include "dynamics/body3d.hpp"
#include "dynamics/body3d_detail.hpp"
#include "dynamics/modal_checks.hpp"

namespace freestand::dynamics {

namespace detail {

namespace {

// The second moment of a point mass m at r about the origin: m (|r|^2 1 - r r^T).
Eigen::Matrix3d point_inertia(double mass_kg, const Eigen::Vector3d& r_m) {
    return mass_kg * (r_m.squaredNorm() * Eigen::Matrix3d::Identity() - r_m * r_m.transpose());
}

// Velocity Jacobian of a body point at rho (world, from the reference point) over (v, w, q'):
// [1, -[rho]x, modal], the last two columns the point's own motion along the body's axes.
Eigen::Matrix<double, 3, 8> point_jacobian(const Eigen::Vector3d& rho_m,
                                           const Eigen::Matrix<double, 3, 2>& modal) {
    Eigen::Matrix<double, 3, 8> J;
    J << Eigen::Matrix3d::Identity(), -cross_matrix(rho_m), modal;
    return J;
}

}  // namespace

ModalSplit modal_split(const Body3dModel& model) {
    const Body3dMode& mode = *model.mode;
    const Body3d& b = model.body;
    ModalSplit s;
    s.modal_kg = mode.mass_fraction * b.mass_kg;
    s.rest_kg = b.mass_kg - s.modal_kg;
    s.modal_rest_m = Eigen::Vector3d(0.0, 0.0, mode.height_m - b.h_m);
    s.rest_cg_m = -s.modal_kg / s.rest_kg * s.modal_rest_m;
    s.rest_inertia_kgm2 = b.inertia_cg_kgm2 - point_inertia(s.modal_kg, s.modal_rest_m) -
                          point_inertia(s.rest_kg, s.rest_cg_m);
    s.omega_radps = units::two_pi * Eigen::Vector2d(mode.frequency_x_hz, mode.frequency_y_hz);
    s.zeta = mode.damping;
    return s;
}

Matrix8d generalized_mass(const ModalSplit& s, const Eigen::Matrix3d& R,
                          const Eigen::Vector2d& q_m) {
    const Eigen::Matrix<double, 3, 2> along = R.leftCols<2>();
    const Eigen::Vector3d rho_s = R * (s.modal_rest_m + Eigen::Vector3d(q_m.x(), q_m.y(), 0.0));
    const auto J_r = point_jacobian(R * s.rest_cg_m, Eigen::Matrix<double, 3, 2>::Zero());
    const auto J_s = point_jacobian(rho_s, along);
    Matrix8d M = s.rest_kg * J_r.transpose() * J_r + s.modal_kg * J_s.transpose() * J_s;
    M.block<3, 3>(3, 3) += R * s.rest_inertia_kgm2 * R.transpose();
    return M;
}

Vector8d generalized_force(const ModalSplit& s, const Eigen::Matrix3d& R,
                           const Eigen::Vector2d& q_m, const Twist& u,
                           const Eigen::Vector2d& a_mps2, double G_mps2) {
    const Eigen::Matrix<double, 3, 2> along = R.leftCols<2>();
    const Eigen::Vector3d rho_r = R * s.rest_cg_m;
    const Eigen::Vector3d rho_s = R * (s.modal_rest_m + Eigen::Vector3d(q_m.x(), q_m.y(), 0.0));
    const Eigen::Vector3d& w = u.w_radps;
    // Gravity and the base's inertia force per unit mass, in the base's frame.
    const Eigen::Vector3d field(-a_mps2.x(), -a_mps2.y(), -G_mps2);
    const Eigen::Vector3d kappa_r = w.cross(w.cross(rho_r));
    const Eigen::Vector3d kappa_s = w.cross(w.cross(rho_s)) + 2.0 * w.cross(along * u.q_mps);
    Vector8d f =
        s.rest_kg * point_jacobian(rho_r, Eigen::Matrix<double, 3, 2>::Zero()).transpose() *
            (field - kappa_r) +
        s.modal_kg * point_jacobian(rho_s, along).transpose() * (field - kappa_s);
    const Eigen::Matrix3d I_world = R * s.rest_inertia_kgm2 * R.transpose();
    f.segment<3>(3) -= w.cross(I_world * w);
    const Eigen::Array2d omega = s.omega_radps.array();
    f.tail<2>() -= (s.modal_kg * (omega.square() * q_m.array() +
                                  2.0 * s.zeta * omega * u.q_mps.array()))
                       .matrix();
    return f;
}

Vector8d pack(const Twist& t) {
    Vector8d u;
    u << t.v_mps, t.w_radps, t.q_mps;
    return u;
}

Twist unpack(const Vector8d& u) {
    Twist t;
    t.v_mps = u.head<3>();
    t.w_radps = u.segment<3>(3);
    t.q_mps = u.tail<2>();
    return t;
}

}  // namespace detail

Body3dModel with_mode(Body3dModel model, const Body3dMode& mode) {
    detail::require_modal_frequency(mode.frequency_x_hz, "flexible.f_x");
    detail::require_modal_frequency(mode.frequency_y_hz, "flexible.f_y");
    detail::require_modal_damping(mode.damping);
    detail::require_modal_mass_fraction(mode.mass_fraction);
    detail::require_modal_height(mode.height_m);
    model.mode = mode;
    const detail::ModalSplit split = detail::modal_split(model);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(split.rest_inertia_kgm2);
    if (eig.eigenvalues().minCoeff() <= 0.0)
        throw InputError({"", 0, "flexible.height"},
                         fmt::format("a modal mass of {:.4g} kg at {} m carries more second "
                                     "moment than the body has: the rigid rest's inertia about "
                                     "its own CG would not be positive",
                                     split.modal_kg, mode.height_m));
    return model;
}

double body3d_modal_stable_step_s(const Body3dModel& model) {
    if (!model.mode) return std::numeric_limits<double>::infinity();
    const detail::ModalSplit s = detail::modal_split(model);
    // In flight the mode moves against the free rest: q'' = B (-K q - C q'), B the q' block of
    // the inverse generalised mass, pose-independent but for q (the rest is rigid).
    const detail::Matrix8d M =
        detail::generalized_mass(s, Eigen::Matrix3d::Identity(), Eigen::Vector2d::Zero());
    const Eigen::Matrix2d B = M.ldlt().solve(detail::Matrix8d::Identity()).bottomRightCorner<2, 2>();
    double step_s = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 2; ++i) {
        // Per axis: the modal mass's effective stiffness and damping against the rest.
        const double scale = std::sqrt(B(i, i) * s.modal_kg);
        const double omega = s.omega_radps(i) * scale;
        const double zeta = s.zeta * scale;
        step_s = std::min(step_s, 2.0 * (std::sqrt(1.0 + zeta * zeta) - zeta) / omega);
    }
    return step_s;
}

}  // namespace freestand::dynamics
