#pragma once
/// Small cases and lists for the batch tests: each case settles quickly (one level, one
/// history at most).
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace freestand::test {

namespace fs = std::filesystem;

/// A fresh folder under the temporary directory, unique to this process.
inline fs::path batch_dir(const std::string& name) {
    const fs::path d =
        fs::temp_directory_path() / ("freestand_batch_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

inline void write_text(const fs::path& p, const std::string& text) {
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
}

/// A squat steel box at 0.05 g: at rest at both friction bounds, so no history is generated.
inline std::string resting_case(const std::string& component_name) {
    return R"([component]
name = ")" + component_name + R"("
mass_kg = 500.0
width_m = 1.2
depth_m = 1.0
height_m = 0.8
base_material = "steel"
allowable_slide_m = 0.050

[site]
pga_g = [0.05]
)";
}

/// The glove box on PVC at 0.2 g, one history per level: it slides, so one history set is
/// generated and simulated.
inline std::string sliding_case(const std::string& component_name) {
    return R"([component]
name = ")" + component_name + R"("
mass_kg = 382.0
cg_height_m = 1.22
cg_to_edge_x_m = [0.526, 0.526]
cg_to_edge_y_m = [0.526, 0.526]
p_radps = 1.97
base_material = "PVC sheet on concrete"
allowable_slide_m = 0.050

[site]
pga_g = [0.2]

[options]
histories_per_level = 1
seed = 3
)";
}

}  // namespace freestand::test
