// The 3D body, its footprint's geometry and its model (docs/methods.md s.11).
#include <algorithm>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "core/errors.hpp"
#include "core/limits.hpp"
#include "dynamics/body3d.hpp"
#include "dynamics/body3d_detail.hpp"

namespace freestand::dynamics {

namespace {

void require_length(double v_m, const char* field) {
    core::limits::require_length(v_m, {"", 0, field});
}

}  // namespace

double Body3d::reach_m(double psi_rad) const {
    const Eigen::Vector2d e(std::cos(psi_rad), std::sin(psi_rad));
    double reach = -std::numeric_limits<double>::infinity();
    for (const auto& v : footprint_m) reach = std::max(reach, v.dot(e));
    return reach;
}

double Body3d::critical_tilt_rad(double psi_rad) const {
    return std::atan2(std::max(reach_m(psi_rad), 0.0), h_m);
}

Body3d box_body(double half_x_m, double half_y_m, double cg_height_m, double mass_kg,
                std::optional<double> total_height_m) {
    require_length(half_x_m, "half_x_m");
    require_length(half_y_m, "half_y_m");
    require_length(cg_height_m, "h_m");
    core::limits::require_in(mass_kg, core::limits::mass_kg, {"", 0, "mass_kg"});
    const double H = total_height_m.value_or(2.0 * cg_height_m);
    require_length(H, "total_height_m");
    if (H < cg_height_m)
        throw InputError({"", 0, "total_height_m"},
                         fmt::format("must be at least the CG height {} m; got {} m", cg_height_m, H));
    Body3d b;
    b.mass_kg = mass_kg;
    b.h_m = cg_height_m;
    b.footprint_m = {{half_x_m, -half_y_m}, {half_x_m, half_y_m}, {-half_x_m, half_y_m},
                     {-half_x_m, -half_y_m}};
    const double M = mass_kg;
    // A uniform box 2 half_x x 2 half_y x H about its centre.
    b.inertia_cg_kgm2 = Eigen::Vector3d(M * (4.0 * half_y_m * half_y_m + H * H) / 12.0,
                                        M * (4.0 * half_x_m * half_x_m + H * H) / 12.0,
                                        M * (half_x_m * half_x_m + half_y_m * half_y_m) / 3.0)
                            .asDiagonal();
    return b;
}

double housner_restitution(const Body3d& b) {
    const auto& f = b.footprint_m;
    double nearest_m = std::numeric_limits<double>::infinity(), r = 0.0;
    for (std::size_t i = 0; i < f.size(); ++i) {
        const Eigen::Vector2d along = (f[(i + 1) % f.size()] - f[i]).normalized();
        const double d_m = std::abs(along.x() * f[i].y() - along.y() * f[i].x());
        if (d_m >= nearest_m) continue;
        nearest_m = d_m;
        const Eigen::Vector3d n(along.x(), along.y(), 0.0);
        const double I_edge = n.dot(b.inertia_cg_kgm2 * n) + b.mass_kg * (d_m * d_m + b.h_m * b.h_m);
        r = std::max(0.0, 1.0 - 2.0 * b.mass_kg * d_m * d_m / I_edge);
    }
    return r;
}

Body3dModel make_body3d_model(const Body3d& body, double mu_s, std::optional<double> mu_k,
                              double normal_restitution,
                              std::optional<double> angular_restitution) {
    core::limits::require_in(mu_s, core::limits::friction, {"", 0, "mu_s"});
    const double k = mu_k.value_or(mu_s);
    if (!std::isfinite(k) || k < 0.0 || k > mu_s)
        throw InputError({"", 0, "mu_k"},
                         fmt::format("kinetic friction must be in [0, mu_s = {}]; got {}", mu_s, k));
    core::limits::require_in(normal_restitution, core::limits::restitution,
                             {"", 0, "normal_restitution"});
    if (angular_restitution) {
        core::limits::require_in(*angular_restitution, core::limits::restitution,
                                 {"", 0, "angular_restitution"});
        if (normal_restitution != 0.0)
            throw InputError({"", 0, "angular_restitution"},
                             "give a restitution on angular velocity or Newton's on the "
                             "vertices' normal speed, not both");
    }
    if (body.footprint_m.size() < 3)
        throw InputError({"", 0, "footprint_m"},
                         fmt::format("expected at least 3 vertices; got {}", body.footprint_m.size()));
    // The edges' outward normals, the rest test and the arrival speed take the vertices
    // counter-clockwise around a convex polygon: each turn is to the left.
    const auto& f = body.footprint_m;
    for (std::size_t i = 0; i < f.size(); ++i) {
        const Eigen::Vector2d in = f[(i + 1) % f.size()] - f[i];
        const Eigen::Vector2d out = f[(i + 2) % f.size()] - f[(i + 1) % f.size()];
        if (!(in.x() * out.y() - in.y() * out.x() > 0.0))
            throw InputError({"", 0, "footprint_m"},
                             fmt::format("expected a convex polygon with its vertices "
                                         "counter-clockwise; the turn at vertex {} is not to the "
                                         "left",
                                         (i + 1) % f.size()));
    }
    require_length(body.h_m, "h_m");
    core::limits::require_in(body.mass_kg, core::limits::mass_kg, {"", 0, "mass_kg"});
    // The CG must stand over the footprint: every direction has a vertex beyond it.
    for (int q = 0; q < 8; ++q)
        if (body.reach_m(q * units::pi / 4.0) <= 0.0)
            throw InputError({"", 0, "footprint_m"}, "must surround the CG's plan position");
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(body.inertia_cg_kgm2);
    if (!body.inertia_cg_kgm2.isApprox(body.inertia_cg_kgm2.transpose()) ||
        eig.eigenvalues().minCoeff() <= 0.0)
        throw InputError({"", 0, "inertia_cg_kgm2"}, "must be symmetric and positive definite");
    return {body, mu_s, k, normal_restitution, angular_restitution, std::nullopt};
}

const char* to_string(ContactState state) {
    switch (state) {
        case ContactState::rest: return "rest";
        case ContactState::slide: return "slide";
        case ContactState::edge: return "edge";
        case ContactState::vertex: return "vertex";
        case ContactState::flight: return "flight";
    }
    return "?";
}

namespace detail {

std::vector<Eigen::Vector3d> vertices_body(const Body3d& body) {
    std::vector<Eigen::Vector3d> out;
    for (std::size_t i = 0; i < body.footprint_m.size(); ++i) out.push_back(vertex_body(body, i));
    return out;
}

std::vector<FootprintEdge> footprint_edges(const Body3d& body) {
    const auto& v = body.footprint_m;
    std::vector<FootprintEdge> out;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const Eigen::Vector2d edge = v[(i + 1) % v.size()] - v[i];
        const Eigen::Vector2d n = Eigen::Vector2d(edge.y(), -edge.x()).normalized();  // outward (ccw)
        out.push_back({n, n.dot(v[i])});
    }
    return out;
}

}  // namespace detail

const char* to_string(Phase phase) {
    switch (phase) {
        case Phase::edge_sticking: return "edge_sticking";
        case Phase::edge_slipping: return "edge_slipping";
        case Phase::flat_slide: return "flat_slide";
    }
    return "?";
}

}  // namespace freestand::dynamics
