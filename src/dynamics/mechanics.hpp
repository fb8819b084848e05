#pragma once
/// Internal: equations of motion of the block in each contact mode (docs/methods.md s.3),
/// shared by the event-driven and the central-difference integrators.
#include <array>
#include <cmath>

#include "dynamics/simulate.hpp"

namespace freestand::dynamics::detail {

/// Base acceleration at an instant: xg'' and the effective gravity G = g + yg'' (m/s^2).
struct Base {
    double ax = 0.0;
    double G = 0.0;
};

/// Geometry constants of the model, indexed by edge: [0] left (s = -1), [1] right (s = +1).
struct Geometry {
    double M = 0.0, Ic = 0.0, h = 0.0, top = 0.0, mu_s = 0.0, mu_k = 0.0;
    std::array<double, 2> b{}, R{}, alpha{}, sin_alpha{}, cos_alpha{}, tan_alpha{}, IO{};
    /// Restitution for an impact that lands on edge [i] (rotation leaves the other edge).
    std::array<double, 2> r_onto{};
    /// Rest limit on |xg''| / G towards edge [i]: min(mu_s, tan(alpha_i)) (section 2).
    std::array<double, 2> c_rest{};
    /// M R / I_O of edge [i] (the rocking equation's factor, precomputed: no division per call).
    std::array<double, 2> k_rock{};

    static int index(int s) { return s > 0 ? 1 : 0; }
};

Geometry make_geometry(const BlockModel& model);

/// Accelerations and base reactions in a contact mode. F is the horizontal (friction) force the
/// base exerts on the block, N the vertical one.
struct Accel {
    double u_dd = 0.0;   ///< slip acceleration of the contact point, m/s^2
    double th_dd = 0.0;  ///< theta'', rad/s^2
    double N = 0.0;
    double F = 0.0;
};

/// Rock about edge s (+1 right, -1 left) without slip:
/// I_O theta'' = -M R [G sin(alpha - theta) + s xg'' cos(alpha - theta)].
Accel rock_accel(const Geometry& g, int s, double th, double om, Base base);
/// The same with sn = sin(alpha_s - theta) and c = cos(alpha_s - theta) given (inline: the
/// event-driven integrator calls it at every step end).
inline Accel rock_accel_sc(const Geometry& g, int s, double sn, double c, double om, Base base) {
    const auto i = static_cast<std::size_t>(Geometry::index(s));
    const double ds = static_cast<double>(s);
    const double R = g.R[i];
    Accel a;
    a.th_dd = -g.k_rock[i] * (base.G * sn + ds * base.ax * c);
    // CG acceleration relative to the base, then the base reactions (sec. 3).
    const double xdd = ds * R * (c * a.th_dd + sn * om * om);
    const double ydd = R * (sn * a.th_dd - c * om * om);
    a.F = g.M * (xdd + base.ax);
    a.N = g.M * (ydd + base.G);
    return a;
}

/// Slide-rock about edge s with the contact point slipping in direction sigma (F = -sigma mu_k N):
/// the 3x3 linear system in (u'', theta'', N) from the CG's horizontal and vertical balance and
/// the moment about the CG, solved by elimination (N from the moment row).
Accel slide_rock_accel(const Geometry& g, int s, int sigma, double th, double om, Base base);
/// The same with sn = sin(alpha_s - theta) and c = cos(alpha_s - theta) given.
Accel slide_rock_accel_sc(const Geometry& g, int s, int sigma, double sn, double c, double om,
                          Base base);

/// Flat sliding in direction sigma: u'' = -xg'' - sigma mu_k G.
inline Accel slide_accel(const Geometry& g, int sigma, Base base) {
    const double dsig = static_cast<double>(sigma);
    Accel a;
    a.u_dd = -base.ax - dsig * g.mu_k * base.G;
    a.N = g.M * base.G;
    a.F = -dsig * g.mu_k * a.N;
    return a;
}

/// The contact mode a block at rest (theta = 0, u' = 0) enters under base acceleration base,
/// by docs/methods.md s.2 (strict inequalities: exactly at a threshold it stays at rest).
struct Start {
    Mode mode = Mode::rest;
    int s = 1;      ///< edge for rock / slide-rock
    int sigma = 1;  ///< slip direction for slide / slide-rock
};
Start classify_from_rest(const Geometry& g, Base base);

/// True if the block at rest satisfies the rest inequalities of section 2: |xg''| <= min(mu_s,
/// tan(alpha)) G for the edge it would tip over (a base accelerating right tips it over the left
/// edge) and G >= 0.
inline bool rest_holds(const Geometry& g, Base base) {
    return base.G >= 0.0 && base.ax <= g.c_rest[0] * base.G && -base.ax <= g.c_rest[1] * base.G;
}

/// Contact mode for a block rocking on edge s with slip velocity v (after an impact or a lift
/// from flat): slide-rock if v != 0, else rock if the friction it needs is available, else
/// slide-rock in the direction it is pushed.
Start classify_on_edge(const Geometry& g, int s, double th, double om, double v, Base base);

/// Mode for a flat block sliding at velocity v != 0: slide, or slide-rock on edge sign(v) when
/// mu_k > tan(alpha) of that edge (the friction moment lifts it, section 3).
Start classify_sliding(const Geometry& g, double v);

/// Peak uplift a free-rocking block reaches from theta = 0 with angular velocity om about edge s
/// (energy conservation, docs/methods.md s.1); returns +infinity if it would pass alpha.
double rebound_angle(const Geometry& g, int s, double om, double G);

/// Absolute horizontal acceleration of the larger-magnitude top corner, given the CG's relative
/// acceleration (xdd), rotation phi (counter-clockwise), phi' and phi''.
double top_corner_accel(const Geometry& g, double ax_base, double xdd_cg, double phi, double phid,
                        double phidd);
/// The same with cos(phi) and sin(phi) given (saves the trigonometry when they are known;
/// inline: evaluated at every output sample).
inline double top_corner_accel_cs(const Geometry& g, double ax_base, double xdd_cg, double cp,
                                  double sp, double phid, double phidd) {
    const double by = g.top - g.h;
    double best = 0.0;
    for (double bx : {g.b[1], -g.b[0]}) {
        const double rx = bx * cp - by * sp, ry = bx * sp + by * cp;
        const double a = ax_base + xdd_cg - phidd * ry - phid * phid * rx;
        if (std::abs(a) > std::abs(best)) best = a;
    }
    return best;
}


/// Free-flight state: CG position relative to the base (X from its initial flat position,
/// Y above the base), counter-clockwise rotation phi, and their rates.
struct Flight {
    double X = 0, Y = 0, phi = 0, Xd = 0, Yd = 0, phid = 0;
};
/// Converts a contact state on edge s (slip u, theta) to the flight state.
Flight to_flight(const Geometry& g, int s, double u, double v, double th, double om);
/// Lowest corner height above the base and which edge it is (s).
double lowest_corner(const Geometry& g, const Flight& f, int& s_out);

/// Contact state after a flight ends with the lowest corner touching: sticking, perfectly
/// plastic impact conserving angular momentum about that corner; or a flat landing, when the
/// tilt is nil or the far edge's gap closes within flat_window_s at the vertical speed, which
/// keeps the horizontal velocity less the Coulomb impulse mu_k |Yd|.
struct Contact {
    int s = 1;
    double u = 0, v = 0, th = 0, om = 0;
    bool flat = false;
};
Contact land(const Geometry& g, const Flight& f, double flat_window_s);

}  // namespace freestand::dynamics::detail
