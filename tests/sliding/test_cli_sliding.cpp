#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "support/run_cli.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_sliding_test_cli_sliding {

using freestand::test::run_cli;
using nlohmann::json;

namespace {

std::filesystem::path scratch() {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("freestand_sliding_cli_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir;
}

// Spectrum file of docs/methods.md s.8's format; damping_line "" leaves the damping out.
std::string write_spectrum(const std::string& name, const std::string& damping_line,
                           const std::vector<std::pair<double, double>>& rows) {
    const auto path = scratch() / name;
    std::ofstream out(path);
    out << "# test spectrum\n" << damping_line << "frequency_hz,psa_g\n";
    for (const auto& [f, a] : rows) out << f << "," << a << "\n";
    return path.string();
}

// PSA = 0.1 f at 10% damping: crossing of level L at f = 10 L.
std::string power_law_file() {
    return write_spectrum("power10.csv", "# damping: 0.1\n",
                          {{0.25, 0.025}, {1.0, 0.1}, {4.0, 0.4}, {16.0, 1.6}});
}

}  // namespace

TEST_CASE("classify: the b=0.15, h=0.6, mu 0.32, 0.8 g example in JSON", "[sliding][cli]") {
    const auto r = run_cli("classify --block b=0.15,h=0.6 --mu 0.32 --a-g 0.8 --av-g 0 --json");
    REQUIRE(r.exit_code == 0);
    const json j = json::parse(r.out);
    CHECK(j["mode"] == "slide-rock");
    CHECK(j["tan_alpha"].get<double>() == Approx(0.25).epsilon(1e-15));
    // Shenton: (0.8 * 1.25 + 0.75) / (4.0625 + 0.6) = 0.375335.
    CHECK(j["mu_crit"].get<double>() == Approx(1.75 / 4.6625).epsilon(1e-12));
    CHECK(j["edges"]["left"]["mode"] == "slide-rock");
    CHECK(j["decided_by"] == "A > tan(alpha) and tan(alpha) < mu_s < mu_crit(A)");
}

TEST_CASE("classify: text output, rest with a null mu_crit and its reason", "[sliding][cli]") {
    const auto r = run_cli("classify --block b=0.15,h=0.6 --mu 0.32 --a-g 0.2");
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("mode: rest") != std::string::npos);
    CHECK(r.out.find("mu_crit(A): n/a (A = 0.2 <= tan(alpha) = 0.25: no uplift demanded)") !=
          std::string::npos);
    const auto j = json::parse(run_cli("classify --block b=0.15,h=0.6 --mu 0.32 --a-g 0.2 --json").out);
    CHECK(j["mu_crit"].is_null());
    CHECK(j["mu_crit_reason"].get<std::string>().find("no uplift") != std::string::npos);
}

TEST_CASE("classify: asymmetric block through --cg and --inertia", "[sliding][cli]") {
    // b = 0.15, CG 0.05 m right of centre: b_L = 0.2, b_R = 0.1, h = 0.6.
    const auto r = run_cli("classify --block b=0.15,h=0.6,m=38 --cg x=0.05 --inertia 2 --mu 0.5 "
                           "--a-g 0.3 --json");
    REQUIRE(r.exit_code == 0);
    const json j = json::parse(r.out);
    CHECK(j["edge"] == "right");
    CHECK(j["edges"]["right"]["tan_alpha"].get<double>() == Approx(0.1 / 0.6));
    CHECK(j["edges"]["left"]["tan_alpha"].get<double>() == Approx(0.2 / 0.6));
    CHECK(j["edges"]["right"]["mode"] == "rock");
    CHECK(j["edges"]["left"]["mode"] == "rest");
}

TEST_CASE("classify: out-of-range input is a clear error", "[sliding][cli]") {
    auto r = run_cli("classify --block b=0.15,h=0.6 --mu -0.1 --a-g 0.8");
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("--mu: value -0.1 is out of range") != std::string::npos);
    r = run_cli("classify --block b=0,h=0.6 --mu 0.3 --a-g 0.8");
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("half-width") != std::string::npos);
    r = run_cli("classify --block b=0.15 --mu 0.3 --a-g 0.8");
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("block h: missing") != std::string::npos);
    r = run_cli("classify --block b=0.15,h=0.6,m=1 --cg x=0.05 --mu 0.3 --a-g 0.8");
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("inertia") != std::string::npos);
    r = run_cli("classify --block b=0.15,h=0.6 --mu 0.3 --a-g 0.8 --av-g 1");
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("--av-g") != std::string::npos);
    r = run_cli("classify --block b=0.15,h=0.6 --mu 0.3");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("a-g") != std::string::npos);
}

TEST_CASE("slide: glove box example with a given f_es", "[sliding][cli]") {
    const auto r = run_cli("slide --mu 0.15 --av-g 0.2243 --pgd-m 0.040 --fes-hz 1.2 --json");
    REQUIRE(r.exit_code == 0);
    const json j = json::parse(r.out);
    CHECK(j["mu_e"].get<double>() == Approx(0.1365).margin(5e-5));
    CHECK(j["c_s_mps2"].get<double>() == Approx(2.679).margin(5e-4));
    CHECK(j["f_es_hz"].get<double>() == 1.2);
    CHECK(j["slide_asce_m"].get<double>() == Approx(0.047).margin(5e-4));
    CHECK(j["slide_energy_m"].get<double>() == Approx(0.056).margin(5e-4));
    const auto t = run_cli("slide --mu 0.15 --av-g 0.2243 --pgd-m 0.040 --fes-hz 1.2");
    CHECK(t.out.find("ASCE 4 equivalent-linear: 0.04712 m") != std::string::npos);
}

TEST_CASE("slide: f_es read off 10% spectrum files", "[sliding][cli]") {
    const std::string f = power_law_file();
    auto r = run_cli("slide --mu 0.15 --spectrum10 '" + f + "' --json");
    REQUIRE(r.exit_code == 0);
    json j = json::parse(r.out);
    CHECK(j["f_es_hz"].get<double>() == Approx(3.0).epsilon(1e-12));
    CHECK(j["slide_energy_m"].is_null());
    CHECK(j["slide_energy_m_reason"].get<std::string>().find("pgd_m") != std::string::npos);
    // Two components: H1 = H2 = 0.1 f -> SA_VH = sqrt(1.16) 0.1 f; level 0.3 -> 3 / sqrt(1.16).
    r = run_cli("slide --mu 0.15 --spectrum10 '" + f + "," + f + "' --json");
    REQUIRE(r.exit_code == 0);
    j = json::parse(r.out);
    CHECK(j["f_es_hz"].get<double>() == Approx(3.0 / std::sqrt(1.16)).epsilon(1e-12));
    // Never reached: C_s = 2 g > 1.6 g.
    r = run_cli("slide --mu 1.0 --pgd-m 0.1 --spectrum10 '" + f + "' --json");
    REQUIRE(r.exit_code == 0);
    j = json::parse(r.out);
    CHECK(j["slides"] == false);
    CHECK(j["slide_asce_m"].is_null());
    CHECK(j["slide_asce_m_reason"].get<std::string>().find("does not slide") != std::string::npos);
    CHECK(j["slide_energy_m"].is_null());
}

TEST_CASE("slide: bad spectra and options are clear errors", "[sliding][cli]") {
    const std::string five = write_spectrum("five.csv", "# damping: 0.05\n", {{1.0, 0.5}, {2.0, 0.6}});
    auto r = run_cli("slide --mu 0.15 --spectrum10 '" + five + "'");
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("five.csv") != std::string::npos);
    CHECK(r.err.find("damping") != std::string::npos);
    const std::string none = write_spectrum("none.csv", "", {{1.0, 0.5}, {2.0, 0.6}});
    r = run_cli("slide --mu 0.15 --spectrum10 '" + none + "'");
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("none.csv") != std::string::npos);
    CHECK(r.err.find("damping") != std::string::npos);
    r = run_cli("slide --mu 0.15 --fes-hz 1 --spectrum10 '" + power_law_file() + "'");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("exactly one of --fes-hz and --spectrum10") != std::string::npos);
    r = run_cli("slide --mu -0.15 --fes-hz 1");
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("--mu") != std::string::npos);
    // Range errors name the option as typed, with the allowed range.
    r = run_cli("slide --mu 0.15 --fes-hz 0");
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("--fes-hz: value 0 must be a finite number > 0") != std::string::npos);
    r = run_cli("slide --mu 0.15 --fes-hz 1 --pgd-m -1");
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("--pgd-m: value -1 is out of range; expected [0, inf)") != std::string::npos);
    r = run_cli("slide --mu 0.15 --fes-hz 1 --pga-g -0.2");
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("--pga-g: value -0.2 is out of range; expected [0, inf)") != std::string::npos);
    r = run_cli("slide --mu 0.15 --spectrum10 '" + power_law_file() + ",'");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--spectrum10: empty file name in") != std::string::npos);
    r = run_cli("slide --mu 0.15 --fes-hz nan");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--fes-hz: expected a finite number; got \"nan\"") != std::string::npos);
    CHECK(r.out.empty());
}

}  // namespace freestand_test_sliding_test_cli_sliding
