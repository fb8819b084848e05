#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <unistd.h>

#include "support/run_cli.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_rocking_test_cli_rock {

using freestand::test::run_cli;
using nlohmann::json;

namespace {

constexpr double pi = std::numbers::pi;

// Constant spectral displacement d_m at the given damping, 0.01-1000 Hz.
std::string constant_sd_file(const std::string& name, double d_m, double damping) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("freestand_rocking_cli_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const auto path = dir / name;
    std::ofstream out(path);
    out.precision(17);
    out << "# damping: " << damping << "\nfrequency_hz,psa_g\n";
    for (double f : {0.01, 0.1, 1.0, 10.0, 100.0, 1000.0})
        out << f << "," << std::pow(2.0 * pi * f, 2) * d_m / 9.81 << "\n";
    return path.string();
}

}  // namespace

TEST_CASE("rock: geometry-only checks of the 0.3 x 1.2 m block", "[rocking][cli]") {
    const auto r = run_cli("rock --block b=0.15,h=0.6,m=38 --pgv-mps 0.2 --json");
    REQUIRE(r.exit_code == 0);
    const json j = json::parse(r.out);
    CHECK(j["alpha_rad"].get<double>() == Approx(0.2449787).epsilon(1e-6));
    CHECK(j["R_m"].get<double>() == Approx(0.6184658).epsilon(1e-6));
    CHECK(j["p_radps"].get<double>() == Approx(std::sqrt(3.0 * 9.81 / (4.0 * 0.6184658))).epsilon(1e-6));
    CHECK(j["restitution"].get<double>() == Approx(1.0 - 1.5 * std::pow(std::sin(0.2449787), 2)));
    CHECK(j["uplift_a_g"].get<double>() == Approx(0.25));
    CHECK(j["ishiyama_v_mps"].get<double>() == Approx(0.28227).epsilon(2e-4));
    CHECK(j["pgv_below_ishiyama"] == true);
    CHECK(j["rock_asce_rad"].is_null());
    CHECK(j["rock_asce_rad_reason"] == "needs a horizontal spectrum");
    CHECK(j["mode"].is_null());
    CHECK(j["mode_reason"] == "needs the static friction mu");
}

TEST_CASE("rock: equivalent-linear estimate from spectrum files", "[rocking][cli]") {
    // Two dampings of the same constant SD = 0.05 m: any interpolated damping gives 0.05 m and
    // theta0 = alpha - asin(sin(alpha) - D / R) = 0.0825753 rad; margin b / D = 3.
    const std::string lo = constant_sd_file("sd2.csv", 0.05, 0.02);
    const std::string hi = constant_sd_file("sd10.csv", 0.05, 0.10);
    const auto r = run_cli("rock --block b=0.15,h=0.6,m=38 --spectrum '" + lo + "," + hi +
                           "' --pga-g 0.5 --mu 0.5 --json");
    REQUIRE(r.exit_code == 0);
    const json j = json::parse(r.out);
    CHECK(j["rock_asce_rad"].get<double>() == Approx(0.0825753).epsilon(1e-6));
    CHECK(j["overturn_fs"].get<double>() == Approx(0.2449787 / 0.0825753).epsilon(1e-6));
    CHECK(j["overturn_fs_required"].get<double>() == 1.5);
    CHECK(j["overturn_fs_ok"] == true);
    CHECK(j["spectral_margin"].get<double>() == Approx(3.0).epsilon(1e-5));
    CHECK(j["rock_asce_label"].get<std::string>().find("equivalent-linear estimate") == 0);
    CHECK(j["mode"] == "rock");
    CHECK(j["amplification_warning"].get<std::string>().find("1.3 to 11") != std::string::npos);
    CHECK(j["flexible"].is_null());
    // Text output names the estimate and the margin.
    const auto t = run_cli("rock --block b=0.15,h=0.6,m=38 --spectrum '" + lo + "," + hi +
                           "' --pga-g 0.5");
    CHECK(t.out.find("equivalent-linear estimate") != std::string::npos);
    CHECK(t.out.find("spectral margin: 3") != std::string::npos);
    // Peak PSV of this spectrum is at 1000 Hz (2 pi 1000 x 0.05 = 314 m/s): Housner's alpha far
    // exceeds the block's, and the text says what that means.
    CHECK(j["housner_survives"] == false);
    CHECK(t.out.find("rad (alpha below it: may overturn)") != std::string::npos);
}

TEST_CASE("rock: flexible-body screen from the command line", "[rocking][cli]") {
    // Constant SD 0.05 m at 5%: PSA(5 Hz * 1.15) = (2 pi 5.75)^2 0.05 / 9.81 = 6.65 g >= 0.25 g,
    // while the PGA 0.1 g is below the static 0.25 g: flagged.
    const std::string f = constant_sd_file("sd5.csv", 0.05, 0.05);
    const auto r = run_cli("rock --block b=0.15,h=0.6 --spectrum '" + f + "' --pga-g 0.1 --fn-hz 5 --json");
    REQUIRE(r.exit_code == 0);
    const json j = json::parse(r.out);
    CHECK(j["flexible"]["flagged"] == true);
    CHECK(j["flexible"]["band_hi_hz"].get<double>() == Approx(5.75));
    CHECK(j["rock_asce_rad"].get<double>() == 0.0);  // below the gate
    CHECK(j["overturn_fs"].is_null());
    CHECK(j["overturn_fs_reason"].get<std::string>().find("no rocking") != std::string::npos);
}

TEST_CASE("rock: out-of-range input is a clear error", "[rocking][cli]") {
    auto r = run_cli("rock --block b=0.15,h=-0.6");
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("h (half-height, m)") != std::string::npos);
    const std::string f = constant_sd_file("sd5b.csv", 0.05, 0.05);
    r = run_cli("rock --block b=0.15,h=0.6 --spectrum '" + f + "' --restitution 1.5");
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("restitution") != std::string::npos);
    r = run_cli("rock --block b=0.15,h=0.6 --mu -1 --pga-g 0.3");
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("--mu") != std::string::npos);
    r = run_cli("rock --block b=0.15,h=0.6 --spectrum '" + f + "' --rock-band-hz 1");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--rock-band-hz") != std::string::npos);
    r = run_cli("rock --block b=0.15,h=0.6 --spectrum '" + f + "," + f + "'");
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("distinct dampings") != std::string::npos);
    r = run_cli("rock --block b=0.15,h=0.6 --spectrum '," + f + "'");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--spectrum: empty file name in") != std::string::npos);
    r = run_cli("rock --block b=0.15,h=0.6 --spectrum /nonexistent/x.csv");
    CHECK(r.exit_code != 0);
    CHECK(r.err.find("x.csv") != std::string::npos);
}

TEST_CASE("rock: range errors name the option as typed", "[rocking][cli]") {
    struct Case {
        const char* option;
        const char* message;
    };
    const Case cases[] = {
        {"--pga-g -1", "--pga-g: value -1 is out of range; expected [0, inf)"},
        {"--av-g -0.5", "--av-g: value -0.5 is out of range; expected [0, 1)"},
        {"--av-g 1", "--av-g: value 1 is out of range; expected [0, 1)"},
        {"--pgv-mps -1", "--pgv-mps: value -1 is out of range; expected [0, inf)"},
        {"--v-ratio -0.1", "--v-ratio: value -0.1 is out of range; expected [0, inf)"},
        {"--restitution 1.2", "--restitution: value 1.2 is out of range; expected [0, 1]"},
        {"--fs-required 0.5", "--fs-required: value 0.5 is out of range; expected [1, inf)"},
        {"--fn-hz 0", "--fn-hz: value 0 is out of range; expected (0, inf)"},
        {"--rock-band-hz 5,1", "--rock-band-hz: 5,1 Hz; expected 0 < LO < HI"},
        {"--rock-band-hz -1,2", "--rock-band-hz: -1,2 Hz; expected 0 < LO < HI"},
    };
    for (const auto& c : cases) {
        INFO(c.option);
        const auto r = run_cli(std::string("rock --block b=0.15,h=0.6 ") + c.option);
        CHECK(r.exit_code == 3);
        CHECK(r.out.empty());
        CHECK(r.err.find(c.message) != std::string::npos);
    }
}

}  // namespace freestand_test_rocking_test_cli_rock
