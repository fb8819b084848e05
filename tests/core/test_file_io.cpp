// Atomic writing and the protection of inputs (core/file_io.hpp).
#include <catch2/catch.hpp>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "support/dead_pid.hpp"

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
    // Nothing runs unbounded (README "Limits"): unbounded, `assess /dev/zero` reads until
    // memory runs out.
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

using freestand::test::dead_pid;

namespace {

// The temporaries of write_file_atomic in dir.
int temporaries_in(const std::filesystem::path& dir) {
    int n = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        if (e.path().filename().string().find(".freestand-tmp-") != std::string::npos) ++n;
    return n;
}

}  // namespace

TEST_CASE("a write stopped by the file-size limit removes its temporary and names the file",
          "[core][io][limits]") {
    const auto dir = std::filesystem::temp_directory_path() / "freestand_file_io_fsize";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const auto target = dir / "series.csv";
    const auto message = dir / "message.txt";
    // In a child process: the limit (ulimit -f) would bind the test runner's own writes.
    const pid_t pid = ::fork();
    if (pid == 0) {
        const rlimit limit{4096, 4096};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        try {
            core::write_file_atomic(target, std::string(100000, 'x'));
        } catch (const IoError& e) {
            std::ofstream(message) << e.what();
            ::_exit(5);
        }
        ::_exit(0);
    }
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0) {
    }
    CHECK_FALSE(WIFSIGNALED(status));
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 5);
    CHECK(core::read_text_file(message) ==
          target.string() + ": write failed: File too large (the file-size limit, ulimit -f, or "
                             "the file system's largest file)");
    CHECK_FALSE(std::filesystem::exists(target));
    CHECK(temporaries_in(dir) == 0);
    std::filesystem::remove_all(dir);
}

TEST_CASE("write_file_atomic removes the temporaries of its file left by processes that died",
          "[core][io]") {
    const auto dir = std::filesystem::temp_directory_path() / "freestand_file_io_stale";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string dead = ".freestand-tmp-" + std::to_string(dead_pid()) + "-0";
    const std::string live = ".freestand-tmp-" + std::to_string(::getppid()) + "-3";
    std::ofstream(dir / ("out.csv" + dead)) << "half";
    std::ofstream(dir / ("out.csv" + live)) << "being written";
    std::ofstream(dir / ("other.csv" + dead)) << "another file's";
    core::write_file_atomic(dir / "out.csv", "done\n");
    CHECK(core::read_text_file(dir / "out.csv") == "done\n");
    CHECK_FALSE(std::filesystem::exists(dir / ("out.csv" + dead)));
    CHECK(std::filesystem::exists(dir / ("out.csv" + live)));    // its writer may still run
    CHECK(std::filesystem::exists(dir / ("other.csv" + dead)));  // its own writer cleans it
    std::filesystem::remove_all(dir);
}

}  // namespace freestand_test_core_test_file_io
