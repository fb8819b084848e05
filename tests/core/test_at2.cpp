#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "support/paths.hpp"
#include "core/errors.hpp"
#include "core/readers.hpp"
#include "core/units.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_core_test_at2 {

namespace fs = std::filesystem;
using namespace freestand;

namespace {
fs::path write_temp(const std::string& name, const std::string& text) {
    const fs::path p = fs::temp_directory_path() / ("freestand_test_" + name);
    std::ofstream(p) << text;
    return p;
}
const std::string header =
    "PEER NGA STRONG MOTION DATABASE RECORD\nTest, 1/1/2000, X\n"
    "ACCELERATION TIME SERIES IN UNITS OF G\n";
}  // namespace

TEST_CASE("AT2 reader reads the shipped El Centro #12 record", "[core][at2]") {
    const auto rec = core::read_at2(fs::path(freestand::test::data_dir()) / "RSN175_IMPVALL.H_H-E12140.AT2");
    CHECK(rec.size() == 7814);
    CHECK(rec.dt_s == Approx(0.005));
    // First value in the file: .3654112E-03 g.
    CHECK(rec.accel_mps2.front() == Approx(0.3654112e-3 * units::g_mps2));
    CHECK(rec.name == "RSN175_IMPVALL.H_H-E12140");
}

TEST_CASE("AT2 reader accepts a small well-formed file", "[core][at2]") {
    const auto p = write_temp("ok.AT2", header + "NPTS=  3, DT= .0100 SEC\n 0.1 -0.2\n 0.3\n");
    const auto rec = core::read_at2(p);
    REQUIRE(rec.size() == 3);
    CHECK(rec.accel_mps2[1] == Approx(-0.2 * 9.81));
}

TEST_CASE("AT2 reader rejects NPTS that disagrees with the data", "[core][at2]") {
    const auto p = write_temp("npts.AT2", header + "NPTS=  4, DT= .0100 SEC\n 0.1 -0.2\n 0.3\n");
    CHECK_THROWS_WITH(core::read_at2(p), Catch::Contains(":4: NPTS: header says NPTS= 4 but the file holds 3"));
}

TEST_CASE("AT2 reader rejects a malformed value naming its line", "[core][at2]") {
    const auto p = write_temp("bad.AT2", header + "NPTS=  3, DT= .0100 SEC\n 0.1 -0.2\n 0.3x\n");
    CHECK_THROWS_WITH(core::read_at2(p), Catch::Contains(":6: acceleration: expected a number in g; got \"0.3x\""));
}

TEST_CASE("AT2 reader rejects NaN and infinity", "[core][at2]") {
    const auto p = write_temp("nan.AT2", header + "NPTS=  2, DT= .0100 SEC\n 0.1 nan\n");
    CHECK_THROWS_AS(core::read_at2(p), InputError);
    CHECK_THROWS_WITH(core::read_at2(p), Catch::Contains("nan.AT2:5: acceleration"));
    const auto q = write_temp("inf.AT2", header + "NPTS=  2, DT= .0100 SEC\n inf 0.1\n");
    CHECK_THROWS_WITH(core::read_at2(q), Catch::Contains(":5: acceleration"));
}

TEST_CASE("AT2 reader requires the units line", "[core][at2]") {
    const auto p = write_temp("units.AT2", "PEER\nTest\nACCELERATION TIME SERIES\nNPTS=  1, DT= .01 SEC\n 0.1\n");
    CHECK_THROWS_WITH(core::read_at2(p), Catch::Contains(":3: units: expected the AT2 units line"));
}

TEST_CASE("AT2 reader rejects an empty file and a missing DT", "[core][at2]") {
    CHECK_THROWS_WITH(core::read_at2(write_temp("empty.AT2", "")), Catch::Contains(":1: file ends inside"));
    const auto p = write_temp("nodt.AT2", header + "NPTS=  1\n 0.1\n");
    CHECK_THROWS_WITH(core::read_at2(p), Catch::Contains(":4: NPTS/DT"));
    const auto q = write_temp("nodata.AT2", header + "NPTS=  1, DT= .01 SEC\n");
    CHECK_THROWS_WITH(core::read_at2(q), Catch::Contains("no acceleration values"));
}

TEST_CASE("AT2 reader reports a missing file as an I/O error", "[core][at2]") {
    CHECK_THROWS_AS(core::read_at2("/nonexistent/x.AT2"), IoError);
}

TEST_CASE("AT2 reader rejects an absurd NPTS as an input error", "[core][at2]") {
    const auto p = write_temp("hugenpts.AT2", header + "NPTS=  99999999999999999999, DT= .0100 SEC\n 0.1\n");
    CHECK_THROWS_WITH(core::read_at2(p), Catch::Contains(":4: NPTS: expected a point count between 1 and 1e+07 (README, Limits)"));
}

TEST_CASE("AT2 reader refuses an overlong header line instead of overflowing the stack",
          "[core][at2][hardening]") {
    // NPTS= with 50,000 digits would overflow the header pattern's recursion (exit 139).
    const auto p = write_temp("long.AT2", header + "NPTS= " + std::string(50000, '1') +
                                              ", DT= .0100 SEC\n 0.1 -0.2\n 0.3\n");
    try {
        core::read_record(p);
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(std::string(e.what()).find(":4: line is 50021 characters long") != std::string::npos);
    }
}

}  // namespace freestand_test_core_test_at2
