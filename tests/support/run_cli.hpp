#pragma once
/// Runs the freestand executable in tests and captures exit code, stdout and stderr.
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

#include "support/paths.hpp"

namespace freestand::test {

struct CliResult {
    int exit_code = -1;
    std::string out;
    std::string err;
};

inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// Runs `freestand <args>` (args already shell-quoted as needed) from the source directory.
/// prefix goes before the executable, e.g. "timeout 60 " so a regressed build fails instead of
/// hanging the suite.
inline CliResult run_cli(const std::string& args, const std::string& prefix = "") {
    static int counter = 0;
    const auto dir = std::filesystem::temp_directory_path() /
                     ("freestand_cli_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::create_directories(dir);
    const auto out = dir / "out.txt";
    const auto err = dir / "err.txt";
    const std::string cmd = "cd '" + source_dir() + "' && " + prefix + "'" + exe() + "' " + args +
                            " >'" + out.string() + "' 2>'" + err.string() + "'";
    const int status = std::system(cmd.c_str());
    CliResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    std::filesystem::remove_all(dir);
    return r;
}

}  // namespace freestand::test
