// Batch lists (README "Batch"): a folder, a CSV list, a TOML list; every problem of a list an
// InputError naming list:line and the field, before anything runs.
#include <catch2/catch.hpp>

#include "batch/helpers.hpp"
#include "batch/list.hpp"
#include "core/errors.hpp"
#include "core/sha256.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_batch_test_list {

using namespace freestand;
using namespace freestand::batch;
namespace fs = std::filesystem;

namespace {

std::string csv_error(const std::string& text) {
    try {
        parse_csv_list(text, "plant/list.csv");
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

std::string toml_error(const std::string& text) {
    try {
        parse_toml_list(text, "plant/list.toml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace

TEST_CASE("a folder lists its *.toml cases sorted by name, named by their stems", "[batch][list]") {
    const fs::path dir = test::batch_dir("folder");
    for (const char* f : {"pump.toml", "Fan.toml", "rack-2.toml", "notes.txt", ".hidden.toml"})
        test::write_text(dir / f, "x");
    test::write_text(dir / "sub" / "deep.toml", "x");
    const BatchList list = read_batch_list(dir);
    REQUIRE(list.entries.size() == 3);
    CHECK(list.entries[0].name == "Fan");
    CHECK(list.entries[1].name == "pump");
    CHECK(list.entries[2].name == "rack-2");
    CHECK(list.entries[1].case_file == dir / "pump.toml");
    CHECK(list.entries[1].overrides.empty());
    CHECK(list.entries[1].line == 0);
    CHECK(list.sha256.empty());
    CHECK(list.source == dir.string());
    fs::remove_all(dir);
}

TEST_CASE("a folder's errors", "[batch][list]") {
    const fs::path dir = test::batch_dir("folder_errors");
    CHECK_THROWS_AS(read_batch_list(dir), InputError);
    CHECK_THROWS_WITH(read_batch_list(dir), dir.string() + ": holds no case files (*.toml)");
    test::write_text(dir / "pump A.toml", "x");
    CHECK_THROWS_WITH(read_batch_list(dir),
                      (dir / "pump A.toml").string() +
                          ": name (the file's stem): \"pump A\" cannot name a report folder: use "
                          "1-100 letters, digits, '.', '_', '-' or '+', starting with a letter "
                          "or digit");
    fs::remove(dir / "pump A.toml");
    test::write_text(dir / "pump.toml", "x");
    test::write_text(dir / "PUMP.toml", "x");
    CHECK_THROWS_WITH(read_batch_list(dir),
                      (dir / "pump.toml").string() +
                          ": name (the file's stem): duplicate name \"pump\" (also " +
                          (dir / "PUMP.toml").string() +
                          "); names must differ, ignoring case: each names a report folder");
    fs::remove_all(dir);
}

TEST_CASE("a CSV list with overrides, columns in any order, empty cells keeping the case's",
          "[batch][list][csv]") {
    const fs::path dir = test::batch_dir("csv");
    const std::string text =
        "name, file ,pga_g,base_material,seed,histories_per_level\r\n"
        "pump-1,cases/pump.toml,0.1;0.2; 0.3,steel,12,3\r\n"
        "\r\n"
        ",\"cases/rack.toml\",,,,\r\n"
        "abs," + (dir / "abs.toml").string() + ",0.4,,,\r\n";
    test::write_text(dir / "list.csv", text);
    const BatchList list = read_batch_list(dir / "list.csv");
    REQUIRE(list.entries.size() == 3);
    const BatchEntry& a = list.entries[0];
    CHECK(a.name == "pump-1");
    CHECK(a.line == 2);
    CHECK(a.case_file == dir / "cases" / "pump.toml");
    CHECK(a.overrides.pga_g == std::vector<double>{0.1, 0.2, 0.3});
    CHECK(a.overrides.base_material == "steel");
    CHECK(a.overrides.seed == 12);
    CHECK(a.overrides.histories_per_level == 3);
    const BatchEntry& b = list.entries[1];
    CHECK(b.name == "rack");
    CHECK(b.line == 4);
    CHECK(b.overrides.empty());
    CHECK(list.entries[2].case_file == dir / "abs.toml");
    CHECK(list.entries[2].overrides.pga_g == std::vector<double>{0.4});
    CHECK(list.sha256 == core::sha256_hex(text));
    CHECK(list.source == (dir / "list.csv").string());
    // Only the file column is required.
    const BatchList minimal = parse_csv_list("file\na.toml\n", "list.csv");
    REQUIRE(minimal.entries.size() == 1);
    CHECK(minimal.entries[0].case_file == "a.toml");
    fs::remove_all(dir);
}

TEST_CASE("a CSV list's errors name list:line and the column", "[batch][list][csv]") {
    CHECK_THROWS_AS(parse_csv_list("name\npump\n", "plant/list.csv"), InputError);
    CHECK(csv_error("name\npump\n") ==
          "plant/list.csv:1: file: missing required column (the case file of each row)");
    CHECK(csv_error("file,pga\na.toml,0.1\n") ==
          "plant/list.csv:1: pga: unknown column (column 2); allowed columns: file, name, pga_g, "
          "base_material, seed, histories_per_level");
    CHECK(csv_error("file,seed,seed\na.toml,1,2\n") ==
          "plant/list.csv:1: seed: column given twice (columns 2 and 3)");
    CHECK(csv_error("") ==
          "plant/list.csv: empty list: expected a header row naming the columns (file, and any "
          "of name, pga_g, base_material, seed, histories_per_level)");
    CHECK(csv_error("file\n") == "plant/list.csv:1: no components listed below the header");
    CHECK(csv_error("file,name\na.toml,pump\nb.toml,Pump\n") ==
          "plant/list.csv:3: name: duplicate name \"Pump\" (also plant/list.csv:2); names must "
          "differ, ignoring case: each names a report folder");
    CHECK(csv_error("file,name\na/pump.toml,\nb/pump.toml,\n") ==
          "plant/list.csv:3: name (the file's stem): duplicate name \"pump\" (also "
          "plant/list.csv:2); names must differ, ignoring case: each names a report folder");
    CHECK(csv_error("file,pga_g\na.toml,0.1;x\n") ==
          "plant/list.csv:2: pga_g: item 2 \"x\" of \"0.1;x\" is not a number; expected levels "
          "in g separated by ';', e.g. 0.1;0.2;0.3");
    CHECK(csv_error("file,pga_g\na.toml,0.1;;0.3\n") ==
          "plant/list.csv:2: pga_g: item 2 \"\" of \"0.1;;0.3\" is not a number; expected "
          "levels in g separated by ';', e.g. 0.1;0.2;0.3");
    CHECK(csv_error("file,pga_g\na.toml,0.3;0.2\n") ==
          "plant/list.csv:2: pga_g: levels must be strictly increasing; 0.2 follows 0.3");
    CHECK(csv_error("file,pga_g\na.toml,4\n") ==
          "plant/list.csv:2: pga_g: value 4 is out of range; expected [0.001, 3]");
    CHECK(csv_error("file,seed\na.toml,1.5\n") ==
          "plant/list.csv:2: seed: \"1.5\" is not a whole number");
    CHECK(csv_error("file,seed\na.toml,-3\n") ==
          "plant/list.csv:2: seed: value -3 is out of range; expected an integer in [0, "
          "9007199254740991]");
    CHECK(csv_error("file,histories_per_level\na.toml,0\n") ==
          "plant/list.csv:2: histories_per_level: value 0 is out of range; expected an integer "
          "in [1, 1000]");
    CHECK(csv_error("file,base_material\na.toml,granite\n") ==
          "plant/list.csv:2: base_material: unknown material \"granite\"; expected one of "
          "\"plywood\", \"PVC sheet on concrete\", \"HDPE\", \"aluminium\", \"steel\"");
    CHECK(csv_error("file,name\na.toml\n") ==
          "plant/list.csv:2: 1 field(s); expected 2, one per column of the header");
    CHECK(csv_error("file,name\n ,pump\n") ==
          "plant/list.csv:2: file: empty: expected the case file of the row");
    CHECK(csv_error("file,name\na.toml,../up\n") ==
          "plant/list.csv:2: name: \"../up\" cannot name a report folder: use 1-100 letters, "
          "digits, '.', '_', '-' or '+', starting with a letter or digit");
    CHECK(csv_error("file,name\na.toml,Summary.CSV\n") ==
          "plant/list.csv:2: name: \"Summary.CSV\" is the name of a summary file; choose "
          "another name");
    CHECK(csv_error("file,name\na.toml,\"pump\"x\n") ==
          "plant/list.csv:2: text after the closing quote of a field; expected ',' or the end "
          "of the line (RFC 4180)");
}

TEST_CASE("a TOML list with overrides", "[batch][list][toml]") {
    const std::string text = R"(
[[case]]
file = "cases/pump.toml"
name = "pump-1"
pga_g = [0.1, 0.2, 0.3]
base_material = "HDPE"
seed = 12
histories_per_level = 3

[[case]]
file = "cases/rack.toml"
)";
    const BatchList list = parse_toml_list(text, "plant/list.toml");
    REQUIRE(list.entries.size() == 2);
    const BatchEntry& a = list.entries[0];
    CHECK(a.name == "pump-1");
    CHECK(a.line == 2);
    CHECK(a.case_file == fs::path("plant/cases/pump.toml"));
    CHECK(a.overrides.pga_g == std::vector<double>{0.1, 0.2, 0.3});
    CHECK(a.overrides.base_material == "HDPE");
    CHECK(a.overrides.seed == 12);
    CHECK(a.overrides.histories_per_level == 3);
    CHECK(list.entries[1].name == "rack");
    CHECK(list.entries[1].overrides.empty());
    CHECK(list.entries[1].line == 10);
}

TEST_CASE("a TOML list's errors name list:line and the key", "[batch][list][toml]") {
    CHECK(toml_error("[[case]]\nname = \"x\"\n") ==
          "plant/list.toml:1: case.file: missing required key (a string)");
    CHECK(toml_error("[[case]]\nfile = \"a.toml\"\npga = [0.1]\n") ==
          "plant/list.toml:3: case.pga: unknown key; allowed keys: file, name, pga_g, "
          "base_material, seed, histories_per_level");
    CHECK(toml_error("[[case]]\nfile = \"a.toml\"\npga_g = [0.3, 0.2]\n") ==
          "plant/list.toml:3: case.pga_g: levels must be strictly increasing; 0.2 follows 0.3");
    CHECK(toml_error("[[case]]\nfile = \"a.toml\"\npga_g = \"0.1;0.2\"\n") ==
          "plant/list.toml:3: case.pga_g: expected a non-empty array of numbers in [0.001, 3], got "
          "a string");
    CHECK(toml_error("[[case]]\nfile = \"a.toml\"\nseed = -1\n") ==
          "plant/list.toml:3: case.seed: value -1 is out of range; expected an integer in [0, "
          "9007199254740991]");
    CHECK(toml_error("[[case]]\nfile = \"a.toml\"\nbase_material = \"granite\"\n") ==
          "plant/list.toml:3: case.base_material: unknown material \"granite\"; expected one of "
          "\"plywood\", \"PVC sheet on concrete\", \"HDPE\", \"aluminium\", \"steel\"");
    CHECK(toml_error("[[case]]\nfile = \"a.toml\"\n[[case]]\nfile = \"b/A.toml\"\n") ==
          "plant/list.toml:3: case.name (the file's stem): duplicate name \"A\" (also "
          "plant/list.toml:1); names must differ, ignoring case: each names a report folder");
    CHECK(toml_error("[component]\nname = \"x\"\n") ==
          "plant/list.toml:1: component: unknown key; a batch list holds [[case]] tables (this "
          "looks like a case file: assess it on its own, or list it in a [[case]] table's "
          "file)");
    CHECK(toml_error("title = \"x\"\n") ==
          "plant/list.toml:1: title: unknown key; a batch list holds [[case]] tables");
    CHECK(toml_error("") ==
          "plant/list.toml: case: no [[case]] tables: expected one per component, each with file "
          "and any of name, pga_g, base_material, seed, histories_per_level");
    CHECK(toml_error("case = 3\n") ==
          "plant/list.toml:1: case: expected [[case]] tables (an array of tables)");
    CHECK_THAT(toml_error("[[case]\n"), Catch::StartsWith("plant/list.toml:1: TOML syntax error"));
}

TEST_CASE("a list path that is no list", "[batch][list]") {
    const fs::path dir = test::batch_dir("paths");
    test::write_text(dir / "list.txt", "file\na.toml\n");
    CHECK_THROWS_AS(read_batch_list(dir / "list.txt"), InputError);
    CHECK_THROWS_WITH(read_batch_list(dir / "list.txt"),
                      (dir / "list.txt").string() +
                          ": list: a list is a folder of case files, a .csv or a .toml file; got "
                          "\".txt\"");
    CHECK_THROWS_AS(read_batch_list(dir / "none.csv"), IoError);
    CHECK_THROWS_WITH(read_batch_list(dir / "none.csv"),
                      (dir / "none.csv").string() + ": no such file or folder");
    fs::remove_all(dir);
}

}  // namespace freestand_test_batch_test_list
