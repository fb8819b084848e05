#pragma once
/// Tables of command lines that must each end with a given exit code and error text.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "support/run_cli.hpp"

namespace freestand::test {

struct CliProbe {
    std::string args;
    std::string message;  ///< a part of standard error
    int exit_code;
};

/// Runs each probe (prefix as for run_cli) and checks its exit code and message.
inline void check_cli_probes(const std::vector<CliProbe>& probes, const std::string& prefix = "") {
    for (const CliProbe& p : probes) {
        INFO(p.args);
        const CliResult r = run_cli(p.args, prefix);
        CHECK(r.exit_code == p.exit_code);
        CHECK_THAT(r.err, Catch::Contains(p.message));
    }
}

}  // namespace freestand::test
