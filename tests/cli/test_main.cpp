#include <catch2/catch.hpp>

#include <cctype>
#include <filesystem>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>
#include <fstream>

#include "support/run_cli.hpp"
#include "core/version.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_cli_test_main {

using freestand::test::run_cli;

TEST_CASE("freestand without a command prints help and exits 2", "[cli]") {
    const auto r = run_cli("");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Contains("commands:"));
}

TEST_CASE("freestand --help lists every command and the exit codes", "[cli]") {
    const auto r = run_cli("--help");
    CHECK(r.exit_code == 0);
    for (const char* cmd : {"assess", "regress", "validate", "spectrum", "target", "generate", "classify",
                            "slide", "rock", "simulate"})
        CHECK_THAT(r.out, Catch::Contains(cmd));
    CHECK_THAT(r.out, Catch::Contains("exit codes"));
    CHECK_THAT(r.out, Catch::Contains("freestand --version"));
    CHECK_THAT(r.out, Catch::Contains("--flexible a flexible body"));
}

TEST_CASE("an unknown command is a usage error naming it", "[cli]") {
    const auto r = run_cli("frobnicate");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains("unknown command \"frobnicate\""));
}

TEST_CASE("an unknown option is a usage error with the command prefixed once", "[cli]") {
    const auto r = run_cli("spectrum --no-such-option x");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::StartsWith("freestand spectrum: error: unrecognised option '--no-such-option'"));
    CHECK_THAT(r.err, Catch::Contains("(see freestand spectrum --help)"));
}

TEST_CASE("freestand --version prints the version, the commit and each linked library's version", "[cli]") {
    const auto r = run_cli("--version");
    CHECK(r.exit_code == 0);
    CHECK(r.err.empty());
    // core::version() is CMake's project(VERSION).
    CHECK_THAT(r.out, Catch::StartsWith(std::string("freestand ") + freestand::core::version() + "\ncommit "));
    std::vector<std::string> lines;
    std::istringstream in(r.out);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    REQUIRE(lines.size() == 10);
    CHECK(lines[1] != "commit unknown");
    // Each library line is "<name> <version>": the name, then a version starting with a digit
    // (FFTW's own string reads "fftw-3.3.10-...").
    const char* names[] = {"Eigen ", "FFTW fftw-", "Boost ", "fmt ", "toml++ ", "nlohmann-json ", "mstch ", "compiler "};
    for (std::size_t i = 0; i < std::size(names); ++i) {
        INFO(lines[i + 2]);
        CHECK_THAT(lines[i + 2], Catch::StartsWith(names[i]));
        const std::string version = lines[i + 2].substr(std::string(names[i]).size());
        CHECK_FALSE(version.empty());
        if (!version.empty() && i != 7) CHECK(std::isdigit(static_cast<unsigned char>(version[0])));
    }
}

TEST_CASE("report stamps carry a commit of this repository", "[cli]") {
    const auto dir = std::filesystem::temp_directory_path() / "freestand_stamp_test";
    // The TS1 block at 0.1 g is settled by the static check: a stamped result.json in milliseconds.
    const auto r = run_cli("assess cases/block-ts1.toml --pga 0.1 --out '" + dir.string() + "'");
    REQUIRE(r.exit_code == 0);
    const std::string json = freestand::test::slurp(dir / "result.json");
    std::filesystem::remove_all(dir);
    const std::string key = "\"commit\": \"";
    const auto at = json.find(key);
    REQUIRE(at != std::string::npos);
    const std::string commit = json.substr(at + key.size(), json.find('"', at + key.size()) - at - key.size());
    // The suite runs from a git checkout (CI clones one): "unknown" is a failure, not a skip.
    REQUIRE(commit != "unknown");
    // 12 hex digits, "-dirty" appended when the build had uncommitted changes.
    const bool dirty = commit.size() == 18 && commit.substr(12) == "-dirty";
    CHECK((commit.size() == 12 || dirty));
    // The stamped commit must name an object of the source repository.
    CHECK(run_cli("--version >/dev/null && git cat-file -e " + commit.substr(0, 12) + "^{commit}")
              .exit_code == 0);
    // Dirty exactly when tracked files differ from the commit.
    const bool tree_dirty =
        run_cli("--version >/dev/null && git diff --quiet HEAD --").exit_code != 0;
    CHECK(dirty == tree_dirty);
}

TEST_CASE("errors quoting a file's bytes show control characters as hexadecimal escapes", "[cli][hardening]") {
    // A record value "ESC]0;pwned BEL" (a terminal's set-title sequence) must not be quoted raw
    // in "expected a number; got ...".
    const auto dir = std::filesystem::temp_directory_path() / "freestand_cli_controls";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "esc.csv") << "time_s,accel_g\n0,\x1b]0;pwned\x07\n";
    const auto r = run_cli("spectrum '" + (dir / "esc.csv").string() + "'");
    CHECK(r.exit_code == 3);
    CHECK_THAT(r.err, Catch::EndsWith("esc.csv:2: column 2 (accel_g): expected a number; got "
                                      "\"\\x1B]0;pwned\\x07\"\n"));
    CHECK(r.err.find('\x1b') == std::string::npos);
    CHECK(r.err.find('\x07') == std::string::npos);
    const auto u = run_cli("\"$(printf '\\033[2J')\"");  // /bin/sh: no $'...' quoting
    CHECK(u.exit_code == 2);
    CHECK_THAT(u.err, Catch::Contains("unknown command \"\\x1B[2J\""));
    std::filesystem::remove_all(dir);
}

}  // namespace freestand_test_cli_test_main
