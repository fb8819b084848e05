#pragma once
/// Pieces of a fragility sample the runner shares with no one (not installed).
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "assess/case.hpp"
#include "assess/histories.hpp"
#include "fragility/fragility.hpp"

namespace freestand::fragility {

/// The draws of one sample from its own stream: they depend on (seed, level, sample) alone
/// (docs/methods.md s.9), so a merge can redraw them to check a shard's.
struct Draw {
    std::size_t pick = 0;  ///< index into the pool (the sets, or the records of the suite)
    double mu_s = 0.0;
    std::array<double, 2> restitution{};  ///< x, y
};

/// The draws of sample `sample` of level `level` from laws, picking among pool motions.
Draw draw(const Laws& laws, std::uint64_t seed, int level, int sample, std::size_t pool);

/// What a model of the whole body (every component at once) gives for a sample.
struct WholeBody {
    enum class Model { biaxial_slide, body3d };
    Model model = Model::biaxial_slide;
    double slide_max_m = 0.0;          ///< peak |u| (of the footprint centre for the 3D body)
    double rock_max_over_alpha = 0.0;  ///< 3D body: peak tilt over critical; biaxial: 0
    bool overturned = false;
};

/// The whole body under both horizontal components of the set and its vertical, scaled to
/// pga_g, with friction mu_s, mu_k (docs/methods.md s.10, s.11): when the block of direction x or
/// y would rock under it (dynamics::biaxial_rocking_reason) the 3D rigid body with restitution r
/// (Body3dModel::angular_restitution; its slide 0 when it overturns), else biaxial sliding;
/// nullopt when models does not turn the applicable model on. The rules, options and
/// scaling are those of a simulated level (assess/biaxial_level.hpp, assess/body3d_level.hpp).
/// `flexible`: the level's flag is raised, and the 3D body carries the case's mode
/// (assess::body3d_mode).
std::optional<WholeBody> whole_body_sample(const assess::Case& c, const assess::HistorySet& set,
                                           double pga_g, double mu_s, double mu_k,
                                           double restitution, const Models& models,
                                           bool flexible);

}  // namespace freestand::fragility
