// What every text reader does with the bytes it is given: a UTF-8 BOM dropped, UTF-16 refused,
// control characters shown in messages rather than cutting them, a record's size bounded while
// it is read, and a record's time step stated once.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <string>

#include "core/csv_table.hpp"
#include "core/errors.hpp"
#include "core/readers.hpp"
#include "core/text_parse.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_core_test_text_input {

using namespace freestand;
using Catch::Contains;
using namespace std::string_literals;

namespace {

// The message of the InputError that f throws ("" when it throws none).
template <class F>
std::string input_error(F f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

std::string utf16le(const std::string& ascii) {
    std::string out = "\xFF\xFE";
    for (char c : ascii) {
        out += c;
        out += '\0';
    }
    return out;
}

}  // namespace

TEST_CASE("an error message shows a NUL of its field as a hexadecimal escape and keeps what follows",
          "[core][errors]") {
    const InputError direct({"list\0.csv"s, 2, "na\0me"s}, "bad \0 value, expected a name"s);
    CHECK(std::string(direct.what()) ==
          "list\\x00.csv:2: na\\x00me: bad \\x00 value, expected a name");
    CHECK(direct.message() == "bad \\x00 value, expected a name");
    const IoError io("out/a\0b: cannot create"s);
    CHECK(std::string(io.what()) == "out/a\\x00b: cannot create");

    const std::string header = "time_s,acc\0el_g"s;
    const std::string message = input_error([&] { core::parse_csv(header + "\n0,1\n", "nul.csv"); });
    CHECK_THAT(message, Contains("nul.csv:1: header: column 2 \"acc\\x00el_g\" of "
                                 "\"time_s,acc\\x00el_g\" is not a recognised name"));
    CHECK_THAT(message, Contains("accepted names: time"));
}

TEST_CASE("every text reader refuses UTF-16 text, saying so", "[core][text]") {
    const std::string expected = ":1: UTF-16 text; save it as UTF-8";
    const std::string csv = utf16le("time_s,accel_g\n0,0.1\n0.01,0.2\n");
    CHECK_THAT(input_error([&] { core::parse_csv(csv, "w.csv"); }), Contains("w.csv" + expected));
    // Without a BOM, ASCII in UTF-16 still shows as every other byte NUL.
    CHECK_THAT(input_error([&] { core::parse_csv(csv.substr(2), "w.csv"); }),
               Contains("w.csv" + expected));
    CHECK_THAT(input_error([&] { core::parse_at2(utf16le("PEER\n"), "w.AT2"); }),
               Contains("w.AT2" + expected));
    CHECK_THAT(input_error([&] { core::parse_cosmos_v2(utf16le("Corrected\n"), "w.V2"); }),
               Contains("w.V2" + expected));
    CHECK_THAT(input_error([&] { core::parse_csv_table(utf16le("file\na.toml\n"), "l.csv"); }),
               Contains("l.csv" + expected));
}

TEST_CASE("text readers drop a UTF-8 BOM", "[core][text]") {
    CHECK(core::text::strip_bom("\xEF\xBB\xBFx,y") == "x,y");
    CHECK(core::text::strip_bom("x,y") == "x,y");
    const auto table = core::parse_csv_table("\xEF\xBB\xBF" "file\na.toml\n", "l.csv");
    REQUIRE(table.size() == 2);
    CHECK(table[0].fields[0] == "file");
}

TEST_CASE("a CSV record's '# dt_s' lines must agree", "[core][csv]") {
    const std::string rows = "accel_g\n0.1\n0.2\n";
    const std::string message = input_error(
        [&] { core::parse_csv("# dt_s: 0.01\n# name: a\n# dt_s: 0.02\n" + rows, "dt.csv"); });
    CHECK(message == "dt.csv:3: dt_s: 0.02 s here but 0.01 s at line 1; expected one time step, "
                     "stated once (or repeated unchanged)");
    // The same step twice reads as once.
    const core::Record same = core::parse_csv("# dt_s: 0.01\n# dt_s: 0.01\n" + rows, "dt.csv");
    CHECK(same.dt_s == 0.01);
    CHECK(same.accel_mps2.size() == 2);
}

TEST_CASE("a CSV record stops at the sample limit, at the first row beyond it", "[core][csv][limits]") {
    std::string text = "time_s,accel_g\n";
    for (int i = 0; i < 8; ++i) text += fmt::format("{},0.1\n", 0.01 * i);
    CHECK(core::parse_csv(text, "eight.csv", 8).accel_mps2.size() == 8);
    // Row 6 is line 7; the malformed row after it is never read.
    const std::string message =
        input_error([&] { core::parse_csv(text + "oops\n", "eight.csv", 5); });
    CHECK(message == "eight.csv:7: more than 5 samples, the limit of a record (README, Limits); "
                     "the reading stops at this row");
}

TEST_CASE("an AT2 record stops at the header's NPTS, at the first value beyond it",
          "[core][at2][limits]") {
    const std::string at2 = "PEER\nTEST 0\nACCELERATION TIME SERIES IN UNITS OF G\n"
                            "NPTS=    3, DT=   .0100 SEC\n0.1 0.2\n0.3 0.4\nnot a number\n";
    CHECK(input_error([&] { core::parse_at2(at2, "long.AT2"); }) ==
          "long.AT2:6: acceleration: more values than the header's NPTS= 3 (line 4); expected 3 "
          "values");
}

}  // namespace freestand_test_core_test_text_input
