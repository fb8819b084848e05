#pragma once
/// Facts about the build that outputs are stamped with.
#include <string>

#include "api/build_commit.hpp"

namespace freestand::cli {

using api::build_commit;

/// What `freestand --version` prints, one fact a line: "freestand <version>", "commit <hash>",
/// then "<library> <version>" for each library linked (Eigen, FFTW as its fftw_version string,
/// Boost, fmt, toml++, nlohmann-json, mstch as its CMake package version) and "compiler <name>".
std::string version_text();

}  // namespace freestand::cli
