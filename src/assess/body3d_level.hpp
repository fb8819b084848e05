#pragma once
/// The rigid body in three dimensions at the simulated levels of one PGA (docs/methods.md s.11):
/// where the body can uplift in some direction, every history's three components at once.
#include <optional>
#include <string>
#include <vector>

#include "assess/case.hpp"
#include "assess/histories.hpp"
#include "assess/level.hpp"
#include "assess/result.hpp"
#include "dynamics/body3d.hpp"

namespace freestand::assess {

/// The model name LevelResult::model carries for a level the 3D body decides.
inline constexpr const char* body3d_model_name =
    "rigid body in three dimensions, every component at once: rocking about edges and corners, "
    "sliding and twisting (docs/methods.md s.11), beside the rigid planar block of each "
    "direction (docs/methods.md s.3)";
/// The same for a flagged body, which the 3D body decides carrying the flexible body's mode.
inline constexpr const char* body3d_flexible_model_name =
    "body in three dimensions carrying the flexible body's mode along x and y, every component "
    "at once (docs/methods.md s.11), beside the planar flexible body (docs/methods.md s.10) and "
    "the rigid planar block (docs/methods.md s.3) of each direction";

/// The 3D body of the component: the rectangle of its two planar geometries' edge distances
/// around the CG, the CG height, the mass, and the inertia about the CG from the planar blocks
/// (I_xx from direction y's, I_yy from direction x's) and a uniform box's I_zz.
dynamics::Body3d component_body3d(const Component& c);
/// The same from two planar blocks (x's and y's geometry and inertia), the mass and CG height.
dynamics::Body3d body3d_of_blocks(const block::Block& bx, const block::Block& by, double mass_kg,
                                  double cg_height_m);

/// The 3D body's options in assess: dt 1e-3 s, sweeps to 1e-8 g dt or 100 sweeps (a step that
/// needs more is counted in unconverged_steps), no series.
/// The step is ten times the engine's default for cost: on the bench's records its peak tilt
/// is within 2% (one component) and 5% (two) of the converged run, and in the step study of
/// docs/methods.md s.11 its overturn counts were as high as or higher than the converged ones.
dynamics::Body3dOptions body3d_options(double g_mps2);

/// True for the classifications in which the block leaves the floor (rocking, sliding and
/// rocking, flight).
bool uplifts(Mode m);

/// Why the body cannot uplift in any direction at the level's upper bounds (either direction's
/// classification at the upper friction is rest or slide), or nullopt when it can: uplift along
/// a plan direction needs one horizontal component past its own axis's g tan(alpha), so the
/// two directions' classifications settle every direction, the diagonal included.
std::optional<std::string> no_uplift_reason(const LevelResult& x, const LevelResult& y);

/// The case's mode as the 3D body carries it: the fixed-base frequency along both axes, the
/// damping, modal mass and height as the planar flexible model resolves them.
dynamics::Body3dMode body3d_mode(const Component& c, const ContactBound& bound);

/// The flexible body's mode for the 3D body when a flexible-body flag is raised at this PGA
/// (a flexible simulation ran in x or y): the case's fixed-base frequency along both axes, its
/// damping, modal mass and height as the planar flexible model resolves them; else nullopt.
std::optional<dynamics::Body3dMode> flexible_mode(const Case& c, const LevelResult& x,
                                                  const LevelResult& y);

/// For the levels of one PGA (directions x and y, as evaluate_level made them, biaxial applied):
/// every simulated level gets LevelResult::body3d. Where the simulation decides the level (the
/// screen failed, or the flexible body runs) and the body can uplift, every history runs with
/// the 3D body at the sliding and the rocking bound (their friction and restitution; one run
/// when they coincide) and at the lower restitution when it differs, as the planar runs, shared
/// by both levels; their model, verdict and trail are then remade with the 3D body deciding.
/// With a raised flexible-body flag the 3D body carries the mode (flexible_mode). Elsewhere
/// body3d says why not (where only the flexible body lifts its base, its planar runs decide).
void apply_body3d(const Case& c, const LevelDemand& demand, std::vector<LevelResult*> levels,
                  HistoryBank& bank);

}  // namespace freestand::assess
