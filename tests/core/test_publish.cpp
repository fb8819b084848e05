// Output safety (core/publish.hpp): no special file is replaced, a run's folder is
// published whole, concurrent runs do not mix, and inputs are checked before anything is written.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <sys/wait.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <thread>

#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/publish.hpp"
#include "support/special_files.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_core_test_publish {

namespace fs = std::filesystem;
using namespace freestand;
using Catch::Contains;

namespace {

fs::path fresh(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("freestand_publish_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::vector<core::OutputFile> run_files(const std::string& tag, bool with_figure = true) {
    std::vector<core::OutputFile> out{{"report.md", "report " + tag + "\n"},
                                      {"result.json", "{\"run\": \"" + tag + "\"}\n"}};
    if (with_figure) out.push_back({"figure.svg", "<svg>" + tag + "</svg>\n"});
    return out;
}

// A file of an open folder, or "" when it is gone.
std::string read_at(int dir_fd, const char* name) {
    const int fd = ::openat(dir_fd, name, O_RDONLY);
    if (fd < 0) return "";
    std::string out;
    char buffer[256];
    for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0;)
        out.append(buffer, static_cast<std::size_t>(n));
    ::close(fd);
    return out;
}

std::size_t entries(const fs::path& dir) {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), {}));
}

// Runs body without root's privileges, where file permissions bind: directly when not root,
// else in a child process as the user nobody (uid and gid 65534). Returns body's exit status:
// 0 when it returned, 1 when it threw.
int unprivileged(const std::function<void()>& body) {
    const auto guarded = [&body] {
        try {
            body();
            return 0;
        } catch (const std::exception& e) {
            std::cerr << "unprivileged: " << e.what() << "\n";
            return 1;
        }
    };
    if (::geteuid() != 0) return guarded();
    std::cout.flush();
    const pid_t pid = ::fork();
    if (pid == 0) {
        if (::setgid(65534) != 0 || ::setuid(65534) != 0) ::_exit(2);
        ::_exit(guarded());
    }
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0) {
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 3;
}

// A folder that the user nobody may write into (the tests may run as root).
fs::path fresh_shared(const std::string& name) {
    const fs::path dir = fresh(name);
    fs::permissions(dir, fs::perms::all);
    return dir;
}

// What body writes to std::cerr.
std::string cerr_of(const std::function<void()>& body) {
    std::ostringstream captured;
    std::streambuf* const old = std::cerr.rdbuf(captured.rdbuf());
    try {
        body();
    } catch (...) {
        std::cerr.rdbuf(old);
        throw;
    }
    std::cerr.rdbuf(old);
    return captured.str();
}

}  // namespace

TEST_CASE("write_file_atomic never replaces a device, a FIFO or a symlink",
          "[core][io][hardening]") {
    const fs::path dir = fresh("special");
    if (const auto dev = test::make_null_device(dir)) {
        CHECK_THROWS_WITH(core::write_file_atomic(*dev, "x"),
                          Contains("device: exists and is not a regular file"));
        CHECK(fs::is_character_file(*dev));
    } else {
        WARN("not root: mknod refused, the device case is not run");
    }
    REQUIRE(::mkfifo((dir / "fifo").c_str(), 0600) == 0);
    CHECK_THROWS_WITH(core::write_file_atomic(dir / "fifo", "x"),
                      Contains("exists and is not a regular file"));
    CHECK(fs::is_fifo(dir / "fifo"));
    core::write_file_atomic(dir / "target.txt", "kept\n");
    fs::create_symlink(dir / "target.txt", dir / "link.txt");
    CHECK_THROWS_WITH(core::write_file_atomic(dir / "link.txt", "x"),
                      Contains("(a symbolic link); refusing to replace it"));
    CHECK(core::read_text_file(dir / "target.txt") == "kept\n");
    CHECK(fs::is_symlink(dir / "link.txt"));
    // No temporary is left behind by a refusal or a success.
    core::write_file_atomic(dir / "plain.txt", "a\n");
    for (const auto& e : fs::directory_iterator(dir))
        CHECK(e.path().filename().string().find("freestand-tmp") == std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("publish_folder writes a new folder whole, marked as freestand's",
          "[core][io][publish]") {
    const fs::path root = fresh("new");
    core::publish_folder(root / "out" / "case", run_files("A"));
    CHECK(core::read_text_file(root / "out" / "case" / "report.md") == "report A\n");
    CHECK(fs::is_regular_file(root / "out" / "case" / core::run_marker));
    CHECK(entries(root / "out" / "case") == 4);
    CHECK(entries(root / "out") == 1);  // no staging or aside folder left
    fs::remove_all(root);
}

TEST_CASE("a republish replaces the previous run's files, keeps hand-added ones",
          "[core][io][publish]") {
    const fs::path root = fresh("again");
    const fs::path dir = root / "case";
    core::publish_folder(dir, run_files("A", true));
    std::ofstream(dir / "notes.txt") << "mine\n";
    core::publish_folder(dir, run_files("B", false));
    CHECK(core::read_text_file(dir / "result.json") == "{\"run\": \"B\"}\n");
    CHECK_FALSE(fs::exists(dir / "figure.svg"));  // written by run A only: gone with it
    CHECK(core::read_text_file(dir / "notes.txt") == "mine\n");
    CHECK(entries(root) == 1);
    fs::remove_all(root);
}

TEST_CASE("publish_folder refuses before writing anything", "[core][io][publish][hardening]") {
    const fs::path root = fresh("refuse");
    SECTION("a folder it does not own") {
        fs::create_directories(root / "mine");
        std::ofstream(root / "mine" / "thesis.tex") << "x";
        CHECK_THROWS_WITH(core::publish_folder(root / "mine", run_files("A")),
                          Contains("was not written by freestand"));
        CHECK(entries(root / "mine") == 1);
    }
    SECTION("a symlink, a file, a FIFO inside") {
        core::publish_folder(root / "real", run_files("A"));
        fs::create_directory_symlink(root / "real", root / "link");
        CHECK_THROWS_WITH(core::publish_folder(root / "link", run_files("B")),
                          Contains("is a symbolic link"));
        std::ofstream(root / "file") << "x";
        CHECK_THROWS_WITH(core::publish_folder(root / "file", run_files("B")),
                          Contains("exists and is not a folder"));
        REQUIRE(::mkfifo((root / "real" / "pipe").c_str(), 0600) == 0);
        CHECK_THROWS_WITH(core::publish_folder(root / "real", run_files("B")),
                          Contains("pipe: is not a regular file"));
        CHECK(core::read_text_file(root / "real" / "report.md") == "report A\n");
    }
    SECTION("an output that is an input of the run") {
        core::publish_folder(root / "out", run_files("A"));
        CHECK(core::read_input_file(root / "out" / "report.md") == "report A\n");
        CHECK_THROWS_WITH(core::publish_folder(root / "out", run_files("B")),
                          Contains("refusing to overwrite an input file"));
        CHECK(core::read_text_file(root / "out" / "result.json") == "{\"run\": \"A\"}\n");
    }
    for (const auto& e : fs::directory_iterator(root))
        CHECK(e.path().filename().string().find(".freestand-") == std::string::npos);
    fs::remove_all(root);
}

TEST_CASE("concurrent runs into one folder leave one run's files, never a mix",
          "[core][io][publish][hardening]") {
    const fs::path root = fresh("race");
    const fs::path dir = root / "case";
    std::vector<std::thread> runs;
    std::atomic<int> running{4};
    for (int t = 0; t < 4; ++t) {
        runs.emplace_back([&, t] {
            for (int i = 0; i < 25; ++i)
                core::publish_folder(dir, run_files(std::to_string(t) + "-" + std::to_string(i)));
            --running;
        });
    }
    // A reader that opens the folder once and reads both files through it (as a reader of a
    // run's outputs should) sees one run's files, or none while the folder is being swapped.
    int consistent = 0;
    for (int probe = 0; running > 0 && probe < 1000000; ++probe) {
        const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
        if (dfd < 0) continue;
        const std::string md = read_at(dfd, "report.md");
        const std::string json = read_at(dfd, "result.json");
        ::close(dfd);
        if (md.empty() || json.empty()) continue;  // the old folder was removed meanwhile
        const std::string tag = md.substr(7, md.size() - 8);
        CHECK(json == "{\"run\": \"" + tag + "\"}\n");
        ++consistent;
    }
    for (auto& r : runs) r.join();
    CHECK(consistent > 0);
    CHECK(entries(dir) == 4);
    CHECK(entries(root) == 1);
    fs::remove_all(root);
}

TEST_CASE("left-overs of killed runs are cleaned by the next publish", "[core][io][publish]") {
    const fs::path root = fresh("stale");
    fs::create_directories(root / ".case.freestand-old-1-0");
    // A staging folder of a run that died before it could publish.
    fs::create_directories(root / ".case.freestand-stage-4194305-0");
    core::publish_folder(root / "case", run_files("A"));
    CHECK(entries(root) == 1);
    fs::remove_all(root);
}

TEST_CASE("a trailing slash names the same folder, and '.' the working folder, replaced in place",
          "[core][io][publish]") {
    const fs::path root = fresh("slash");
    core::publish_folder(root.string() + "/new/", run_files("A"));
    CHECK(core::read_text_file(root / "new" / "report.md") == "report A\n");
    core::publish_folder(root.string() + "/new/x/..", run_files("B"));
    CHECK(core::read_text_file(root / "new" / "report.md") == "report B\n");
    CHECK(entries(root) == 1);
    fs::create_directories(root / "here");
    const fs::path before = fs::current_path();
    fs::current_path(root / "here");
    core::publish_folder(".", run_files("A"));
    std::ofstream("notes.txt") << "mine\n";
    core::publish_folder("./", run_files("B", false));
    // Read through the working folder as it was entered: a shell standing in it sees this run.
    const bool same_folder = fs::equivalent(".", root / "here");
    const std::string report = core::read_text_file("report.md");
    const bool figure_left = fs::exists("figure.svg");
    const std::string notes = core::read_text_file("notes.txt");
    const std::size_t count = entries(".");
    fs::current_path(before);
    CHECK(same_folder);
    CHECK(report == "report B\n");
    CHECK_FALSE(figure_left);  // written by run A only: gone with it
    CHECK(notes == "mine\n");
    CHECK(count == 4);
    CHECK(entries(root) == 2);  // no staging or aside folder left
    CHECK_THROWS_WITH(core::publish_folder("/", run_files("A")),
                      Contains("/: cannot publish into the root folder"));
    CHECK_THROWS_WITH(core::check_publish_target("/.."),
                      Contains("/..: cannot publish into the root folder"));
    fs::remove_all(root);
}

TEST_CASE("a previous run that cannot be removed is refused before the swap, and left-overs "
          "that cannot be removed are named",
          "[core][io][publish]") {
    const fs::path root = fresh_shared("readonly");
    const fs::path dir = root / "case";
    const fs::path message = root / "message.txt";
    // Permissions bind only without root's privileges: the publishes run as nobody.
    const int status = unprivileged([&] {
        core::publish_folder(dir, run_files("A"));
        fs::permissions(dir, fs::perms::owner_write | fs::perms::group_write |
                                 fs::perms::others_write, fs::perm_options::remove);
        try {
            core::publish_folder(dir, run_files("B"));
        } catch (const IoError& e) {
            std::ofstream(message) << e.what();
        }
    });
    CHECK(status == 0);
    CHECK_THAT(core::read_text_file(message),
               Contains(dir.string() + ": cannot replace the previous run: Permission denied"));
    CHECK(core::read_text_file(dir / "report.md") == "report A\n");
    for (const auto& e : fs::directory_iterator(root))
        CHECK(e.path().filename().string().find(".freestand-") == std::string::npos);

    // A left-over of a killed run that cannot be removed is named on standard error.
    fs::permissions(dir, fs::perms::owner_write, fs::perm_options::add);
    const fs::path stale = root / ".case.freestand-old-1-0";
    const fs::path warning = root / "warning.txt";
    const int stale_status = unprivileged([&] {
        fs::create_directories(stale);
        std::ofstream(stale / "report.md") << "old\n";
        fs::permissions(stale, fs::perms::owner_write, fs::perm_options::remove);
        std::ofstream(warning) << cerr_of([&] { core::publish_folder(dir, run_files("C")); });
    });
    CHECK(stale_status == 0);
    CHECK_THAT(core::read_text_file(warning),
               Contains("warning: " + stale.string() + ": cannot remove this left-over of an "
                        "earlier run: Permission denied; remove it by hand"));
    CHECK(core::read_text_file(dir / "report.md") == "report C\n");
    fs::permissions(stale, fs::perms::owner_all, fs::perm_options::add);
    fs::remove_all(root);
}

namespace {
std::vector<core::OutputFile> batch_files(const std::string& tag,
                                          const std::vector<std::string>& components) {
    std::vector<core::OutputFile> out{{"summary.md", "summary " + tag + "\n"}};
    for (const std::string& c : components) {
        out.push_back({c + "/report.md", c + " " + tag + "\n"});
        out.push_back({c + "/result.json", "{}\n"});
    }
    return out;
}
}  // namespace

TEST_CASE("publish_folder writes sub-folders that read as folders published on their own",
          "[core][io][publish]") {
    const fs::path root = fresh("nested");
    core::publish_folder(root / "batch", batch_files("A", {"pump", "rack"}));
    CHECK(core::read_text_file(root / "batch" / "pump" / "report.md") == "pump A\n");
    CHECK(core::read_text_file(root / "batch" / core::run_marker).find("summary.md\npump/\nrack/\n") !=
          std::string::npos);
    // The sub-folder's marker is the one a publish of its files alone writes.
    core::publish_folder(root / "alone", {{"report.md", "x"}, {"result.json", "y"}});
    CHECK(core::read_text_file(root / "batch" / "pump" / core::run_marker) ==
          core::read_text_file(root / "alone" / core::run_marker));
    CHECK(entries(root / "batch") == 4);
    CHECK(entries(root / "batch" / "pump") == 3);
    CHECK(entries(root) == 2);
    fs::remove_all(root);
}

TEST_CASE("a republish replaces sub-folders whole and keeps hand-added files in them",
          "[core][io][publish]") {
    const fs::path root = fresh("nested_again");
    const fs::path dir = root / "batch";
    core::publish_folder(dir, batch_files("A", {"pump", "rack", "fan"}));
    std::ofstream(dir / "pump" / "notes.txt") << "mine\n";
    std::ofstream(dir / "top.txt") << "top\n";
    core::publish_folder(dir, batch_files("B", {"pump", "rack"}));
    CHECK(core::read_text_file(dir / "rack" / "report.md") == "rack B\n");
    CHECK_FALSE(fs::exists(dir / "fan"));  // written by run A only: gone with it
    CHECK(core::read_text_file(dir / "pump" / "notes.txt") == "mine\n");
    CHECK(core::read_text_file(dir / "top.txt") == "top\n");
    // A flat run replaces the batch whole: its sub-folders go, once the hand-added file in
    // one of them is moved out (it would be lost with the folder).
    CHECK_THROWS_WITH(core::publish_folder(dir, run_files("C")),
                      Contains("pump/notes.txt: was added by hand"));
    fs::remove(dir / "pump" / "notes.txt");
    core::publish_folder(dir, run_files("C"));
    CHECK_FALSE(fs::exists(dir / "rack"));
    CHECK_FALSE(fs::exists(dir / "pump"));
    CHECK(core::read_text_file(dir / "top.txt") == "top\n");
    fs::remove_all(root);
}

TEST_CASE("publish_folder refuses sub-folders it cannot account for",
          "[core][io][publish][hardening]") {
    const fs::path root = fresh("nested_refuse");
    const fs::path dir = root / "batch";
    core::publish_folder(dir, batch_files("A", {"pump", "rack"}));
    SECTION("a folder added by hand") {
        fs::create_directories(dir / "photos");
        CHECK_THROWS_AS(core::publish_folder(dir, batch_files("B", {"pump"})), IoError);
        CHECK_THROWS_WITH(core::publish_folder(dir, batch_files("B", {"pump"})),
                          Contains("photos: is not a regular file; refusing to replace its folder"));
    }
    SECTION("a hand-added file in a sub-folder the run no longer writes") {
        std::ofstream(dir / "rack" / "notes.txt") << "mine\n";
        CHECK_THROWS_WITH(core::publish_folder(dir, batch_files("B", {"pump"})),
                          Contains("rack/notes.txt: was added by hand to a sub-folder this run "
                                   "no longer writes; move it out first"));
    }
    SECTION("a sub-folder whose marker is gone") {
        fs::remove(dir / "pump" / core::run_marker);
        CHECK_THROWS_WITH(core::publish_folder(dir, batch_files("B", {"pump"})),
                          Contains("pump: exists, is not empty and was not written by freestand"));
    }
    SECTION("an input of the run in a sub-folder") {
        CHECK(core::read_input_file(dir / "pump" / "report.md") == "pump A\n");
        CHECK_THROWS_WITH(core::publish_folder(dir, batch_files("B", {"pump"})),
                          Contains("refusing to overwrite an input file"));
    }
    CHECK(core::read_text_file(dir / "summary.md") == "summary A\n");
    CHECK(core::read_text_file(dir / "rack" / "report.md") == "rack A\n");
    CHECK_THROWS_AS(core::publish_folder(dir, {{"a/b/c", "x"}}), std::invalid_argument);
    CHECK_THROWS_AS(core::publish_folder(dir, {{"a", "x"}, {"a/b", "y"}}), std::invalid_argument);
    CHECK_THROWS_AS(core::publish_folder(dir, {{"../b", "x"}}), std::invalid_argument);
    fs::remove_all(root);
}

}  // namespace freestand_test_core_test_publish
