#include <boost/version.hpp>
#include <fftw3.h>
#include <fmt/format.h>

#include "cli/build_info.hpp"
#include "core/version.hpp"

namespace freestand::cli {

namespace {

std::string compiler() {
#if defined(__clang__)
    return fmt::format("clang {}.{}.{}", __clang_major__, __clang_minor__, __clang_patchlevel__);
#elif defined(__GNUC__)
    return fmt::format("GCC {}.{}.{}", __GNUC__, __GNUC_MINOR__, __GNUC_PATCHLEVEL__);
#else
    return "unknown";
#endif
}

}  // namespace

std::string version_text() {
    // FFTW, the one C library, reports the shared library loaded at run time; Boost and fmt
    // the headers compiled in. Eigen, toml++ and nlohmann-json are header-only packages whose
    // headers are large to compile for a version number, and mstch's header has none: CMake
    // passes the versions their find_package read from the installed packages
    // (src/cli/CMakeLists.txt), which are the headers this build compiled.
    std::string text = fmt::format("freestand {}\ncommit {}\n", core::version(), build_commit);
    text += fmt::format("Eigen {}\n", FREESTAND_EIGEN_VERSION);
    text += fmt::format("FFTW {}\n", fftw_version);
    text += fmt::format("Boost {}.{}.{}\n", BOOST_VERSION / 100000, BOOST_VERSION / 100 % 1000, BOOST_VERSION % 100);
    text += fmt::format("fmt {}.{}.{}\n", FMT_VERSION / 10000, FMT_VERSION / 100 % 100, FMT_VERSION % 100);
    text += fmt::format("toml++ {}\n", FREESTAND_TOMLPLUSPLUS_VERSION);
    text += fmt::format("nlohmann-json {}\n", FREESTAND_NLOHMANN_JSON_VERSION);
    text += fmt::format("mstch {}\n", FREESTAND_MSTCH_VERSION);
    text += fmt::format("compiler {}\n", compiler());
    return text;
}

}  // namespace freestand::cli
