// Every entry point applies the same limits and names the option the user gave: PGA levels,
// friction, a spectrum's grid and a fragility run's size (core/limits.hpp, README Limits).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "support/cli_probes.hpp"
#include "support/run_cli.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_cli_test_entry_limits {

using freestand::test::run_cli;

namespace {

const std::string record = "tests/data/RSN175_IMPVALL.H_H-E12140.AT2 ";
const std::string block = "--block b=0.15,h=0.6,m=38 ";

// timeout: a regressed build fails instead of running the unbounded work.
void check_probes(const std::vector<freestand::test::CliProbe>& probes) {
    freestand::test::check_cli_probes(probes, "timeout 120 ");
}

// cases/block-ts1.toml with its pga_g line replaced, in a scratch folder.
std::filesystem::path case_with_levels(const std::string& levels) {
    const auto dir = std::filesystem::temp_directory_path() / "freestand_entry_limits";
    std::filesystem::create_directories(dir);
    std::ifstream in(freestand::test::source_dir() + "/cases/block-ts1.toml");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string key = "pga_g = [0.1, 0.2, 0.3, 0.4]";
    text.replace(text.find(key), key.size(), "pga_g = " + levels);
    const auto path = dir / "levels.toml";
    std::ofstream(path) << text;
    return path;
}

}  // namespace

TEST_CASE("a limit message names the option given and never reads 'X above the limit X'",
          "[cli][limits]") {
    check_probes({
        // The grid's size came from --per-decade, not --frequencies.
        {"spectrum " + record + "--fmin 1 --fmax 10 --per-decade 100000",
         "--per-decade: the spectrum's frequencies (decades x per decade + 1): 100001 is above "
         "the limit 100000 (README, Limits)",
         3},
        {"spectrum " + record + "--fmin 1e-6 --fmax 10",
         "--fmin: a response-spectrum frequency (Hz): 1e-06 is below the limit 0.001", 3},
        {"spectrum " + record + "--fmax 2000",
         "--fmax: a response-spectrum frequency (Hz): 2000 is above the limit 1000", 3},
        {"target --design rg1.60 --pga 3.0001",
         "--pga: a design level (g): 3.0001 is above the limit 3 (README, Limits)", 3},
    });
}

TEST_CASE("PGA levels near zero are refused at every entry point", "[cli][limits]") {
    const auto tiny = case_with_levels("[1e-310, 0.1]");
    const auto out = std::filesystem::temp_directory_path() / "freestand_entry_limits_out";
    check_probes({
        // No level the results' rounding cannot read back, no 300-digit margin.
        {"assess '" + tiny.string() + "' --out '" + out.string() + "'",
         "levels.toml:24: site.pga_g: value 1e-310 is out of range; expected [0.001, 3]", 3},
        {"assess cases/block-ts1.toml --pga 1e-300,0.1 --out '" + out.string() + "'",
         "--pga: value 1e-300 is out of range; expected [0.001, 3]", 3},
        {"fragility cases/block-ts1.toml --pga 1e-310,0.1 --samples 2 --out '" + out.string() +
             "'",
         "--pga: value 1e-310 is out of range; expected [0.001, 3]", 3},
    });
    CHECK_FALSE(std::filesystem::exists(out));
    std::filesystem::remove_all(tiny.parent_path());
}

TEST_CASE("fragility bounds levels x samples before it runs", "[cli][limits]") {
    check_probes({
        {"fragility cases/block-ts1.toml --pga 0.1:1.0:0.01 --samples 20000 --no-cache",
         "--samples: the run's samples (levels x samples per level): 1.82e+06 is above the limit "
         "1e+06 (README, Limits)",
         3},
    });
}

TEST_CASE("friction and restitution: the case's ranges at every command", "[cli][limits]") {
    // Every command takes a case's [0, 2] for friction and [0, 1] for restitution.
    const std::string range = "is out of range; expected [0, 2]";
    check_probes({
        {"simulate " + block + "--mu 2.5 --sine 0.4g,2Hz,2s", "--mu: value 2.5 " + range, 3},
        {"simulate " + block + "--mu 1e300 --sine 0.4g,2Hz,2s", "--mu: value 1e+300 " + range, 3},
        {"simulate " + block + "--mu 2.5 --sine-y 0.4g,2Hz,2s", "--mu: value 2.5 " + range, 3},
        {"classify --block b=0.15,h=0.6 --mu 2.5 --a-g 0.3", "--mu: value 2.5 " + range, 3},
        {"rock --block b=0.15,h=0.6 --mu 2.5", "--mu: value 2.5 " + range, 3},
        {"slide --mu 2.5 --fes-hz 2", "--mu: value 2.5 " + range, 3},
        {"simulate " + block + "--mu 0.5 --restitution 1.5 --sine 0.4g,2Hz,2s",
         "--restitution: value 1.5 is out of range; expected [0, 1]", 3},
        // The second unit's too.
        {"simulate --block b=1.0,h=0.5,m=400 --mu 0.12 --sine 0.4g,2Hz,2s --tunnel-height 1.2 "
         "--block2 b=1.0,h=0.5,m=600 --mu2 2.5",
         "--mu2: value 2.5 " + range, 3},
    });
    // The range's ends are accepted, as in a case.
    CHECK(run_cli("simulate " + block + "--mu 2 --sine 0.1g,2Hz,1s --json").exit_code == 0);
    CHECK(run_cli("rock --block b=0.15,h=0.6 --mu 2 --restitution 0 --pga-g 0.1 --json")
              .exit_code == 0);
}

}  // namespace freestand_test_cli_test_entry_limits
