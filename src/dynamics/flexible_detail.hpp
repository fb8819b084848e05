#pragma once
/// Internal: equations of motion of the flexible body (flexible.hpp) in each contact mode.
#include <array>

#include "dynamics/flexible.hpp"
#include "dynamics/mechanics.hpp"

namespace freestand::dynamics::detail {

/// Constants of the split body. Body frame: origin O on the base plane below the CG, x along
/// the base to the right, y up; edges at (-b_L, 0) and (b_R, 0); the rigid remainder's CG at
/// (0, hr); the modal mass at (q, hs).
struct FlexGeometry {
    Geometry rigid;  ///< the whole block as the rigid model sees it (restitution, alpha, mu)
    double M = 0.0, Mr = 0.0, ms = 0.0, hr = 0.0, Ir = 0.0, hs = 0.0, Mh = 0.0;
    double omega = 0.0, zeta = 0.0, k = 0.0, c = 0.0;
    std::array<double, 2> b{};  ///< [0] left, [1] right half-widths
};
FlexGeometry make_flex_geometry(const FlexibleModel& m);

/// Mode of the base with its edge s (rock, slide-rock) and slip direction sigma.
struct FlexMode {
    Mode mode = Mode::rest;
    int s = 1;
    int sigma = 1;
};

/// Pose of the body relative to the moving base frame: O's position (X, Y), rotation phi
/// (counter-clockwise), modal coordinate q, and their rates.
struct Pose {
    double X = 0, Y = 0, phi = 0, q = 0, Xd = 0, Yd = 0, phid = 0, qd = 0;
};

/// Accelerations of the pose and the base reactions (F horizontal, N vertical, on the body);
/// NL, NR the normal forces at the left and right edges in the flat modes.
struct FlexAccel {
    double Xdd = 0, Ydd = 0, phidd = 0, qdd = 0, F = 0, N = 0, NL = 0, NR = 0;
};

/// Newton-Euler equations of the two bodies (linear and angular momentum of the whole about O,
/// the modal mass along the body's x axis: m_s a_s . e1 = -k q - c q' + forces . e1) with the
/// mode's contact constraints, one linear system (at most 7 x 7) per call.
FlexAccel flex_accel(const FlexGeometry& g, const FlexMode& m, const Pose& p, Base base);

/// Rest (base held flat, docs/methods.md s.2 generalised): the modal equation and the base
/// reactions in closed form, F = M xg'' + m_s q'', N = M G and the moment about O.
FlexAccel rest_accel(const FlexGeometry& g, double q, double qd, Base base);
/// Rest holds: |F| <= mu_s N, both edges pressed (NL, NR >= 0) and G >= 0.
inline double rest_margin(const FlexGeometry& g, const FlexAccel& a, Base base) {
    double m = g.rigid.mu_s * a.N - std::abs(a.F);
    m = std::min(m, a.NL);
    m = std::min(m, a.NR);
    return std::min(m, base.G);
}

/// Pose of a contact state on edge s: slip u of the contact point (flat: of O), uplift theta.
Pose contact_pose(const FlexGeometry& g, int s, double u, double v, double th, double om,
                  double q, double qd);
/// Horizontal acceleration of the edge-s contact point and theta'' from the pose accelerations.
double contact_slip_accel(const FlexGeometry& g, int s, const Pose& p, const FlexAccel& a);

/// Mode entered from flat contact (theta = 0, theta' = 0) with slip velocity v (0: from rest)
/// under base acceleration base, by docs/methods.md s.2 and s.3 generalised: flight if G < 0;
/// if an edge unloads, rock about the other when static friction holds there, else slide-rock
/// (slide when the edge does not lift under kinetic friction); a slip continues as slide (or
/// slide-rock if an edge unloads); rest if the rest inequalities hold, else slide.
FlexMode classify_flat(const FlexGeometry& g, double q, double qd, double v, Base base);
/// Mode on edge s with slip velocity v: flight if N < 0, slide-rock if v != 0, rock if static
/// friction holds, else slide-rock in the direction it is pushed.
FlexMode classify_edge(const FlexGeometry& g, int s, const Pose& p, double v, Base base);

/// Angular momentum of the body about the base-plane point (xc, 0), counter-clockwise.
double angular_momentum_about(const FlexGeometry& g, const Pose& p, double xc);
/// Absolute horizontal acceleration of the modal mass, m/s^2.
double modal_abs_accel(const FlexGeometry& g, const Pose& p, const FlexAccel& a, Base base);

/// The linear oscillator q'' + 2 zeta omega q' + omega^2 q = -(a0 + a1 tau) advanced exactly
/// by tau (Nigam & Jennings 1969).
void oscillator_step(const FlexGeometry& g, double& q, double& qd, double a0, double a1,
                     double tau);

}  // namespace freestand::dynamics::detail
