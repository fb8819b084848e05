// Every size is bounded before allocation (exit 3 naming the limit; README "Limits"), and a
// folder given as an input file is an I/O error. Unbounded, each command here hangs, runs out of
// memory or crashes.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "support/run_cli.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_cli_test_limits {

using freestand::test::run_cli;
using Catch::Contains;

namespace {
const std::string block = "--block b=0.15,h=0.6,m=38 --mu 0.5 ";
const std::string record = "tests/data/RSN175_IMPVALL.H_H-E12140.AT2 ";
}  // namespace

TEST_CASE("sizes beyond the documented limits are input errors, not hangs",
          "[cli][limits][hardening]") {
    struct Probe {
        std::string args;
        std::string message;
    };
    const std::vector<Probe> probes{
        {"simulate " + block + "--sine 0.1g,2Hz,1e9s",
         "the sine's sampling (duration / step): 8e+11 is above the limit 1e+07"},
        {"simulate " + block + "--sine 0.5g,1e9Hz,10s",
         "the sine's frequency: 1e+09 is above the limit 1000"},
        {"simulate " + block + "--sine 0.5g,2Hz,10s --integrator cd --dt 1e-12",
         "central difference (duration / dt): 2e+13 is above the limit 1e+08"},
        {"spectrum " + record + "--frequencies 1e8",
         "a response-spectrum frequency (Hz): 1e+08 is above the limit 1000"},
        {"spectrum " + record + "--frequencies 1e300",
         "a response-spectrum frequency (Hz): 1e+300 is above the limit 1000"},
        // Out-of-range physics is an input error, not NaN or 8e304 m with exit 0 (a frequency
        // of 1e-300 Hz gives -nan; 1e-6 Hz a PSA 480 times the exact one).
        // A design level of 1e300 g would give spectral accelerations of 7.5e298 g.
        {"target --design rg1.60 --pga 1e300", "--pga: a design level (g): 1e+300 is above the limit 3"},
        {"target --design asce7 --sds 1 --sd1 4 --tl 8", "--sd1: a design level (g): 4 is above the limit 3"},
        {"generate --target ec8 --ag 5 --type 1 --ground A --out /nonexistent/never",
         "--ag: a design level (g): 5 is above the limit 3"},
        {"spectrum " + record + "--frequencies 1e-300",
         "a response-spectrum frequency (Hz): 1e-300 is below the limit 0.001"},
        {"spectrum " + record + "--frequencies 1e-6,1",
         "a response-spectrum frequency (Hz): 1e-06 is below the limit 0.001"},
        {"simulate " + block + "--motion " + record + "--scale 1e308",
         "an excitation acceleration (m/s^2, 100 g): 3.585e+305 is above the limit 981"},
    };
    for (const Probe& p : probes) {
        INFO(p.args);
        const auto r = run_cli(p.args);
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Contains(p.message));
        CHECK_THAT(r.err, Contains("(README, Limits)"));
    }
}

TEST_CASE("generate bounds a synthetic record's samples before it allocates them",
          "[cli][limits][hardening]") {
    // Unbounded, generate's --duration 1e7 takes 24 GB until the kernel kills it, --dt 1e-7 runs
    // for minutes at 20 GB, --duration 1e300 loops without end (6 MB), and --duration 1e5
    // allocates 2.8 GB to end in "sample 367 is 994.9 m/s^2, beyond the limit" of the record
    // it has made. The probes here are the two a regressed build survives: under `timeout` it
    // fails (exit 124 or the wrong message) instead of exhausting the machine.
    const std::filesystem::path out =
        std::filesystem::temp_directory_path() / "freestand_limits_generate";
    std::filesystem::remove_all(out);
    struct Probe {
        std::string args;
        std::string message;
    };
    const std::vector<Probe> probes{
        {"--duration 1e300",
         "--duration: the synthetic record's sampling (duration / dt): 2e+302 is above the limit "
         "1e+07"},
        {"--duration 1e5",
         "--duration: the synthetic record's sampling (duration / dt): 2e+07 is above the limit "
         "1e+07"},
    };
    for (const Probe& p : probes) {
        INFO(p.args);
        const auto r = run_cli("generate --target rg1.60 --pga 0.3 " + p.args + " --out '" +
                                   out.string() + "'",
                               "timeout 60 ");
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Contains(p.message));
        CHECK_THAT(r.err, Contains("(README, Limits)"));
        CHECK_FALSE(std::filesystem::exists(out));
    }
}

TEST_CASE("a folder where a file is expected is an I/O error", "[cli][hardening]") {
    const auto r = run_cli("assess cases");
    CHECK(r.exit_code == 5);
    CHECK_THAT(r.err, Contains("cases: is a folder; expected a file"));
    const auto s = run_cli("spectrum tests/data");
    CHECK(s.exit_code == 5);
}

TEST_CASE("a record time step outside [1e-6, 1] s is an input error", "[cli][limits][hardening]") {
    // Unchecked, DT= 1e300 gives "pgd_m": null with exit 0.
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / "freestand_limits_dt";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "big.AT2") << "PEER\nRECORD\nACCELERATION TIME SERIES IN UNITS OF G\n"
                                      "NPTS= 3, DT= 1e300 SEC\n0.1 0.2 0.3\n";
    const auto r = run_cli("spectrum '" + (dir / "big.AT2").string() + "' --json");
    CHECK(r.exit_code == 3);
    CHECK_THAT(r.err, Contains("time step 1e+300 s is outside [1e-06, 1] s (README, Limits)"));
    std::filesystem::remove_all(dir);
}

TEST_CASE("library parameters are shown as the options the user typed", "[cli][hardening]") {
    // The dynamics library names cd_dt_s, sine.ramp_s and mu_s; the command line maps
    // them to --dt, --sine and --mu in one place (cli/flag_names.hpp).
    CHECK_THAT(run_cli("simulate " + block + "--sine 0.5g,2Hz,10s --integrator cd --dt -1").err,
               Contains("simulate: error: --dt: value -1 must be a finite number > 0"));
    CHECK_THAT(run_cli("simulate --block b=0.15,h=0.6,m=38 --mu -0.1 --sine 0.5g,2Hz,10s").err,
               Contains("error: --mu: value -0.1 is out of range; expected [0, 2]"));
}

}  // namespace freestand_test_cli_test_limits
