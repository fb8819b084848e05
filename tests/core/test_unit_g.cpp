// The unit g of the readers and measures is the caller's (a case's site.g_mps2; docs/methods.md,
// Conventions): values in g are multiplied by it, values in m/s^2 and cm/s^2 are not.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "core/file_io.hpp"
#include "core/measures.hpp"
#include "core/readers.hpp"
#include "support/paths.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_core_test_unit_g {

namespace fs = std::filesystem;
using namespace freestand;

namespace {
// Standard gravity, exactly (the default unit g is the thesis's 9.81).
constexpr double standard_g_mps2 = 9.80665;

// The replacement of `from` (present exactly once) by `to` in text.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const std::size_t pos = text.find(from);
    REQUIRE(pos != std::string::npos);
    REQUIRE(text.find(from, pos + 1) == std::string::npos);
    return text.replace(pos, from.size(), to);
}
}  // namespace

TEST_CASE("records in g are read in the caller's unit g", "[core][readers][gravity]") {
    const std::string at2 =
        "PEER NGA STRONG MOTION DATABASE RECORD\nTest, 1/1/2000, X\n"
        "ACCELERATION TIME SERIES IN UNITS OF G\nNPTS=  3, DT= .0100 SEC\n 0.1 -0.2\n 0.3\n";
    const core::Record a = core::parse_at2(at2, "g.AT2", standard_g_mps2);
    CHECK(a.accel_mps2[1] == -0.2 * standard_g_mps2);
    CHECK(core::parse_at2(at2, "g.AT2").accel_mps2[1] == -0.2 * 9.81);

    const std::string csv = "time_s,accel_g\n0,0.5\n0.01,-0.2\n";
    const core::Record c =
        core::parse_csv(csv, "g.csv", core::limits::max_samples, standard_g_mps2);
    CHECK(c.accel_mps2[0] == 0.5 * standard_g_mps2);
    CHECK(core::parse_csv(csv, "g.csv").accel_mps2[0] == 0.5 * 9.81);
    // A column in m/s^2 does not depend on the unit g.
    const std::string si = "time_s,accel_mps2\n0,0.5\n0.01,-0.2\n";
    CHECK(core::parse_csv(si, "si.csv", core::limits::max_samples, standard_g_mps2)
              .accel_mps2[0] == 0.5);

    // The COSMOS fixture (tests/data/cosmos_small.V2, cm/s/s) restated in g (code 2).
    const std::string fixture =
        core::read_text_file(fs::path(freestand::test::data_dir()) / "cosmos_small.V2");
    const std::string in_g =
        replaced(replaced(fixture, "units=cm/sec2 (04)", "units=g (02)"),
                 "       2       1       4     120", "       2       1       2     120");
    const core::Record v = core::parse_cosmos_v2(in_g, "g.V2", core::limits::max_cosmos_lines,
                                                 standard_g_mps2);
    CHECK(v.accel_mps2[1] == 1.5 * standard_g_mps2);
    // In cm/s/s it does not.
    CHECK(core::parse_cosmos_v2(fixture, "cm.V2", core::limits::max_cosmos_lines,
                                standard_g_mps2)
              .accel_mps2[1] == core::parse_cosmos_v2(fixture, "cm.V2").accel_mps2[1]);

    // read_record passes it to the reader its extension picks.
    const fs::path shipped = fs::path(freestand::test::data_dir()) / "RSN175_IMPVALL.H_H-E12140.AT2";
    // First value in the file: .3654112E-03 g.
    CHECK(core::read_record(shipped, standard_g_mps2).accel_mps2.front() ==
          Approx(0.3654112e-3 * standard_g_mps2).epsilon(1e-15));
}

TEST_CASE("PGA in g and the Arias intensity use the caller's gravity", "[core][measures][gravity]") {
    const core::Record r{"r", "s", "h1", 0.01, {0.0, 2.0, -4.0, 1.0, 0.0}};
    const core::GroundMotion thesis = core::measure(r);
    const core::GroundMotion standard = core::measure(r, standard_g_mps2);
    CHECK(standard.pga_g == 4.0 / standard_g_mps2);
    CHECK(thesis.pga_g == 4.0 / 9.81);
    // I_a = pi / (2 g) integral a^2 dt (Arias 1970): trapezoids of a^2 over 0.01 s.
    const double integral = 0.01 * (0.0 + 4.0) / 2.0 + 0.01 * (4.0 + 16.0) / 2.0 +
                            0.01 * (16.0 + 1.0) / 2.0 + 0.01 * (1.0 + 0.0) / 2.0;
    CHECK(standard.arias_mps ==
          Approx(3.141592653589793 / (2.0 * standard_g_mps2) * integral).epsilon(1e-14));
    // Velocities and displacements do not depend on it.
    CHECK(standard.pgv_mps == thesis.pgv_mps);
    CHECK(standard.pgd_m == thesis.pgd_m);
}

}  // namespace freestand_test_core_test_unit_g
