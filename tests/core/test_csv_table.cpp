// RFC 4180 tables: quoting both ways, line numbers, and every malformed field an error.
#include <catch2/catch.hpp>

#include "core/csv_table.hpp"
#include "core/errors.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_core_test_csv_table {

using namespace freestand;
using Catch::Contains;

namespace {
using Fields = std::vector<std::string>;
}

TEST_CASE("parse_csv_table reads quoted fields, CRLF, a BOM and skips empty lines",
          "[core][csv_table]") {
    const std::string text =
        "\xEF\xBB\xBF" "file,name\r\n\r\n"
        "a.toml,\"pump, \"\"A\"\"\"\n"
        "\"b\nc.toml\",plain\n"
        "\"\",x,\n";
    const auto rows = core::parse_csv_table(text, "list.csv");
    REQUIRE(rows.size() == 4);
    CHECK(rows[0].line == 1);
    CHECK(rows[0].fields == Fields{"file", "name"});
    CHECK(rows[1].line == 3);
    CHECK(rows[1].fields == Fields{"a.toml", "pump, \"A\""});
    CHECK(rows[2].line == 4);
    CHECK(rows[2].fields == Fields{"b\nc.toml", "plain"});
    CHECK(rows[3].line == 6);
    CHECK(rows[3].fields == Fields{"", "x", ""});
    CHECK(core::parse_csv_table("", "e.csv").empty());
}

TEST_CASE("parse_csv_table names the line of each malformed field", "[core][csv_table]") {
    CHECK_THROWS_AS(core::parse_csv_table("a,b\nx\"y,z\n", "l.csv"), InputError);
    CHECK_THROWS_WITH(core::parse_csv_table("a,b\nx\"y,z\n", "l.csv"),
                      "l.csv:2: a double quote inside an unquoted field; quote the whole field "
                      "(\"...\") and double the quote inside it (RFC 4180)");
    CHECK_THROWS_WITH(core::parse_csv_table("a\n\"x\"y\n", "l.csv"),
                      "l.csv:2: text after the closing quote of a field; expected ',' or the end "
                      "of the line (RFC 4180)");
    CHECK_THROWS_WITH(core::parse_csv_table("a\nb\n\"open,\nstill\n", "l.csv"),
                      "l.csv:3: a quoted field that never closes (RFC 4180)");
}

TEST_CASE("csv_field quotes what RFC 4180 requires and round-trips", "[core][csv_table]") {
    CHECK(core::csv_field("plain") == "plain");
    CHECK(core::csv_field("") == "");
    CHECK(core::csv_field("a,b") == "\"a,b\"");
    CHECK(core::csv_field("say \"hi\"") == "\"say \"\"hi\"\"\"");
    CHECK(core::csv_field("two\nlines") == "\"two\nlines\"");
    CHECK(core::csv_field(" padded") == "\" padded\"");
    const Fields fields{"Pump, \"A\"", "<script>", "x\r\ny", ""};
    const std::string line = core::csv_record(fields);
    CHECK(line.substr(line.size() - 2) == "\r\n");
    const auto back = core::parse_csv_table(line + line, "r.csv");
    REQUIRE(back.size() == 2);
    CHECK(back[0].fields == fields);
    CHECK(back[1].fields == fields);
    CHECK(back[1].line == 3);
}

}  // namespace freestand_test_core_test_csv_table
