// `freestand simulate --block2 ... --mu2 ... --tunnel-height H`: two units joined by a tunnel.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "support/run_cli.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_dynamics_test_cli_pair {

using freestand::test::run_cli;

namespace {
const std::string pair_of =
    "simulate --block b=1.0,h=0.5,m=400 --mu 0.12 --motion "
    "tests/data/RSN175_IMPVALL.H_H-E12140.AT2 --scale 1.5 --tunnel-height 1.2 --json ";
const std::string single_of =
    "simulate --block b=1.0,h=0.5,m=400 --motion tests/data/RSN175_IMPVALL.H_H-E12140.AT2 "
    "--scale 1.5 --json ";
}  // namespace

TEST_CASE("simulate with a second unit prints relative_max_m and both units", "[dynamics][cli]") {
    const auto r = run_cli(pair_of + "--block2 b=1.0,h=0.5,m=600 --mu2 0.18");
    REQUIRE(r.exit_code == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["relative_max_m"].get<double>() > 1e-3);
    CHECK(j["tunnel_height_m"].get<double>() == 1.2);
    CHECK(j["model"] == "two rigid planar blocks under the same base motion (docs/methods.md s.10)");
    // Sliding only: each unit's peak is its own single run's.
    const auto one = nlohmann::json::parse(run_cli(single_of + "--mu 0.12").out);
    const auto two = nlohmann::json::parse(run_cli(single_of + "--mu 0.18").out);
    CHECK(j["unit1"]["slide_max_m"].get<double>() == one["slide_max_m"].get<double>());
    CHECK(j["unit2"]["slide_max_m"].get<double>() == two["slide_max_m"].get<double>());
    CHECK(j["relative_max_m"].get<double>() >=
          std::abs(one["slide_max_m"].get<double>() - two["slide_max_m"].get<double>()) - 1e-12);
    // The same unit twice: no relative displacement.
    const auto same = run_cli(pair_of + "--block2 b=1.0,h=0.5,m=600 --mu2 0.12");
    CHECK(nlohmann::json::parse(same.out)["relative_max_m"].get<double>() == 0.0);
}

TEST_CASE("simulate's second-unit options are refused naming the option", "[dynamics][cli][errors]") {
    const std::string base = "simulate --block b=1.0,h=0.5,m=400 --mu 0.12 --sine 0.4g,2Hz,2s ";
    auto r = run_cli(base + "--block2 b=1.0,h=0.5 --tunnel-height 1");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--mu2: needed for a second unit") != std::string::npos);
    r = run_cli(base + "--mu2 0.2 --tunnel-height 1");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--block2: needed for a second unit") != std::string::npos);
    r = run_cli(base + "--block2 b=1.0,h=0.5 --mu2 0.2");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--tunnel-height: needed for a second unit") != std::string::npos);
    r = run_cli(base + "--block2 b=1.0,h=0.5 --mu2 -0.2 --tunnel-height 1");
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("--mu2") != std::string::npos);
    r = run_cli(base + "--block2 b=1.0,h=0.5 --mu2 0.2 --mu-k2 0.3 --tunnel-height 1");
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("--mu-k2") != std::string::npos);
    r = run_cli(base + "--block2 b=1.0,h=0.5 --mu2 0.2 --restitution2 1.5 --tunnel-height 1");
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("--restitution2") != std::string::npos);
    r = run_cli(base + "--block2 b=1.0,h=0.5 --mu2 0.2 --tunnel-height -1");
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("--tunnel-height (m)") != std::string::npos);
    r = run_cli(base + "--block2 b=-1.0,h=0.5 --mu2 0.2 --tunnel-height 1");
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("--block2") != std::string::npos);
    r = run_cli(base + "--block2 b=1.0,q=0.5 --mu2 0.2 --tunnel-height 1");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--block2") != std::string::npos);
    r = run_cli("simulate --block b=1.0,h=0.5,m=400 --mu 0.12 --motion "
                "tests/data/RSN175_IMPVALL.H_H-E12140.AT2 --motion-y "
                "tests/data/RSN175_IMPVALL.H_H-E12230.AT2 --block2 b=1.0,h=0.5 --mu2 0.2 "
                "--tunnel-height 1");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--motion-y: not available with a second unit") != std::string::npos);
}

}  // namespace freestand_test_dynamics_test_cli_pair
