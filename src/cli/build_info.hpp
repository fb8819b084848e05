#pragma once
/// Facts about the build that outputs are stamped with.
#include <string>

namespace freestand::cli {

/// Short commit of the source tree at build time ("unknown" outside git); written by
/// cmake/commit_stamp.cmake on every build.
extern const char* const build_commit;

/// What `freestand --version` prints, one fact a line: "freestand <version>", "commit <hash>",
/// then "<library> <version>" for each library linked (Eigen, FFTW as its fftw_version string,
/// Boost, fmt, toml++, nlohmann-json, mstch as its CMake package version) and "compiler <name>".
std::string version_text();

}  // namespace freestand::cli
