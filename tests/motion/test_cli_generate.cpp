// `freestand generate`: files, match.json keys, byte-identical reruns, errors with exit codes.
#include <catch2/catch.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/paths.hpp"
#include "core/readers.hpp"
#include "support/run_cli.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_motion_test_cli_generate {

using freestand::test::run_cli;
using freestand::test::slurp;
namespace fs = std::filesystem;

namespace {
fs::path scratch(const std::string& name) {
    const fs::path p =
        fs::temp_directory_path() / ("freestand_gen_" + std::to_string(::getpid()) + "_" + name);
    fs::remove_all(p);
    return p;
}
}  // namespace

TEST_CASE("generate writes one CSV per component and match.json with the issue's keys",
          "[motion][cli]") {
    const fs::path out = scratch("a");
    const auto r = run_cli("generate --target rg1.60 --pga 0.2 --components h1,v --seed 3 --out '" +
                           out.string() + "'");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(fs::exists(out / "h1.csv"));
    CHECK(fs::exists(out / "v.csv"));
    const auto j = nlohmann::json::parse(slurp(out / "match.json"));
    CHECK(j["passed"] == true);
    REQUIRE(j["components"].size() == 2);
    for (const char* key : {"component", "passed", "min_ratio", "max_ratio", "mean_ratio",
                            "max_adjacent_below", "pga_g", "pgv_mps", "pgd_m", "final_velocity_mps",
                            "final_displacement_m", "d5_75_s", "iterations", "wall_s"})
        CHECK(j["components"][0].contains(key));
    CHECK(j["components"][1]["component"] == "v");
    CHECK(j["correlations"].size() == 1);
    // Every history reports its ground-motion measures and realism checks (docs/methods.md s.8).
    const auto& h1 = j["components"][0];
    for (const char* key : {"pga_g", "pgv_mps", "pgd_m", "va_mps_per_g", "adv2", "da_m_per_g",
                            "arias_mps", "d5_75_s", "d5_95_s", "zpa_g", "pga_over_zpa"})
        CHECK(h1["measures"].contains(key));
    CHECK(h1["measures"]["zpa_g"] == 0.2);
    CHECK(h1["realism"]["passed"] == true);
    CHECK(h1["realism"]["va_range_mps_per_g"] == nlohmann::json::array({0.8, 2.0}));
    CHECK(h1["realism"]["ratios_checked"] == true);
    CHECK(j["components"][1]["realism"]["ratios_checked"] == false);
    CHECK(slurp(out / "h1.csv").find("time_s,accel_g\n0,") != std::string::npos);
    fs::remove_all(out);
}

TEST_CASE("generate checks the realism ranges the options set, and exits 1 when one fails",
          "[motion][cli]") {
    const fs::path out = scratch("realism");
    // ASCE 7 has no V/A range of its own: reported, not checked...
    auto r = run_cli("generate --target asce7 --sds 1 --sd1 0.6 --tl 8 --components h1 --out '" +
                     out.string() + "'");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    auto j = nlohmann::json::parse(slurp(out / "match.json"));
    CHECK(j["components"][0]["realism"]["va_range_mps_per_g"].is_null());
    const double va = j["components"][0]["measures"]["va_mps_per_g"];
    // ...until --va-range asks for a range the history cannot meet.
    const fs::path out2 = scratch("realism2");
    r = run_cli("generate --target asce7 --sds 1 --sd1 0.6 --tl 8 --components h1 --va-range " +
                std::to_string(va * 2.0) + "," + std::to_string(va * 3.0) + " --out '" +
                out2.string() + "'");
    CHECK(r.exit_code == 1);
    j = nlohmann::json::parse(slurp(out2 / "match.json"));
    CHECK(j["passed"] == false);
    CHECK_THAT(j["components"][0]["reason"].get<std::string>(), Catch::Contains("V/A"));
    CHECK(j["components"][0]["realism"]["passed"] == false);
    CHECK(j["components"][0]["realism"]["srp_passed"] == true);
    fs::remove_all(out);
    fs::remove_all(out2);
}

TEST_CASE("generate's match.json cites docs/methods.md and the standards it applies",
          "[motion][cli][references]") {
    const fs::path out = scratch("refs");
    const auto r = run_cli("generate --target rg1.60 --pga 0.2 --components h1 --seed 3 --out '" +
                           out.string() + "'");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const std::string text = slurp(out / "match.json");
    CHECK(text.find(std::string("METHODS") + ".md") == std::string::npos);
    const auto j = nlohmann::json::parse(text);
    CHECK(j["methods"] == "docs/methods.md s.8");
    std::vector<std::string> keys;
    for (const auto& ref : j["references"]) {
        CHECK_FALSE(ref["text"].get<std::string>().empty());
        keys.push_back(ref["key"]);
    }
    CHECK(keys == std::vector<std::string>{"docs/methods.md", "SRP 3.7.1", "RG 1.60", "ASCE 4-16",
                                           "NUREG/CR-6728", "Nigam & Jennings 1969",
                                           "Al Atik & Abrahamson 2010"});
    fs::remove_all(out);
}

TEST_CASE("generate is byte-identical for the same inputs and seed", "[motion][cli]") {
    const fs::path a = scratch("b1"), b = scratch("b2");
    const std::string args =
        "generate --target asce7 --sds 0.8 --sd1 0.4 --tl 6 --components h1 --no-timing --out ";
    REQUIRE(run_cli(args + "'" + a.string() + "'").exit_code == 0);
    REQUIRE(run_cli(args + "'" + b.string() + "'").exit_code == 0);
    CHECK(slurp(a / "h1.csv") == slurp(b / "h1.csv"));
    CHECK(slurp(a / "match.json") == slurp(b / "match.json"));
    fs::remove_all(a);
    fs::remove_all(b);
}

TEST_CASE("generate matches a seed record given on the command line", "[motion][cli]") {
    const fs::path out = scratch("c");
    const auto r = run_cli(
        "generate --target rg1.60 --pga 0.3 --seed-record tests/data/RSN175_IMPVALL.H_H-E12230.AT2 "
        "--out '" +
        out.string() + "'");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const auto j = nlohmann::json::parse(slurp(out / "match.json"));
    REQUIRE(j["components"].size() == 1);
    CHECK(j["components"][0]["method"].get<std::string>().find("RSN175") != std::string::npos);
    fs::remove_all(out);
}

TEST_CASE("generate refuses an output that is an input of the run before writing any file",
          "[motion][cli][hardening]") {
    // With --seed-record A.AT2,gdir/h2.csv --out gdir, writing file by file would replace h1.csv
    // before finding h2.csv is an input (exit 5 with a changed folder).
    const fs::path dir = scratch("input_out");
    fs::create_directories(dir);
    // A folder a previous run wrote (its marker lists its files), holding a seed record.
    std::ofstream(dir / ".freestand-run") << "Written by freestand.\nh1.csv\nh2.csv\n";
    std::ofstream(dir / "h1.csv") << "previous run\n";
    freestand::core::write_csv_g(
        freestand::core::read_at2(fs::path(freestand::test::data_dir()) / "RSN175_IMPVALL.H_H-E12230.AT2"),
        dir / "h2.csv");
    const std::string h2_before = slurp(dir / "h2.csv");
    const auto r = run_cli("generate --target rg1.60 --pga 0.3 --seed-record "
                           "tests/data/RSN175_IMPVALL.H_H-E12140.AT2,'" +
                           (dir / "h2.csv").string() + "' --out '" + dir.string() + "'");
    CHECK(r.exit_code == 5);
    CHECK_THAT(r.err, Catch::Contains("h2.csv: refusing to overwrite an input file of this run"));
    CHECK(slurp(dir / "h1.csv") == "previous run\n");
    CHECK(slurp(dir / "h2.csv") == h2_before);
    CHECK_FALSE(fs::exists(dir / "match.json"));
    fs::remove_all(dir);
}

TEST_CASE("generate rejects bad requests with a clear message and exit code",
          "[motion][cli][errors]") {
    const fs::path out = scratch("d");
    auto r = run_cli("generate --target rg1.60 --pga 0.2 --dt 0.02 --out '" + out.string() + "'");
    CHECK(r.exit_code == 3);
    CHECK_THAT(r.err, Catch::Contains("dt 0.02 s is too coarse"));
    r = run_cli("generate --target rg1.60 --pga 0.2 --duration 15 --out '" + out.string() + "'");
    CHECK(r.exit_code == 3);
    CHECK_THAT(r.err, Catch::Contains("duration 15 s is too short"));
    r = run_cli("generate --target rg1.60 --out '" + out.string() + "'");
    CHECK(r.exit_code == 3);
    CHECK_THAT(r.err, Catch::Contains("--pga: required by design rg1.60"));
    r = run_cli("generate --target nureg --pga 0.2 --out '" + out.string() + "'");
    CHECK(r.exit_code == 3);
    CHECK_THAT(r.err, Catch::Contains("--target: unknown design \"nureg\""));
    r = run_cli("generate --out '" + out.string() + "'");
    CHECK(r.exit_code == 3);
    CHECK_THAT(r.err, Catch::Contains("--target: no target; expected a design (rg1.60, asce7, "
                                      "ec8, is1893) or a target spectrum file"));
    r = run_cli("generate --target rg1.60 --pga 0.2 --target-file x.csv --out '" + out.string() +
                "'");
    CHECK(r.exit_code == 3);
    CHECK_THAT(r.err, Catch::Contains("--target-file: excludes a design target; give one"));
    // Realism ranges: two numbers, min < max, positive; --sds belongs to asce7 only.
    r = run_cli("generate --target rg1.60 --pga 0.2 --va-range 0.8 --out '" + out.string() + "'");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains("--va-range: expected MIN,MAX (two numbers), got 1"));
    r = run_cli("generate --target rg1.60 --pga 0.2 --adv2-range 8,2 --out '" + out.string() + "'");
    CHECK(r.exit_code == 3);
    CHECK_THAT(r.err, Catch::Contains("adv2") && Catch::Contains("expected min < max"));
    r = run_cli("generate --target rg1.60 --pga 0.2 --da-max -1 --out '" + out.string() + "'");
    CHECK(r.exit_code == 3);
    CHECK_THAT(r.err, Catch::Contains("da"));
    r = run_cli("generate --target rg1.60 --pga 0.2 --sds 1 --out '" + out.string() + "'");
    CHECK(r.exit_code == 3);
    CHECK_THAT(r.err, Catch::Contains("--sds: does not apply to design rg1.60"));
    r = run_cli(
        "generate --target rg1.60 --pga 0.2 --seed-record tests/data/RSN175_IMPVALL.H_H-E12230.AT2 "
        "--dt 0.005 --out '" +
        out.string() + "'");
    CHECK(r.exit_code == 3);
    CHECK_THAT(r.err, Catch::Contains("--dt: applies to synthetic records"));
    // Target files: missing damping, non-increasing frequency, non-positive PSA.
    fs::create_directories(out);
    const auto write = [&](const std::string& name, const std::string& text) {
        const fs::path p = out / name;
        std::ofstream(p) << text;
        return p.string();
    };
    // An all-zero seed record is refused as such, not as "sample 0 is not a finite number".
    std::string zeros = "# dt_s: 0.005\naccel_g\n";
    for (int i = 0; i < 5000; ++i) zeros += "0\n";
    const std::string zero_file = write("zero.csv", zeros);
    r = run_cli("generate --target rg1.60 --pga 0.2 --components h1 --seed-record '" + zero_file +
                "' --out '" + (out / "zero_out").string() + "'");
    CHECK(r.exit_code == 3);
    CHECK_THAT(r.err, Catch::Contains("zero.csv: seed record \"zero\" is zero at all 5000 "
                                      "samples; a seed record needs motion to match"));
    CHECK_FALSE(fs::exists(out / "zero_out"));
    r = run_cli("generate --target-file '" +
                write("nodamp.csv", "frequency_hz,psa_g\n0.1,0.1\n10,0.5\n") + "' --out '" +
                out.string() + "'");
    CHECK(r.exit_code == 3);
    CHECK_THAT(r.err, Catch::Contains("damping"));
    r = run_cli("generate --target-file '" +
                write("order.csv", "# damping: 0.05\nfrequency_hz,psa_g\n1,0.1\n1,0.5\n") +
                "' --out '" + out.string() + "'");
    CHECK(r.exit_code == 3);
    CHECK_THAT(r.err, Catch::Contains("order.csv"));
    r = run_cli("generate --target-file '" +
                write("neg.csv", "# damping: 0.05\nfrequency_hz,psa_g\n1,0.1\n2,-0.5\n") +
                "' --out '" + out.string() + "'");
    CHECK(r.exit_code == 3);
    CHECK_THAT(r.err, Catch::Contains("neg.csv"));
    r = run_cli("generate --target-file '" +
                write("d02.csv", "# damping: 0.02\nfrequency_hz,psa_g\n1,0.1\n2,0.5\n") +
                "' --out '" + out.string() + "'");
    CHECK(r.exit_code == 3);
    CHECK_THAT(r.err, Catch::Contains("damping 0.02"));
    fs::remove_all(out);
}

}  // namespace freestand_test_motion_test_cli_generate
