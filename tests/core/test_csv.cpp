#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>

#include "support/paths.hpp"
#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/printable.hpp"
#include "core/readers.hpp"
#include "core/units.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_core_test_csv {

namespace fs = std::filesystem;
using namespace freestand;
using Catch::Contains;

namespace {
fs::path write_temp(const std::string& name, const std::string& text) {
    const fs::path p = fs::temp_directory_path() / ("freestand_csv_" + name);
    std::ofstream(p, std::ios::binary) << text;
    return p;
}
}  // namespace

TEST_CASE("CSV reader reads two columns in g", "[core][csv]") {
    const auto p = write_temp("two.csv", "# a comment\ntime_s,accel_g\n0,0.1\n0.01,-0.2\n\n0.02,0.3\n# trailing\n");
    const auto rec = core::read_csv(p);
    REQUIRE(rec.size() == 3);
    CHECK(rec.dt_s == Approx(0.01).epsilon(1e-15));
    CHECK(rec.accel_mps2[1] == Approx(-0.2 * units::g_mps2).epsilon(1e-15));
    CHECK(rec.name == "freestand_csv_two");
    CHECK(rec.source == p.string());
}

TEST_CASE("CSV reader reads one column with a dt_s comment, CRLF and every unit", "[core][csv]") {
    const auto p = write_temp("one.csv", "# dt_s: 0.02\r\naccel_cmps2\r\n1\r\n-2.5\r\n");
    const auto rec = core::read_csv(p);
    REQUIRE(rec.size() == 2);
    CHECK(rec.dt_s == 0.02);
    CHECK(rec.accel_mps2[1] == Approx(-0.025).epsilon(1e-15));
    const auto q = write_temp("mps2.csv", "# dt_s: 0.005\n# component: v\naccel_mps2\n 3.5 \n");
    const auto rq = core::read_csv(q);
    CHECK(rq.accel_mps2[0] == 3.5);
    CHECK(rq.component == "v");
}

TEST_CASE("CSV reader accepts time jitter within 1e-6 of dt", "[core][csv]") {
    const auto p = write_temp("jitter.csv", "time_s,accel_g\n0,0\n0.01,0\n0.020000000005,0\n0.03,0\n");
    CHECK(core::read_csv(p).dt_s == Approx(0.01).epsilon(1e-12));
}

TEST_CASE("CSV reader rejects a malformed line naming line and column", "[core][csv]") {
    const auto p = write_temp("bad.csv", "time_s,accel_g\n0,0.1\n0.01,abc\n");
    CHECK_THROWS_AS(core::read_csv(p), InputError);
    CHECK_THROWS_WITH(core::read_csv(p),
                      Contains("freestand_csv_bad.csv:3: column 2 (accel_g): expected a number; got \"abc\""));
    const auto q = write_temp("cols.csv", "time_s,accel_g\n0,0.1\n0.01,0.2,7\n");
    CHECK_THROWS_WITH(core::read_csv(q),
                      Contains(":3: expected 2 comma-separated column(s) as in the header at line 1; got 3"));
    const auto r = write_temp("badtime.csv", "time_s,accel_g\n0,0.1\nx,0.2\n");
    CHECK_THROWS_WITH(core::read_csv(r), Contains(":3: column 1 (time_s): expected a number; got \"x\""));
}

TEST_CASE("CSV reader rejects a non-uniform time step naming both steps", "[core][csv]") {
    const auto p = write_temp("step.csv", "time_s,accel_g\n0,0\n0.01,0\n0.02,0\n0.0325,0\n");
    CHECK_THROWS_AS(core::read_csv(p), InputError);
    CHECK_THROWS_WITH(core::read_csv(p), Contains(":5: column 1 (time_s): non-uniform time step: 0.0125"));
    CHECK_THROWS_WITH(core::read_csv(p), Contains("s here but 0.01 s at line 3"));
    const auto q = write_temp("back.csv", "time_s,accel_g\n0.01,0\n0.01,0\n");
    CHECK_THROWS_WITH(core::read_csv(q), Contains(":3: column 1 (time_s): time 0.01 s does not increase after 0.01 s"));
}

TEST_CASE("CSV reader rejects NaN and infinity", "[core][csv]") {
    const auto p = write_temp("nan.csv", "time_s,accel_g\n0,0.1\n0.01,nan\n");
    CHECK_THROWS_AS(core::read_csv(p), InputError);
    CHECK_THROWS_WITH(core::read_csv(p), Contains(":3: column 2 (accel_g): value \"nan\" is not finite"));
    const auto q = write_temp("inf.csv", "# dt_s: 0.01\naccel_mps2\n1\n-inf\n");
    CHECK_THROWS_WITH(core::read_csv(q), Contains(":4: column 1 (accel_mps2): value \"-inf\" is not finite"));
    const auto r = write_temp("inft.csv", "time_s,accel_g\n0,0.1\ninf,0.2\n");
    CHECK_THROWS_WITH(core::read_csv(r), Contains(":3: column 1 (time_s): value \"inf\" is not finite"));
}

TEST_CASE("CSV reader rejects an empty file and a file without rows", "[core][csv]") {
    CHECK_THROWS_AS(core::read_csv(write_temp("empty.csv", "")), InputError);
    CHECK_THROWS_WITH(core::read_csv(write_temp("empty.csv", "")), Contains("freestand_csv_empty.csv:1: empty file"));
    CHECK_THROWS_WITH(core::read_csv(write_temp("comments.csv", "# only\n# comments\n")),
                      Contains(":2: empty file; expected a header"));
    CHECK_THROWS_WITH(core::read_csv(write_temp("norows.csv", "# x\ntime_s,accel_g\n")),
                      Contains(":2: no data rows after the header"));
    CHECK_THROWS_WITH(core::read_csv(write_temp("onerow.csv", "time_s,accel_g\n0,1\n")),
                      Contains(":2: time_s: a single row gives no time step"));
}

TEST_CASE("CSV reader requires a unit in the header", "[core][csv]") {
    const auto p = write_temp("nounit.csv", "time_s,accel\n0,0.1\n0.01,0.2\n");
    CHECK_THROWS_AS(core::read_csv(p), InputError);
    CHECK_THROWS_WITH(core::read_csv(p), Contains(":1: header: column \"accel\" has no recognised unit; expected an "
                                                  "acceleration in g, m/s2 (also mps2, ms-2) or cm/s2 (also cmps2, "
                                                  "cms-2, gal) (accepted names: time: time or t"));
    const auto q = write_temp("ft.csv", "# dt_s: 0.01\naccel_ftps2\n1\n");
    CHECK_THROWS_WITH(core::read_csv(q), Contains(":2: header: column \"accel_ftps2\" has no recognised unit"));
    const auto r = write_temp("three.csv", "time_s,accel_g,accel_mps2\n0,1,2\n");
    CHECK_THROWS_WITH(core::read_csv(r), Contains(":1: header: expected \"time_s,accel_<unit>\" or \"accel_<unit>\" "
                                                  "(a time and an acceleration column, or one acceleration column); "
                                                  "got 3 columns in \"time_s,accel_g,accel_mps2\""));
}

TEST_CASE("CSV reader reads the usual spellings of the column names with their units", "[core][csv]") {
    struct Spelling {
        const char* header;
        double accel_to_mps2;
        double time_to_s;
    };
    const Spelling spellings[] = {
        {"time_s,accel_g", units::g_mps2, 1.0},
        {"time_s,acceleration_g", units::g_mps2, 1.0},
        {"t_s,acc_g", units::g_mps2, 1.0},
        {"Time (s),Accel (g)", units::g_mps2, 1.0},
        {"time,a_g", units::g_mps2, 1.0},
        {"T,ACCELERATION (G)", units::g_mps2, 1.0},
        {"time [s],acceleration [g]", units::g_mps2, 1.0},
        {"time sec,accel g", units::g_mps2, 1.0},
        {" \"time_s\" , \"accel_g\" ", units::g_mps2, 1.0},
        {"time_s,a_mps2", 1.0, 1.0},
        {"time_s,acc_m/s2", 1.0, 1.0},
        {"time (s),acceleration (m/s^2)", 1.0, 1.0},
        {"time (s),acceleration (m / s ^ 2)", 1.0, 1.0},
        {"time (s),acceleration (m/s\xC2\xB2)", 1.0, 1.0},
        {"time (s),accel [ms-2]", 1.0, 1.0},
        {"time_s,accel_cm/s2", units::cm_to_m, 1.0},
        {"time_s,accel_cmps2", units::cm_to_m, 1.0},
        {"time_s,acc (gal)", units::cm_to_m, 1.0},
        {"time_s,a_Gal", units::cm_to_m, 1.0},
        {"time_ms,accel_g", units::g_mps2, 1e-3},
        {"t (ms),accel_g", units::g_mps2, 1e-3},
    };
    for (const Spelling& s : spellings) {
        INFO(s.header);
        const double step = 0.01 / s.time_to_s;
        const auto p = write_temp("spelling.csv", fmt::format("{}\n0,0.5\n{},-1.5\n{},2\n", s.header, step, 2 * step));
        const auto rec = core::read_csv(p);
        REQUIRE(rec.size() == 3);
        CHECK(rec.dt_s == Approx(0.01).epsilon(1e-12));
        CHECK(rec.accel_mps2[1] == Approx(-1.5 * s.accel_to_mps2).epsilon(1e-15));
    }
}

TEST_CASE("CSV reader takes the columns in either order", "[core][csv]") {
    const auto rec = core::read_csv(write_temp("swapped.csv", "acc (g),t (s)\n0.5,0\n-1.5,0.02\n2,0.04\n"));
    REQUIRE(rec.size() == 3);
    CHECK(rec.dt_s == Approx(0.02).epsilon(1e-12));
    CHECK(rec.accel_mps2[1] == Approx(-1.5 * units::g_mps2).epsilon(1e-15));
    const auto p = write_temp("swapbad.csv", "acc (g),t (s)\n0.5,0\n-1.5,0.02\n2,0.05\n");
    CHECK_THROWS_WITH(core::read_csv(p), Contains(":4: column 2 (t (s)): non-uniform time step"));
}

TEST_CASE("CSV reader accepts a BOM, CRLF, semicolon and tab separators and a decimal comma after semicolon", "[core][csv]") {
    const auto bom = core::read_csv(write_temp("bom.csv", "\xEF\xBB\xBFtime_s,accel_g\r\n0,0.1\r\n0.01,0.2\r\n"));
    CHECK(bom.size() == 2);
    CHECK(bom.accel_mps2[1] == Approx(0.2 * units::g_mps2).epsilon(1e-15));
    const auto semi = core::read_csv(write_temp("semi.csv", "\xEF\xBB\xBFTime (s);Acc (m/s2)\r\n0;0,25\r\n0,01;-1,5\r\n"
                                                            "0,02;2\r\n"));
    REQUIRE(semi.size() == 3);
    CHECK(semi.dt_s == Approx(0.01).epsilon(1e-12));
    CHECK(semi.accel_mps2[0] == 0.25);
    CHECK(semi.accel_mps2[1] == -1.5);
    const auto semi_point = core::read_csv(write_temp("semipoint.csv", "time_s ; accel_g\n0 ; 0.5\n0.01 ; 1\n"));
    CHECK(semi_point.accel_mps2[0] == Approx(0.5 * units::g_mps2).epsilon(1e-15));
    const auto tab = core::read_csv(write_temp("tab.csv", "time_s\taccel_mps2\n0\t1\n0.01\t2,5\n"));
    CHECK(tab.accel_mps2[1] == 2.5);
}

TEST_CASE("CSV reader names the header and lists the accepted names for an unknown column", "[core][csv]") {
    const auto p = write_temp("german.csv", "# from a logger\nZeit (s);Beschleunigung (g)\n0;0,1\n");
    CHECK_THROWS_AS(core::read_csv(p), InputError);
    CHECK_THROWS_WITH(core::read_csv(p),
                      Contains("freestand_csv_german.csv:2: header: column 1 \"Zeit (s)\" of \"Zeit (s);Beschleunigung "
                               "(g)\" is not a recognised name; accepted names: time: time or t, in s (also sec; s when "
                               "no unit is written) or ms; acceleration: acceleration, accel, acc or a, in g, m/s2 (also "
                               "mps2, ms-2) or cm/s2 (also cmps2, cms-2, gal); the unit follows '_' or a space or stands "
                               "in (...) or [...], as in time_s, t (s), accel_g, acc (m/s^2), a [gal]; case, blanks and "
                               "'^' are ignored"));
    const auto q = write_temp("minutes.csv", "time_min,accel_g\n0,0.1\n");
    CHECK_THROWS_WITH(core::read_csv(q), Contains(":1: header: column \"time_min\" has no recognised unit; expected a "
                                                  "time in s (also sec; s when no unit is written) or ms (accepted"));
    const auto r = write_temp("accel_ms.csv", "time_s,accel_ms\n0,0.1\n");
    CHECK_THROWS_WITH(core::read_csv(r), Contains(":1: header: column \"accel_ms\" has no recognised unit"));
}

TEST_CASE("CSV reader requires one time and one acceleration column", "[core][csv]") {
    const auto p = write_temp("twotimes.csv", "time_s,t (ms)\n0,0\n");
    CHECK_THROWS_AS(core::read_csv(p), InputError);
    CHECK_THROWS_WITH(core::read_csv(p), Contains(":1: header: two time columns in \"time_s,t (ms)\"; expected one time "
                                                  "and one acceleration column"));
    const auto q = write_temp("twoaccels.csv", "accel_g;acc_gal\n0;0\n");
    CHECK_THROWS_WITH(core::read_csv(q), Contains(":1: header: two acceleration columns in \"accel_g;acc_gal\""));
    const auto r = write_temp("timeonly.csv", "# dt_s: 0.01\ntime_s\n0\n");
    CHECK_THROWS_WITH(core::read_csv(r), Contains(":2: header: no acceleration column in \"time_s\"; expected "
                                                  "\"time_s,accel_<unit>\" or \"accel_<unit>\""));
}

TEST_CASE("CSV reader keeps to the header's separator", "[core][csv]") {
    // A decimal comma is read only where ',' cannot be the separator.
    const auto p = write_temp("commadecimal.csv", "time_s,accel_g\n0,0,1\n");
    CHECK_THROWS_WITH(core::read_csv(p), Contains(":2: expected 2 comma-separated column(s) as in the header at line 1; "
                                                  "got 3"));
    const auto q = write_temp("semirow.csv", "time_s;accel_g\n0;0.1\n0.01,0.2\n");
    CHECK_THROWS_WITH(core::read_csv(q), Contains(":3: expected 2 semicolon-separated column(s) as in the header at "
                                                  "line 1; got 1"));
    const auto r = write_temp("twocommas.csv", "time_s;accel_g\n0;1,000,5\n");
    CHECK_THROWS_WITH(core::read_csv(r), Contains(":2: column 2 (accel_g): expected a number; got \"1,000,5\""));
}
TEST_CASE("CSV reader requires dt for one column and checks it", "[core][csv]") {
    const auto p = write_temp("nodt.csv", "accel_g\n0.1\n0.2\n");
    CHECK_THROWS_AS(core::read_csv(p), InputError);
    CHECK_THROWS_WITH(core::read_csv(p), Contains(":1: dt_s: one-column file without a time step; expected a "
                                                  "\"# dt_s: <value>\" line before the header"));
    const auto q = write_temp("negdt.csv", "# dt_s: -1\naccel_g\n0.1\n");
    CHECK_THROWS_WITH(core::read_csv(q), Contains(":1: dt_s: expected a time step > 0 s; got \"-1\""));
    const auto r = write_temp("dtdisagree.csv", "# dt_s: 0.02\ntime_s,accel_g\n0,0\n0.01,0\n");
    CHECK_THROWS_WITH(core::read_csv(r), Contains(":1: dt_s: comment says dt_s 0.02 but the time column steps by 0.01 s"));
}

TEST_CASE("read_record picks the reader from the extension", "[core][records]") {
    const fs::path data(freestand::test::data_dir());
    // NPTS= 7810 in the file header (shared/records/README.md says 7814; the file is right).
    CHECK(core::read_record(data / "RSN175_IMPVALL.H_H-E12230.AT2").size() == 7810);
    CHECK(core::read_record(data / "cosmos_small.V2").size() == 20);
    CHECK(core::read_record(write_temp("upper.CSV", "# dt_s: 0.01\naccel_g\n1\n")).size() == 1);
    const auto p = write_temp("rec.txt", "time_s,accel_g\n0,1\n0.01,2\n");
    CHECK_THROWS_AS(core::read_record(p), InputError);
    CHECK_THROWS_WITH(core::read_record(p), Contains("freestand_csv_rec.txt: extension: unknown record format \".txt\"; "
                                                     "expected .AT2 (PEER NGA), .V2 (COSMOS) or .csv"));
}

TEST_CASE("write_csv_g round-trips values to 1e-12 and keeps the labels", "[core][csv]") {
    core::Record rec;
    rec.name = "roundtrip";
    rec.source = "generated\nin a test";  // a line break must not break the comment line
    rec.component = "h1";
    rec.dt_s = 0.005;
    std::mt19937_64 gen(20261121);
    for (int i = 0; i < 2000; ++i) {
        // Mantissas from the raw 64-bit draws (std:: distributions are not portable), scaled
        // over eight decades so short and long decimal forms both occur.
        const double u = static_cast<double>(gen() >> 11) * 0x1.0p-53;
        rec.accel_mps2.push_back((u - 0.5) * std::pow(10.0, i % 8 - 4));
    }
    rec.accel_mps2[0] = 1.0 / 3.0;
    const fs::path out = fs::temp_directory_path() / "freestand_csv_out" / "rt.csv";
    core::write_csv_g(rec, out);
    CHECK_FALSE(fs::exists(out.string() + ".tmp"));
    const std::string text = core::read_text_file(out);
    CHECK(text.rfind("# name: roundtrip\n# source: generated in a test\n# component: h1\n# dt_s: 0.005\n"
                     "time_s,accel_g\n0,", 0) == 0);
    const auto back = core::read_csv(out);
    CHECK(back.name == "roundtrip");
    CHECK(back.component == "h1");
    CHECK(back.dt_s == Approx(rec.dt_s).epsilon(1e-12));
    REQUIRE(back.size() == rec.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < rec.size(); ++i)
        worst = std::max(worst, std::abs(back.accel_mps2[i] - rec.accel_mps2[i]) / std::abs(rec.accel_mps2[i]));
    CHECK(worst <= 1e-12);
}

TEST_CASE("write_csv_g shows control characters in its labels as hexadecimal escapes", "[core][csv][hardening]") {
    // write_csv_g (generate's h1/h2/v.csv) must not copy a label's ESC, BEL or DEL (a seed
    // record's file name is in its source) raw into its comment lines.
    core::Record rec;
    rec.name = "a\x1b]0;pwned\x07" "b";
    rec.source = "x\x7f" "y";  // DEL
    rec.component = "h1";
    rec.dt_s = 0.01;
    rec.accel_mps2 = {0.0, 1.0};
    const fs::path out = fs::temp_directory_path() / "freestand_csv_out" / "ctl.csv";
    core::write_csv_g(rec, out);
    const std::string text = core::read_text_file(out);
    CHECK(text.rfind("# name: a\\x1B]0;pwned\\x07b\n# source: x\\x7Fy\n# component: h1\n", 0) == 0);
    for (char c : text) CHECK_FALSE((c != '\n' && core::is_control(c)));
}

TEST_CASE("write_csv_g refuses an invalid record", "[core][csv]") {
    core::Record rec;
    rec.source = "bad-record";
    rec.dt_s = 0.01;
    rec.accel_mps2 = {0.0, std::nan("")};
    const fs::path out = fs::temp_directory_path() / "freestand_csv_refused.csv";
    fs::remove(out);
    CHECK_THROWS_AS(core::write_csv_g(rec, out), InputError);
    CHECK_THROWS_WITH(core::write_csv_g(rec, out), Contains("bad-record: sample 1 is not a finite number"));
    CHECK_FALSE(fs::exists(out));
}

}  // namespace freestand_test_core_test_csv
