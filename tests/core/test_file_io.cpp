// Atomic writing and the protection of inputs (core/file_io.hpp).
#include <catch2/catch.hpp>
#include <filesystem>

#include "core/errors.hpp"
#include "core/file_io.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_core_test_file_io {

using namespace freestand;

TEST_CASE("write_file_atomic refuses a file read as an input, under any spelling of its path",
          "[core][io][errors]") {
    const auto dir = std::filesystem::temp_directory_path() / "freestand_file_io_inputs";
    std::filesystem::remove_all(dir);
    core::write_file_atomic(dir / "input.csv", "time_s,accel_g\n0,0\n");
    core::write_file_atomic(dir / "other.csv", "x\n");
    CHECK(core::read_input_file(dir / "input.csv") == "time_s,accel_g\n0,0\n");
    CHECK_THROWS_AS(core::write_file_atomic(dir / "input.csv", "lost"), IoError);
    CHECK_THROWS_WITH(core::write_file_atomic(dir / "sub" / ".." / "input.csv", "lost"),
                      Catch::Contains("refusing to overwrite an input file"));
    CHECK(core::read_text_file(dir / "input.csv") == "time_s,accel_g\n0,0\n");
    CHECK_FALSE(std::filesystem::exists(dir / "input.csv.tmp"));
    // Files only read with read_text_file, and new files, are written as before.
    CHECK(core::read_text_file(dir / "other.csv") == "x\n");
    CHECK_NOTHROW(core::write_file_atomic(dir / "other.csv", "y\n"));
    CHECK_NOTHROW(core::write_file_atomic(dir / "new.csv", "z\n"));
    CHECK(core::read_text_file(dir / "other.csv") == "y\n");
    std::filesystem::remove_all(dir);
}

TEST_CASE("an input beyond 512 MiB is refused: a large file before reading, an endless device "
          "as it is read",
          "[core][io][limits][hardening]") {
    // Issue 16 "nothing runs unbounded": `assess /dev/zero` read until memory ran out.
    const auto dir = std::filesystem::temp_directory_path() / "freestand_file_io_limit";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const auto big = dir / "big.csv";
    core::write_file_atomic(big, "");
    std::filesystem::resize_file(big, 512u * 1024u * 1024u + 1u);  // sparse: no disk used
    CHECK_THROWS_MATCHES(core::read_text_file(big), InputError,
                         Catch::Message(big.string() + ": 536870913 bytes; an input file is "
                                        "limited to 536870912 bytes (512 MiB; README, Limits)"));
    CHECK_THROWS_MATCHES(core::read_text_file("/dev/zero"), InputError,
                         Catch::Message("/dev/zero: does not end within 536870912 bytes; an "
                                        "input file is limited to 536870912 bytes (512 MiB; "
                                        "README, Limits)"));
    std::filesystem::remove_all(dir);
}

}  // namespace freestand_test_core_test_file_io
