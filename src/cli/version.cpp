#include <Eigen/Core>
#include <boost/version.hpp>
#include <fftw3.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "cli/build_info.hpp"

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
    // Header-only libraries report the headers compiled in; FFTW, the one C library, reports
    // the shared library loaded at run time; mstch has no version in its header, so CMake's
    // find_package passes the installed package's (src/cli/CMakeLists.txt).
    std::string text = fmt::format("freestand {}\ncommit {}\n", FREESTAND_VERSION, build_commit);
    text += fmt::format("Eigen {}.{}.{}\n", EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION);
    text += fmt::format("FFTW {}\n", fftw_version);
    text += fmt::format("Boost {}.{}.{}\n", BOOST_VERSION / 100000, BOOST_VERSION / 100 % 1000, BOOST_VERSION % 100);
    text += fmt::format("fmt {}.{}.{}\n", FMT_VERSION / 10000, FMT_VERSION / 100 % 100, FMT_VERSION % 100);
    text += fmt::format("toml++ {}.{}.{}\n", TOML_LIB_MAJOR, TOML_LIB_MINOR, TOML_LIB_PATCH);
    text += fmt::format("nlohmann-json {}.{}.{}\n", NLOHMANN_JSON_VERSION_MAJOR, NLOHMANN_JSON_VERSION_MINOR,
                        NLOHMANN_JSON_VERSION_PATCH);
    text += fmt::format("mstch {}\n", FREESTAND_MSTCH_VERSION);
    text += fmt::format("compiler {}\n", compiler());
    return text;
}

}  // namespace freestand::cli
