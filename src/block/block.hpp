#pragma once
/// Planar rigid-block geometry shared by the closed-form checks and the simulator
/// (docs/methods.md s.1). One horizontal direction; the block rocks about a left or right edge.
#include "core/units.hpp"

namespace freestand::block {

/// Which rocking edge. The block tips over the right edge when the base accelerates left.
enum class Edge { left, right };

/// Sign convention of docs/methods.md s.3: s = +1 right edge, -1 left edge.
constexpr double edge_sign(Edge e) { return e == Edge::right ? 1.0 : -1.0; }

/// I_c about the CG of a uniform rectangular block of half-width b and CG height h (height
/// 2 h): M (b^2 + h^2) / 3, kg m^2 (docs/methods.md s.1). The one copy of this formula.
double uniform_inertia_cg_kgm2(double mass_kg, double half_width_m, double cg_height_m);

/// Geometry and mass of a planar rigid block. Construct with uniform() or general(); both
/// validate their inputs and throw InputError naming the offending field.
struct Block {
    double mass_kg = 1.0;
    double b_left_m = 0.0;       ///< CG to left rocking edge, horizontal, m
    double b_right_m = 0.0;      ///< CG to right rocking edge, horizontal, m
    double h_m = 0.0;            ///< CG height above the contact plane, m
    double inertia_cg_kgm2 = 0;  ///< I_c, out of plane, about the CG

    /// Uniform rectangular block of half-width b and CG height h (full size 2b x 2h):
    /// I_c = M (b^2 + h^2) / 3, so I_O = (4/3) M R^2.
    static Block uniform(double half_width_m, double cg_height_m, double mass_kg = 1.0);
    /// General block; inertia_cg_kgm2 must be > 0.
    static Block general(double b_left_m, double b_right_m, double h_m, double mass_kg,
                         double inertia_cg_kgm2);

    double b(Edge e) const { return e == Edge::left ? b_left_m : b_right_m; }
    /// R = sqrt(b^2 + h^2), m.
    double R_m(Edge e) const;
    /// Slenderness angle, tan(alpha) = b / h, rad.
    double alpha_rad(Edge e) const;
    double tan_alpha(Edge e) const { return b(e) / h_m; }
    /// I_O = I_c + M R^2, kg m^2.
    double inertia_edge_kgm2(Edge e) const;
    /// Frequency parameter p = sqrt(M g R / I_O), rad/s, under gravity g_mps2, m/s^2.
    double p_radps(Edge e, double g_mps2 = units::g_mps2) const;
    /// Restitution on angular velocity when the block, rocking about the other edge, strikes
    /// the floor with edge `impact_edge` and goes on rotating about it. Angular momentum about
    /// the impact edge is conserved: r = (I_c + M (h^2 - b_L b_R)) / I_O(impact_edge), which for a
    /// symmetric block is Housner's 1 - 2 M R^2 sin^2(alpha) / I_O (docs/methods.md s.1).
    /// Negative for very squat blocks (no rebound); callers clamp at 0 where they need to.
    double housner_restitution(Edge impact_edge) const;
    /// Edge with the smaller alpha: the one the block tips over first.
    Edge critical_edge() const { return b_left_m < b_right_m ? Edge::left : Edge::right; }
    bool symmetric() const { return b_left_m == b_right_m; }
};

}  // namespace freestand::block
