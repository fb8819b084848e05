// `freestand spectrum` and `freestand target`: output shape, values, and every bad option.
#include <fmt/format.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "support/paths.hpp"
#include "core/measures.hpp"
#include "core/readers.hpp"
#include "spectra/design.hpp"
#include "spectra/spectrum.hpp"
#include "support/run_cli.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_spectra_test_cli_spectra {

namespace fs = std::filesystem;
using namespace freestand;
using test::run_cli;

namespace {
const std::string el_centro = "tests/data/RSN175_IMPVALL.H_H-E12140.AT2";

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
}
}  // namespace

TEST_CASE("spectrum --json prints one object with the record measures and PSA per damping",
          "[spectra][cli]") {
    const auto r = run_cli("spectrum " + el_centro + " --damping 0.05,0.10 --json");
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.empty());
    const auto j = nlohmann::json::parse(r.out);
    for (const char* key : {"record", "dt_s", "pga_g", "pgv_mps", "pgd_m", "frequencies_hz",
                            "psa_g", "sd_m", "psv_mps"})
        CHECK(j.contains(key));
    CHECK(j["record"] == "RSN175_IMPVALL.H_H-E12140");
    CHECK(j["dt_s"].get<double>() == Approx(0.005));
    const auto rec = core::read_at2(fs::path(freestand::test::source_dir()) / el_centro);
    CHECK(j["pga_g"].get<double>() == Approx(core::measure(rec).pga_g).epsilon(1e-12));
    CHECK(j["frequencies_hz"].size() == 301);
    REQUIRE(j["psa_g"].contains("0.05"));
    REQUIRE(j["psa_g"].contains("0.1"));
    CHECK(j["psa_g"]["0.05"].size() == 301);
    // Rigid limit at 100 Hz: PSA close to PGA.
    CHECK(j["psa_g"]["0.05"].back().get<double>() ==
          Approx(j["pga_g"].get<double>()).epsilon(0.01));
}

TEST_CASE("spectrum prints CSV: frequency_hz then psa_g_<damping> per damping", "[spectra][cli]") {
    const auto r = run_cli("spectrum " + el_centro +
                           " --damping 0.02,0.05 --fmin 0.5 --fmax 50 --per-decade 10");
    REQUIRE(r.exit_code == 0);
    const auto l = lines(r.out);
    REQUIRE(l.size() == 22);  // header + 2 decades * 10 + 1
    CHECK(l[0] == "frequency_hz,psa_g_0.02,psa_g_0.05");
    CHECK(l[1].rfind("0.5,", 0) == 0);
    CHECK(l.back().rfind("50,", 0) == 0);
    const auto u = run_cli("spectrum " + el_centro + " --frequencies 1,2,5");
    REQUIRE(u.exit_code == 0);
    CHECK(lines(u.out).size() == 4);
}

TEST_CASE("target rg1.60 prints the RG 1.60 spectrum, --output writes the spectrum file format",
          "[spectra][cli]") {
    const auto r = run_cli(
        "target --design rg1.60 --pga 0.3 --damping 0.05 --frequencies 0.25,2.5,9,33 --json");
    REQUIRE(r.exit_code == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["design"] == "rg1.60");
    const auto& psa = j["psa_g"]["0.05"];
    CHECK(psa[1].get<double>() == Approx(0.939).epsilon(1e-12));
    CHECK(psa[2].get<double>() == Approx(0.783).epsilon(1e-12));
    CHECK(psa[3].get<double>() == Approx(0.3).epsilon(1e-12));
    const auto v = run_cli("target --design rg1.60 --pga 0.3 --vertical --frequencies 3.5");
    REQUIRE(v.exit_code == 0);
    CHECK(lines(v.out)[1] == fmt::format("3.5,{}", 2.98 * 0.3));

    const fs::path out = fs::temp_directory_path() / "freestand_cli_target_out.csv";
    const auto w =
        run_cli("target --design ec8 --ag 0.2 --type 1 --ground B --damping 0.1 --output '" +
                out.string() + "'");
    REQUIRE(w.exit_code == 0);
    const auto s = spectra::read_spectrum_csv(out);
    CHECK(s.damping == 0.1);
    CHECK(s.psa_g == spectra::ec8(0.2, spectra::Ec8Type::type1, 'B', 0.1,
                                  spectra::log_frequencies(0.1, 100, 100))
                         .psa_g);
}

TEST_CASE("target asce7, ec8 and is1893 take their own parameters", "[spectra][cli]") {
    const auto a = run_cli("target --design asce7 --sds 1.0 --sd1 0.6 --tl 8 --frequencies 1");
    REQUIRE(a.exit_code == 0);
    CHECK(lines(a.out)[1] == "1,0.6");
    const auto e = run_cli(
        "target --design ec8 --ag 0.25 --type 2 --ground A --damping 0.05,0.1 --frequencies 5");
    REQUIRE(e.exit_code == 0);
    CHECK(lines(e.out)[0] == "frequency_hz,psa_g_0.05,psa_g_0.1");
    const auto i = run_cli("target --design is1893 --pga 0.2 --soil soft --frequencies 0.5");
    REQUIRE(i.exit_code == 0);
    CHECK(lines(i.out)[1] == fmt::format("0.5,{}", 0.2 * 1.67 / 2.0));
}

TEST_CASE("bad options exit 2 (usage) or 3 (value) and name the option", "[spectra][cli]") {
    struct Case {
        std::string args;
        int code;
        const char* message;
    };
    const Case cases[] = {
        {"spectrum", 2, "the option '--record' is required"},
        {"spectrum " + el_centro + " --bogus", 2, "unrecognised option '--bogus'"},
        {"spectrum " + el_centro + " --damping 1.5", 3,
         "--damping: value 1.5 is out of range; expected (0, 1)"},
        {"spectrum " + el_centro + " --damping 0", 3,
         "--damping: value 0 is out of range; expected (0, 1)"},
        {"spectrum " + el_centro + " --damping 0.05,abc", 2,
         "--damping: expected a finite number; got \"abc\""},
        {"spectrum " + el_centro + " --damping 0.05,0.05", 3, "--damping: 0.05 given twice"},
        {"spectrum " + el_centro + " --fmin 10 --fmax 1", 3,
         "--fmax: 1 Hz; expected more than the lowest frequency 10 Hz"},
        {"spectrum " + el_centro + " --fmin -1", 3, "--fmin: value -1 must be a finite number > 0"},
        {"spectrum " + el_centro + " --per-decade 0", 3,
         "--per-decade: 0; expected an integer in [1, 100000]"},
        {"spectrum " + el_centro + " --per-decade 2.5", 3,
         "--per-decade: 2.5; expected an integer"},
        {"spectrum " + el_centro + " --frequencies 1,2 --fmin 0.5", 2,
         "--frequencies and --fmin exclude each other"},
        {"spectrum " + el_centro + " --frequencies 2,1", 3, "--frequencies: 1 Hz follows 2 Hz"},
        {"spectrum tests/data/no_such.AT2", 5, "no_such.AT2: cannot open file for reading"},
        {"target", 2, "the option '--design' is required"},
        {"target --design rg1.70 --pga 0.3", 3, "--design: unknown design \"rg1.70\""},
        {"target --design rg1.60", 3, "--pga: required by design rg1.60"},
        {"target --design rg1.60 --pga 0", 3, "--pga: value 0 must be a finite number > 0"},
        {"target --design rg1.60 --pga 0.3 --damping 0.2", 3,
         "--damping: value 0.2 is out of range; expected [0.005, 0.1]"},
        {"target --design rg1.60 --pga 0.3 --sds 1", 3, "--sds: does not apply to design rg1.60"},
        {"target --design asce7 --sds 1 --sd1 0.6 --tl 8 --vertical", 3,
         "--vertical: does not apply to design asce7"},
        {"target --design asce7 --sds 1 --sd1 0.6", 3, "--tl: required by design asce7"},
        {"target --design asce7 --sds 1 --sd1 0.6 --tl 8 --damping 0.1", 3,
         "--damping: design asce7 is defined at 5% only; expected 0.05"},
        {"target --design asce7 --sds 1 --sd1 0.6 --tl 0.3", 3, "--tl: 0.3 s; expected more than TS = SD1/SDS = 0.6 s"},
        {"target --design ec8 --ag 0.3 --type 3 --ground A", 3, "--type: \"3\"; expected 1 or 2"},
        {"target --design ec8 --ag 0.3 --type 1 --ground F", 3,
         "--ground: \"F\"; expected A, B, C, D or E"},
        {"target --design is1893 --pga 0.3 --soil clay", 3,
         "--soil: \"clay\"; expected rock, medium or soft"},
        {"target --design ec8 --ag 0.3 --ground A", 3, "--type: required by design ec8; expected 1 or 2"},
        {"target --design rg1.60 --pga 0.3 --damping 0.05,0.1 --output x.csv", 2,
         "--output writes one spectrum"},
    };
    for (const auto& c : cases) {
        INFO(c.args);
        const auto r = run_cli(c.args);
        CHECK(r.exit_code == c.code);
        CHECK(r.out.empty());
        CHECK_THAT(r.err, Catch::Contains(c.message));
    }
}

TEST_CASE("spectrum on a bad record exits 3 naming file, line and what was expected",
          "[spectra][cli]") {
    // Each bad-input case is a clear error with a non-zero exit code through the CLI,
    // not only in the reader (the reader tests in tests/core check the same cases in detail).
    const fs::path dir = fs::temp_directory_path() / "freestand_cli_bad_records";
    fs::create_directories(dir);
    const auto write = [&](const std::string& name, const std::string& text) {
        std::ofstream(dir / name, std::ios::binary) << text;
        return (dir / name).string();
    };
    std::string at2 = "PEER header\nevent\nACCELERATION TIME SERIES IN UNITS OF G\n"
                      "NPTS=    5, DT=   .0100 SEC\n  0.1 0.2 0.3\n";
    struct Case {
        std::string file;
        const char* message;
    };
    const Case cases[] = {
        {write("empty.csv", ""), "empty.csv:1: empty file; expected a header"},
        {write("malformed.csv", "time_s,accel_g\n0,0.1\n0.01,0.2;x\n"),
         "malformed.csv:3: column 2 (accel_g): expected a number; got \"0.2;x\""},
        {write("nonuniform.csv", "time_s,accel_g\n0,0.1\n0.01,0.2\n0.03,0.1\n"),
         "nonuniform.csv:4: column 1 (time_s): non-uniform time step"},
        {write("nan.csv", "time_s,accel_g\n0,0.1\n0.01,nan\n"),
         "nan.csv:3: column 2 (accel_g): value \"nan\" is not finite; expected a finite number"},
        {write("inf.csv", "time_s,accel_g\n0,0.1\n0.01,-inf\n"),
         "inf.csv:3: column 2 (accel_g): value \"-inf\" is not finite"},
        {write("nounit.csv", "time_s,accel\n0,0.1\n0.01,0.2\n"),
         "nounit.csv:1: header: column \"accel\" has no recognised unit"},
        {write("npts.AT2", at2), "npts.AT2:4: NPTS: header says NPTS= 5 but the file holds 3 values"},
    };
    for (const auto& c : cases) {
        INFO(c.file);
        const auto r = run_cli("spectrum '" + c.file + "' --json");
        CHECK(r.exit_code == 3);
        CHECK(r.out.empty());
        CHECK_THAT(r.err, Catch::Contains(std::string("freestand spectrum: error: ") +
                                          (dir / "").string()));
        CHECK_THAT(r.err, Catch::Contains(c.message));
    }
}

TEST_CASE("spectrum and target print help and exit 0", "[spectra][cli]") {
    for (const char* cmd : {"spectrum", "target"}) {
        const auto r = run_cli(std::string(cmd) + " --help");
        CHECK(r.exit_code == 0);
        CHECK_THAT(r.out, Catch::Contains(std::string("usage: freestand ") + cmd));
        CHECK_THAT(r.out, Catch::Contains("--damping"));
    }
}

}  // namespace freestand_test_spectra_test_cli_spectra
