#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "support/paths.hpp"
#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/readers.hpp"
#include "core/units.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_core_test_cosmos {

namespace fs = std::filesystem;
using namespace freestand;
using Catch::Contains;

// tests/data/cosmos_small.V2 is a hand-written COSMOS v1.20 processed record (its comment lines
// say so): 13 text lines, integer header on lines 14-24, real header on 25-42, comments 43-45,
// data header on line 46, data on lines 47-49, 20 values in cm/s/s at dt = 10 ms (real #62).

namespace {

const fs::path fixture = fs::path(freestand::test::data_dir()) / "cosmos_small.V2";

/// The fixture with `from` replaced (exactly once) by `to`, written to a temporary file.
fs::path variant(const std::string& name, const std::string& from, const std::string& to) {
    std::string text = core::read_text_file(fixture);
    const std::size_t pos = text.find(from);
    REQUIRE(pos != std::string::npos);
    REQUIRE(text.find(from, pos + 1) == std::string::npos);
    text.replace(pos, from.size(), to);
    const fs::path p = fs::temp_directory_path() / ("freestand_cosmos_" + name + ".V2");
    std::ofstream(p) << text;
    return p;
}

const std::string dt_ms_field = "    10.000000";    // real #62
const std::string dt_raw_field = "     0.010000";   // real #34
const std::string unknown_real = "  -999.000000";
const std::string units_code_line = "       2       1       4     120";  // integer #1-#4

}  // namespace

TEST_CASE("COSMOS V2 reader reads the hand-written fixture", "[core][cosmos]") {
    const auto rec = core::read_cosmos_v2(fixture);
    REQUIRE(rec.size() == 20);
    CHECK(rec.dt_s == Approx(0.010).epsilon(1e-15));
    CHECK(rec.name == "cosmos_small");
    CHECK(rec.component == "Sta Chan   1: 90 deg (Rcrdr Chan  1) Location:");
    CHECK(rec.accel_mps2[1] == Approx(1.5 * units::cm_to_m).epsilon(1e-15));
    // Line 48 field 5 touches field 4 ("-11.00000-123.45678"): cut by width, not by blanks.
    CHECK(rec.accel_mps2[11] == Approx(-11.0 * units::cm_to_m).epsilon(1e-15));
    CHECK(rec.accel_mps2[12] == Approx(-123.45678 * units::cm_to_m).epsilon(1e-15));
    CHECK(rec.accel_mps2.back() == 0.0);
}

TEST_CASE("COSMOS V2 reader converts g and falls back to real #34 for dt", "[core][cosmos]") {
    auto p = variant("g", "units=cm/sec2 (04)", "units=g (02)");
    std::string text = core::read_text_file(p);
    text.replace(text.find(units_code_line), units_code_line.size(), "       2       1       2     120");
    std::ofstream(p) << text;
    const auto in_g = core::read_cosmos_v2(p);
    CHECK(in_g.accel_mps2[1] == Approx(1.5 * units::g_mps2).epsilon(1e-15));

    const auto q = variant("dt34", "-999.000000" + dt_ms_field, "-999.000000" + unknown_real);
    std::string text_q = core::read_text_file(q);
    text_q.replace(text_q.find(dt_raw_field), dt_raw_field.size(), "     0.020000");
    std::ofstream(q) << text_q;
    CHECK(core::read_cosmos_v2(q).dt_s == Approx(0.020).epsilon(1e-15));
}

TEST_CASE("COSMOS V2 reader rejects a malformed value naming line and field", "[core][cosmos]") {
    const auto p = variant("bad", "   9.75000", "   9.7500x");
    CHECK_THROWS_AS(core::read_cosmos_v2(p), InputError);
    CHECK_THROWS_WITH(core::read_cosmos_v2(p),
                      Contains("cosmos_bad.V2:48: acceleration: field 2 (columns 11-20, Format=(8F10.5)): "
                               "expected a number; got \"9.7500x\""));
}

TEST_CASE("COSMOS V2 reader rejects NaN and infinity", "[core][cosmos]") {
    const auto p = variant("nan", "  14.00000", "       nan");
    CHECK_THROWS_AS(core::read_cosmos_v2(p), InputError);
    CHECK_THROWS_WITH(core::read_cosmos_v2(p), Contains(":48: acceleration: field 8: value \"nan\" is not finite"));
    const auto q = variant("inf", "  16.50000", "      -inf");
    CHECK_THROWS_WITH(core::read_cosmos_v2(q), Contains(":49: acceleration: field 2: value \"-inf\" is not finite"));
}

TEST_CASE("COSMOS V2 reader rejects a point count that disagrees with the data", "[core][cosmos]") {
    const auto p = variant("npts", "      20 acceleration pts", "      21 acceleration pts");
    CHECK_THROWS_AS(core::read_cosmos_v2(p), InputError);
    CHECK_THROWS_WITH(core::read_cosmos_v2(p),
                      Contains(":46: NPTS: data header says 21 acceleration pts but the data block holds 20 values"));
}

TEST_CASE("COSMOS V2 reader stops reading at NPTS and at its line limit", "[core][cosmos]") {
    // Line 47 holds values 1-8, line 48 values 9-16: the reader stops at line 48, not at the
    // end of the block.
    const auto p = variant("npts_short", "      20 acceleration pts", "       9 acceleration pts");
    CHECK_THROWS_WITH(core::read_cosmos_v2(p),
                      Contains(":46: NPTS: data header says 9 acceleration pts but the data block "
                               "holds more (line 48 reaches 16)"));
    // A file of blank lines past the limit is refused at the first line beyond it.
    const std::string text = core::read_text_file(fixture) + std::string(1000, '\n');
    CHECK_NOTHROW(core::parse_cosmos_v2(text, "long.V2", 1050));
    CHECK_THROWS_WITH(core::parse_cosmos_v2(text, "long.V2", 60),
                      Contains("long.V2:61: more than 60 lines"));
}

TEST_CASE("COSMOS V2 reader rejects an empty and a truncated file", "[core][cosmos]") {
    const fs::path empty = fs::temp_directory_path() / "freestand_cosmos_empty.V2";
    std::ofstream(empty) << "";
    CHECK_THROWS_AS(core::read_cosmos_v2(empty), InputError);
    CHECK_THROWS_WITH(core::read_cosmos_v2(empty), Contains("freestand_cosmos_empty.V2:1: empty file"));
    std::string text = core::read_text_file(fixture);
    std::size_t cut = 0;
    for (int i = 0; i < 30; ++i) cut = text.find('\n', cut) + 1;  // keep lines 1-30
    const fs::path truncated = fs::temp_directory_path() / "freestand_cosmos_truncated.V2";
    std::ofstream(truncated) << text.substr(0, cut);
    CHECK_THROWS_WITH(core::read_cosmos_v2(truncated),
                      Contains(":31: file ends where a Real-header line was expected"));
}

TEST_CASE("COSMOS V2 reader requires a unit", "[core][cosmos]") {
    auto p = variant("nounit", "units=cm/sec2 (04), ", "");
    std::string text = core::read_text_file(p);
    text.replace(text.find(units_code_line), units_code_line.size(), "       2       1    -999     120");
    std::ofstream(p) << text;
    CHECK_THROWS_AS(core::read_cosmos_v2(p), InputError);
    CHECK_THROWS_WITH(core::read_cosmos_v2(p), Contains(":46: units: no unit given: expected \"units=cm/sec2 (04)\""));
}

TEST_CASE("COSMOS V2 reader rejects units that disagree or are unsupported", "[core][cosmos]") {
    const auto p = variant("units_mismatch", units_code_line, "       2       1       2     120");
    CHECK_THROWS_WITH(core::read_cosmos_v2(p),
                      Contains(":46: units: data header says \"cm/sec2 (04)\" but integer-header #3 says code 2 (g)"));
    const auto q = variant("units_counts", "units=cm/sec2 (04)", "units=counts (50)");
    CHECK_THROWS_WITH(core::read_cosmos_v2(q), Contains(":46: units: unsupported units \"counts (50)\""));
}

TEST_CASE("COSMOS V2 reader requires a time step", "[core][cosmos]") {
    auto p = variant("nodt", "-999.000000" + dt_ms_field, "-999.000000" + unknown_real);
    std::string text = core::read_text_file(p);
    text.replace(text.find(dt_raw_field), dt_raw_field.size(), unknown_real);
    std::ofstream(p) << text;
    CHECK_THROWS_AS(core::read_cosmos_v2(p), InputError);
    CHECK_THROWS_WITH(core::read_cosmos_v2(p), Contains(":25: dt: no time step: expected the sampling interval in "
                                                        "real-header #62 (ms) or #34 (s)"));
}

TEST_CASE("COSMOS V2 reader rejects a raw record and a non-COSMOS first line", "[core][cosmos]") {
    const auto p = variant("v1", "Corrected acceleration    (Format", "Uncorrected acceleration  (Format");
    CHECK_THROWS_WITH(core::read_cosmos_v2(p), Contains(":1: data type: expected a processed (V2) record"));
    const auto q = variant("noformat", "(Format v01.20 with 13 text lines)", "");
    CHECK_THROWS_WITH(core::read_cosmos_v2(q), Contains(":1: format: expected a COSMOS line 1"));
}

TEST_CASE("COSMOS V2 reader checks block counts and field widths", "[core][cosmos]") {
    const auto p = variant("realcount", " 100 Real-header values follow on 17 lines",
                           " 101 Real-header values follow on 17 lines");
    CHECK_THROWS_WITH(core::read_cosmos_v2(p),
                      Contains(":25: Real-header: header says 101 values on 17 lines but they hold 100"));
    const auto q = variant("wide", "   7.00781\n", "   7.00781   1.00000\n");
    CHECK_THROWS_WITH(core::read_cosmos_v2(q),
                      Contains(":47: acceleration: expected at most 8 fields of width 10 (Format=(8F10.5))"));
    const auto r = variant("nodata", "      20 acceleration pts", "      20 velocity pts");
    CHECK_THROWS_WITH(core::read_cosmos_v2(r), Contains(":46: data header: expected a line like"));
}

TEST_CASE("COSMOS V2 reader refuses overlong lines instead of overflowing the stack",
          "[core][cosmos][hardening]") {
    // A 50,000-blank data line and a 300,000-character units field would overflow std::regex,
    // which recurses per character; both are an error naming the line.
    std::string long_line(50000, ' ');
    long_line.append("\n      20 acceleration pts");
    const fs::path blanks = variant("long_blanks", "      20 acceleration pts", long_line);
    try {
        core::read_record(blanks);
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK_THAT(e.what(), Contains(":46: line is 50000 characters long"));
    }
    const fs::path units =
        variant("long_units", "units=cm/sec2 (04)", "units=" + std::string(300000, 'c'));
    try {
        core::read_record(units);
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK_THAT(e.what(), Contains("characters long; this record format has lines of about 80"));
    }
}

}  // namespace freestand_test_core_test_cosmos
