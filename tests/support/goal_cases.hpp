#pragma once
/// Two cases for the performance goal's tests (docs/methods.md s.6 step 5): one whose levels
/// pass at rest but which surely fails the goal, one that surely meets it; and the build's
/// test cache, so the cases' history sets are generated once per build.
#include <memory>
#include <string>

#include "assess/case.hpp"
#include "core/content_store.hpp"

namespace freestand::test {

/// A slender block (0.6 x 0.6 x 2.0 m, tan alpha = 0.3) on steel, its one level 0.05 g at
/// rest, its DBE 0.33 g: just above the static uplift threshold, where about a quarter of the
/// samples rock beyond 1 / FS_required (the fitted P at the DBE is about 26%, 95% 14-40%).
inline const char* slender_goal_toml = R"([component]
name = "slender cabinet"
mass_kg = 200.0
width_m = 0.6
depth_m = 0.6
height_m = 2.0
base_material = "steel"
allowable_slide_m = 0.05
[site]
pga_g = [0.05]
dbe_pga_g = 0.33
[options]
histories_per_level = 2
seed = 7
)";

/// A squat block (2 x 2 x 1 m, tan alpha = 1) on steel with its DBE 0.05 g: at rest up to
/// 3 x DBE = 0.15 g, far below mu_s g and g tan(alpha), so no sample fails.
inline const char* squat_goal_toml = R"([component]
name = "squat tank"
mass_kg = 2000.0
width_m = 2.0
depth_m = 2.0
height_m = 1.0
base_material = "steel"
allowable_slide_m = 0.05
[site]
pga_g = [0.05]
dbe_pga_g = 0.05
[options]
histories_per_level = 2
seed = 7
)";

/// The build's test cache (tests/CMakeLists.txt points XDG_CACHE_HOME into the build tree).
inline const core::ContentStore* test_cache() {
    static const std::unique_ptr<core::ContentStore> store = [] {
        const auto dir = core::default_cache_dir();
        return dir ? std::make_unique<core::ContentStore>(*dir) : nullptr;
    }();
    return store.get();
}

}  // namespace freestand::test
