#pragma once
/// A block described as its bounding box plus, optionally, the CG position and inertia: the way
/// the command line and case files describe equipment (docs/methods.md s.1).
#include <map>
#include <optional>
#include <string>

#include "block/block.hpp"

namespace freestand::sliding {

/// Box of full size 2 half_width x 2 half_height standing on its base; the rocking edges are the
/// box's bottom corners (or the outer feet).
struct BoxSpec {
    double half_width_m = 0.0;
    double half_height_m = 0.0;
    std::optional<double> mass_kg;          ///< default 1 kg (the checks are per unit mass)
    std::optional<double> cg_offset_m;      ///< CG offset from the box centre towards the right edge
    std::optional<double> cg_height_m;      ///< CG height above the base
    std::optional<double> inertia_cg_kgm2;  ///< I_c about the CG, out of plane
};

/// Uniform block when only the box is given (I_c = M (b^2 + h^2) / 3). With a CG position the
/// inertia is required (a non-uniform mass distribution has no default I_c), and with an inertia
/// the mass is required (I_O depends on I_c / M). |cg_offset| < half_width. Throws InputError
/// naming the BoxSpec field ("box.half_width_m", "box.cg_offset_m", "box.inertia_cg_kgm2",
/// "box.mass_kg", ...) otherwise, the block's own limits (core/limits.hpp) included.
block::Block make_block(const BoxSpec& spec);

/// BoxSpec from key=value maps as the command line and case files write them: box keys
/// b (half-width), h (half-height), m (mass); cg keys x (offset towards the right edge), h
/// (height). InputError (field "block b", "block h") when b or h is missing.
BoxSpec box_spec(const std::map<std::string, double>& box, const std::map<std::string, double>& cg,
                 std::optional<double> inertia_cg_kgm2);

}  // namespace freestand::sliding
