// `freestand simulate --sine-y / --motion-y`: the biaxial JSON fields, the series CSV, the
// rocking refusal and errors naming the flag.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "support/run_cli.hpp"
#include "support/special_files.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_dynamics_test_cli_biaxial {

using freestand::test::run_cli;

TEST_CASE("simulate --sine-y prints the biaxial JSON fields", "[biaxial][cli]") {
    // Circular input, 0.5 g at 1 Hz, mu 0.2: the peak |u| exceeds each component's peak.
    const auto r = run_cli("simulate --block b=0.3,h=0.6,m=100 --mu 0.2 "
                           "--sine-y 0.5g,1Hz,5s,phase=90 --json");
    REQUIRE(r.exit_code == 0);
    const auto j = nlohmann::ordered_json::parse(r.out);
    CHECK(j["model"] == "biaxial_sliding");
    const double peak = j["slide_max_m"].get<double>(), px = j["slide_max_x_m"].get<double>(),
                 py = j["slide_max_y_m"].get<double>();
    CHECK(peak > 0.0);
    CHECK(peak >= std::max(px, py));
    CHECK(peak <= std::hypot(px, py));
    CHECK(j["integrator"] == "event");
    CHECK(j["pga_g"].get<double>() == Approx(0.5).epsilon(1e-9));
    // phase 0: both components equal, the motion on the 45-degree line.
    const auto diag = run_cli("simulate --block b=0.3,h=0.6,m=100 --mu 0.2 --sine-y "
                              "0.3g,1Hz,3s --json");
    REQUIRE(diag.exit_code == 0);
    const auto d = nlohmann::json::parse(diag.out);
    CHECK(d["slide_max_x_m"].get<double>() == Approx(d["slide_max_y_m"].get<double>()).epsilon(1e-12));
    CHECK(d["slide_max_m"].get<double>() ==
          Approx(std::sqrt(2.0) * d["slide_max_x_m"].get<double>()).epsilon(1e-9));
}

TEST_CASE("simulate --motion-y runs both El Centro components and writes slip_x_m, slip_y_m",
          "[biaxial][cli]") {
    const auto out = std::filesystem::temp_directory_path() / "freestand_biaxial_series.csv";
    std::filesystem::remove(out);
    const std::string common = "simulate --block b=0.3,h=0.6,m=100 --mu 0.2 --motion "
                               "tests/data/RSN175_IMPVALL.H_H-E12140.AT2 --motion-y "
                               "tests/data/RSN175_IMPVALL.H_H-E12230.AT2 --scale 3 ";
    const auto r = run_cli(common + "--json --out '" + out.string() + "'");
    REQUIRE(r.exit_code == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["slide_max_m"].get<double>() > 0.0);
    CHECK(j["slide_max_y_m"].get<double>() > 0.0);
    const std::string csv = freestand::test::slurp(out);
    CHECK(csv.find("time_s,slip_x_m,slip_y_m,v_x_mps,v_y_mps,mode") != std::string::npos);
    std::filesystem::remove(out);
    const auto cd = run_cli(common + "--integrator cd --dt 1e-4 --json");
    REQUIRE(cd.exit_code == 0);
    const auto c = nlohmann::json::parse(cd.out);
    CHECK(c["integrator"] == "cd");
    CHECK(c["slide_max_m"].get<double>() == Approx(j["slide_max_m"].get<double>()).epsilon(1e-2));
}

TEST_CASE("simulate --sine-y refuses a block that would rock, and names bad flags",
          "[biaxial][cli][errors]") {
    struct Case { std::string args, expect; int code; };
    const std::vector<Case> cases = {
        // tan(alpha) = 0.25 < mu_s = 0.6 and 0.4 g > 0.25 g: the block rocks.
        {"--block b=0.15,h=0.6,m=38 --mu 0.6 --sine-y 0.4g,2Hz,2s,phase=90",
         "--sine-y: the biaxial model has no rocking", 3},
        {"--block b=0.3,h=0.6,m=38 --mu 0.2 --sine-y 0.4g,2Hz,2s,spin=3", "--sine-y", 2},
        {"--block b=0.3,h=0.6,m=38 --mu 0.2 --sine-y 0.4g,2Hz,2s,phase=x", "--sine-y phase", 2},
        {"--block b=0.3,h=0.6,m=38 --mu 0.2 --sine-y -0.4g,2Hz,2s", "--sine-y amplitude", 3},
        {"--block b=0.3,h=0.6,m=38 --mu 0.2 --sine-y 0.4g,2Hz,2s --restitution 0.5", "--restitution", 2},
        {"--block b=0.3,h=0.6,m=38 --mu 0.2 --sine 0.4g,2Hz,2s --sine-y 0.4g,2Hz,2s",
         "exactly one of --motion, --sine and --sine-y", 2},
        {"--block b=0.3,h=0.6,m=38 --mu 0.2 --sine 0.4g,2Hz,2s --motion-y "
         "tests/data/RSN175_IMPVALL.H_H-E12230.AT2", "--motion-y: needs --motion", 2},
        {"--block b=0.3,h=0.6,m=38 --mu 0.2 --motion tests/data/RSN175_IMPVALL.H_H-E12140.AT2 "
         "--motion-y tests/data/no_such.AT2", "no_such.AT2", 5},
    };
    for (const auto& c : cases) {
        INFO(c.args);
        const auto r = run_cli("simulate " + c.args);
        CHECK(r.exit_code == c.code);
        CHECK(r.err.find(c.expect) != std::string::npos);
    }
}

}  // namespace freestand_test_dynamics_test_cli_biaxial
