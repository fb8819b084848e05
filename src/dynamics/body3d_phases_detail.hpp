#pragma once
/// Internal: the 3D rigid body's smooth phases taken as the few degrees of freedom they have
/// (docs/methods.md s.11, "phases"), between Moreau-Jean steps:
///   - EdgePivot: rocking about a footprint edge whose two vertices stick, one degree of
///     freedom (the rotation about the fixed edge);
///   - EdgeSlide: rocking on a footprint edge whose two vertices slip, six less the two
///     that keep them on the floor (the rigid body's motion, the normal forces from those
///     two conditions and Coulomb's friction against each vertex's slip);
///   - FlatSlide: sliding flat on the whole footprint without turning, two (the plan
///     position), as the biaxial sliding block.
/// Each is stepped by Dormand-Prince 5(4) with its error control, and ends where one of its
/// margins (positive while the phase holds) crosses zero, located on the dense output.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dynamics/biaxial_detail.hpp"
#include "dynamics/body3d_detail.hpp"
#include "dynamics/dopri5.hpp"
#include "dynamics/roots.hpp"

namespace freestand::dynamics::detail {

/// How far a phase's advance went.
struct PhaseRun {
    double t_s = 0.0;        ///< the time it reached
    bool ended = false;      ///< the phase ended there (else it reached the asked end)
    std::size_t steps = 0;   ///< Dormand-Prince steps taken (rejected ones included)
};

/// The Dormand-Prince tolerances of a phase: each component to 1e-8 of itself or 1e-8 (a tighter
/// 1e-10 / 1e-12 gave the same peaks in the tests at several times the steps).
inline constexpr double phase_rel_tol = 1e-8;
inline constexpr double phase_abs_tol = 1e-8;

/// Whether every margin of a phase holds (is positive): a phase starts only where they do.
template <std::size_t K>
bool all_hold(const std::array<double, K>& margins) {
    return std::all_of(margins.begin(), margins.end(), [](double m) { return m > 0.0; });
}

/// Steps x from t_s to t_end_s by Dormand-Prince (rhs(x, k, t) fills k = x'), stopping where
/// the first of margins(t, x) (an array, each positive while the phase holds) crosses zero.
/// Each accepted step is probed at its quarters: a margin that dips below zero and back
/// within a quarter step is not seen. h_try_s carries the step size from call to call.
template <std::size_t N, class Rhs, class Margins>
PhaseRun advance_phase(double& t_s, std::array<double, N>& x, double& h_try_s, double t_end_s,
                       const Rhs& rhs, const Margins& margins) {
    constexpr int probes = 4;
    constexpr double least_step_s = 1e-12;  // below it the steps take the body on
    using Dopri = Dopri5<N>;
    PhaseRun run{t_s, false, 0};
    Dopri dopri;
    typename Dopri::State k1;
    rhs(x, k1, t_s);
    while (t_s < t_end_s) {
        // Within rounding of the asked end: it is reached (the phase goes on).
        if (t_end_s - t_s < least_step_s) {
            t_s = t_end_s;
            break;
        }
        const bool clipped = t_end_s - t_s < h_try_s;
        const double h = std::min(h_try_s, t_end_s - t_s);
        if (h < least_step_s) {
            run.ended = true;
            break;
        }
        const double err = dopri.step(rhs, t_s, x, k1, h, phase_rel_tol, phase_abs_tol);
        ++run.steps;
        if (!(err <= 1.0)) {
            h_try_s = h * Dopri::factor(err);
            continue;
        }
        // A step cut short by the asked end does not shrink the next.
        h_try_s = clipped ? std::max(h_try_s, h * Dopri::factor(err)) : h * Dopri::factor(err);
        const auto at = [&](double theta) { return margins(t_s + theta * h, dopri.dense(theta)); };
        auto before = margins(t_s, x);
        double theta_before = 0.0;
        std::optional<double> end_theta;
        for (int j = 1; j <= probes && !end_theta; ++j) {
            const double theta = static_cast<double>(j) / probes;
            const auto now = at(theta);
            for (std::size_t i = 0; i < now.size(); ++i) {
                // A margin that is no number ends the phase at the last probe that held.
                if (std::isnan(now[i])) {
                    end_theta = end_theta ? std::min(*end_theta, theta_before) : theta_before;
                    continue;
                }
                if (!(now[i] < 0.0)) continue;
                const double root =
                    toms748_root([&](double th) { return at(th)[i]; }, theta_before, theta,
                                 std::max(before[i], 0.0), now[i]);
                end_theta = end_theta ? std::min(*end_theta, root) : root;
            }
            theta_before = theta;
            before = now;
        }
        if (end_theta) {
            x = dopri.dense(*end_theta);
            t_s += *end_theta * h;
            run.ended = true;
            break;
        }
        x = dopri.x1();
        k1 = dopri.k7();
        t_s = t_s + h >= t_end_s ? t_end_s : t_s + h;
    }
    run.t_s = t_s;
    return run;
}

class EdgePivot {
public:
    /// The phase about the footprint edge from vertex `from` to vertex `to` (counter-clockwise
    /// neighbours) of a rigid body whose two vertices stand still on the floor in state s at
    /// time t_s under the segment's base motion; nullopt when the body does not lean onto the
    /// edge (its footprint's tilt about it is not positive) or the floor cannot hold the edge
    /// there.
    static std::optional<EdgePivot> start(const Body3dModel& model, const BodyState& s,
                                          std::size_t from, std::size_t to,
                                          const BiaxialSegment& seg, double t_s, double g_mps2);

    /// Steps the phase from the time it stands at to t_end_s (within the segment seg) or to
    /// its end, whichever comes first: where the footprint is back on the floor, a vertex of
    /// the edge lifts off, or the floor's friction no longer holds the edge.
    PhaseRun advance(const BiaxialSegment& seg, double t_end_s);

    /// The body's state at the time the phase stands at.
    BodyState state() const;
    /// The floor's force on the edge's two vertices at that time, N (world axes; the part
    /// along the edge, which the rigid body leaves indeterminate, shared as the normal forces).
    std::array<Eigen::Vector3d, 2> vertex_forces_N(const BiaxialSegment& seg) const;
    std::array<std::size_t, 2> vertices() const { return {from_, to_}; }

private:
    using X = std::array<double, 2>;  // psi (rad), psi' (rad/s)

    EdgePivot() = default;
    /// psi'' under the base's plan acceleration a and G = g + yg'' at time t.
    double accel(const BiaxialSegment& seg, double t, double psi) const;
    /// The least of the phase's force margins at t in state x, over M g: the two vertices'
    /// normal forces, the friction each has left and the friction the edge has left along it.
    double hold(const BiaxialSegment& seg, double t, const X& x) const;
    std::array<Eigen::Vector3d, 2> forces_at(const BiaxialSegment& seg, double t, const X& x) const;
    /// The tilt of the footprint about the edge, rad (0: flat on the floor).
    double lift(const X& x) const { return lift0_rad_ + x[0]; }
    std::array<double, 2> margins(const BiaxialSegment& seg, double t, const X& x) const {
        return {lift(x), hold(seg, t, x)};
    }

    std::size_t from_ = 0, to_ = 0;
    double mass_kg_ = 0.0, mu_s_ = 0.0, g_mps2_ = 0.0;
    Eigen::Vector3d origin_m_;  ///< vertex `from`, relative to the base
    Eigen::Vector3d axis_;      ///< unit, from `from` to `to`: +psi lifts the footprint
    double length_m_ = 0.0;     ///< of the edge
    Eigen::Quaterniond q0_;     ///< the orientation at psi = 0
    Eigen::Vector3d cg0_m_;     ///< CG from the origin at psi = 0
    double along_m_ = 0.0;      ///< its part along the axis
    Eigen::Vector3d arm0_m_;    ///< its part normal to the axis
    Eigen::Vector3d inertia0_;  ///< I_cg (world, psi = 0) times the axis
    double inertia_axis_kgm2_ = 0.0;  ///< about the edge
    double lift0_rad_ = 0.0;
    double t_s_ = 0.0;
    X x_{};
    double h_try_s_ = std::numeric_limits<double>::infinity();
};

class EdgeSlide {
public:
    /// The phase of a rigid body on the footprint edge from vertex `from` to vertex `to`, both
    /// slipping faster than slow_mps in state s at time t_s; nullopt when they do not, the
    /// floor would pull on either, or another vertex is not above the floor.
    static std::optional<EdgeSlide> start(const Body3dModel& model, const BodyState& s,
                                          std::size_t from, std::size_t to,
                                          const BiaxialSegment& seg, double t_s, double g_mps2,
                                          double slow_mps);

    /// Steps the phase to t_end_s or to its end: a vertex of the edge slips slower than
    /// slow_mps (the steps take the stick or the reversal) or lifts off, or another vertex
    /// reaches the floor.
    PhaseRun advance(const BiaxialSegment& seg, double t_end_s);

    BodyState state() const;
    /// The floor's force on the edge's two vertices at that time, N (world axes).
    std::array<Eigen::Vector3d, 2> vertex_forces_N(const BiaxialSegment& seg) const;
    std::array<std::size_t, 2> vertices() const { return {from_, to_}; }

private:
    // p (m), q (w, x, y, z), v (m/s), w (rad/s), world axes relative to the base.
    using X = std::array<double, 13>;
    /// The motion's derivatives at t in state x, and the two vertices' normal forces, N.
    struct Derivatives {
        X dx{};
        std::array<double, 2> normal_N{};
        /// The normal forces' system's diagonal entries and determinant, scaled by M and M^2:
        /// positive while it has one solution that the phase can follow.
        std::array<double, 3> well_posed{};
    };

    EdgeSlide() = default;
    Derivatives derivatives(const BiaxialSegment& seg, double t, const X& x) const;
    std::array<double, 8> margins(const BiaxialSegment& seg, double t, const X& x) const;

    std::size_t from_ = 0, to_ = 0;
    double mass_kg_ = 0.0, mu_k_ = 0.0, g_mps2_ = 0.0, slow_mps_ = 0.0, reach_m_ = 0.0;
    Eigen::Matrix3d inertia_body_, inverse_inertia_body_;
    std::vector<Eigen::Vector3d> vertices_body_;  ///< from the CG, body axes
    double t_s_ = 0.0;
    X x_{};
    double h_try_s_ = std::numeric_limits<double>::infinity();
};

class FlatSlide {
public:
    /// The phase of a rigid body sliding flat on its whole footprint without turning, from
    /// state s at time t_s; nullopt when the slip is already slower than slow_mps, the base
    /// falls away or the floor's pressure would leave the footprint.
    static std::optional<FlatSlide> start(const Body3dModel& model, const BodyState& s,
                                          const BiaxialSegment& seg, double t_s, double g_mps2,
                                          double slow_mps);

    /// Steps the phase to t_end_s or to its end: the slip slows below slow_mps (the steps
    /// take the stop or the reversal), G falls to 0, or the centre of pressure the friction
    /// moves forward, mu_k h along the slip, reaches an edge (the body tips).
    PhaseRun advance(const BiaxialSegment& seg, double t_end_s);

    BodyState state() const;
    /// The unit direction of the slip, world plan axes.
    Eigen::Vector2d slip_direction() const;

private:
    using X = std::array<double, 4>;  // x, y (m), x', y' (m/s) of the CG relative to the base

    FlatSlide() = default;
    std::array<double, 3> margins(const BiaxialSegment& seg, double t, const X& x) const;

    double mu_k_ = 0.0, g_mps2_ = 0.0, slow_mps_ = 0.0;
    Eigen::Quaterniond q_;
    double height_m_ = 0.0;  ///< of the CG above the floor
    /// The footprint's edges in world plan axes: outward normal and distance from the CG.
    std::vector<std::pair<Eigen::Vector2d, double>> edges_;
    double t_s_ = 0.0;
    X x_{};
    double h_try_s_ = std::numeric_limits<double>::infinity();
};

}  // namespace freestand::dynamics::detail
