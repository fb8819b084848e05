#include "block/block.hpp"

#include <cmath>

#include "core/errors.hpp"
#include "core/limits.hpp"
#include "core/units.hpp"

namespace freestand::block {

namespace {

// Positive and within the limits of src/core/limits.hpp (README, Limits).
void require_length(double v_m, const char* what) {
    core::limits::require_length(v_m, {"", 0, what});
}

void require_mass(double m_kg) {
    const SourceLocation where{"", 0, "m (mass, kg)"};
    require_positive(m_kg, where);
    core::limits::require_at_least(m_kg, core::limits::min_mass_kg, where, "mass (kg)");
    core::limits::require_within(m_kg, core::limits::max_mass_kg, where, "mass (kg)");
}

}  // namespace

double uniform_inertia_cg_kgm2(double mass_kg, double half_width_m, double cg_height_m) {
    return mass_kg * (half_width_m * half_width_m + cg_height_m * cg_height_m) / 3.0;
}

Block Block::uniform(double half_width_m, double cg_height_m, double mass_kg) {
    require_length(half_width_m, "b (half-width, m)");
    require_length(cg_height_m, "h (CG height, m)");
    require_mass(mass_kg);
    Block blk;
    blk.mass_kg = mass_kg;
    blk.b_left_m = half_width_m;
    blk.b_right_m = half_width_m;
    blk.h_m = cg_height_m;
    blk.inertia_cg_kgm2 = uniform_inertia_cg_kgm2(mass_kg, half_width_m, cg_height_m);
    return blk;
}

Block Block::general(double b_left_m, double b_right_m, double h_m, double mass_kg,
                     double inertia_cg_kgm2) {
    require_length(b_left_m, "b_left (CG to left edge, m)");
    require_length(b_right_m, "b_right (CG to right edge, m)");
    require_length(h_m, "h (CG height, m)");
    require_mass(mass_kg);
    require_positive(inertia_cg_kgm2, {"", 0, "I_c (inertia about CG, kg m^2)"});
    return Block{mass_kg, b_left_m, b_right_m, h_m, inertia_cg_kgm2};
}

double Block::R_m(Edge e) const { return std::hypot(b(e), h_m); }

double Block::alpha_rad(Edge e) const { return std::atan2(b(e), h_m); }

double Block::inertia_edge_kgm2(Edge e) const {
    const double r = R_m(e);
    return inertia_cg_kgm2 + mass_kg * r * r;
}

double Block::p_radps(Edge e, double g_mps2) const {
    return std::sqrt(mass_kg * g_mps2 * R_m(e) / inertia_edge_kgm2(e));
}

double Block::housner_restitution(Edge impact_edge) const {
    return (inertia_cg_kgm2 + mass_kg * (h_m * h_m - b_left_m * b_right_m)) /
           inertia_edge_kgm2(impact_edge);
}

}  // namespace freestand::block
