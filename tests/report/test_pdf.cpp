// The PDF report (README "PDF reports"): `assess --pdf` and `fragility --pdf` through WeasyPrint,
// the same bytes for the same HTML, and the errors of a missing, failing or hanging converter.
// These tests need weasyprint installed (scripts/setup.sh): without it they fail, they do not skip.
#include <catch2/catch.hpp>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "core/errors.hpp"
#include "report/pdf.hpp"
#include "support/dead_pid.hpp"
#include "support/run_cli.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_report_test_pdf {

namespace fs = std::filesystem;
using freestand::test::dead_pid;
using freestand::test::run_cli;
using freestand::test::slurp;

namespace {

/// A fresh folder under the temporary folder, removed at the end of the test.
struct Scratch {
    fs::path dir;
    explicit Scratch(const std::string& name)
        : dir(fs::temp_directory_path() /
              ("freestand_pdf_" + name + "_" + std::to_string(::getpid()))) {
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    ~Scratch() { fs::remove_all(dir); }
    /// An executable shell script standing in for the converter.
    fs::path script(const std::string& name, const std::string& body) const {
        const fs::path p = dir / name;
        std::ofstream(p) << "#!/bin/sh\n" << body << "\n";
        fs::permissions(p, fs::perms::owner_all);
        return p;
    }
};

/// Sets PATH for the scope and restores it.
struct PathOverride {
    std::string old;
    explicit PathOverride(const std::string& path) : old(std::getenv("PATH") ? std::getenv("PATH") : "") {
        ::setenv("PATH", path.c_str(), 1);
    }
    ~PathOverride() { ::setenv("PATH", old.c_str(), 1); }
};

const char* const kSmallHtml =
    "<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>t</title></head><body>"
    "<h1>PDF test</h1><p>Glove box &mdash; mu_s 0.15 \xc2\xb1 0.03</p>"
    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200\" height=\"100\">"
    "<rect x=\"10\" y=\"10\" width=\"180\" height=\"80\" fill=\"#36c\"/></svg></body></html>";

/// Waits up to 10 s for a file to have contents; returns them.
std::string await_file(const fs::path& p) {
    for (int i = 0; i < 500; ++i) {
        const std::string text = slurp(p);
        if (!text.empty() && text.back() == '\n') return text;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return "";
}

/// True when no process of the group remains within 5 s (the killed converter's children are
/// reaped by init, which may take a moment).
bool group_gone(pid_t group) {
    for (int i = 0; i < 250; ++i) {
        if (::kill(-group, 0) == -1 && errno == ESRCH) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return false;
}

}  // namespace

TEST_CASE("html_to_pdf makes a PDF, the same bytes on every run", "[report][pdf]") {
    const fs::path converter = freestand::report::find_pdf_converter();
    const std::string a = freestand::report::html_to_pdf(converter, kSmallHtml);
    const std::string b = freestand::report::html_to_pdf(converter, kSmallHtml);
    CHECK(a.rfind("%PDF-", 0) == 0);
    CHECK(a.find("%%EOF") != std::string::npos);
    // Byte-identical outputs for the same inputs: SOURCE_DATE_EPOCH fixes the time stamps the
    // font subsets would otherwise carry.
    CHECK(a == b);
}

TEST_CASE("no weasyprint on PATH is an IoError naming it and scripts/setup.sh", "[report][pdf]") {
    const Scratch s("nopath");
    const PathOverride path(s.dir.string() + ":/nonexistent");
    try {
        (void)freestand::report::find_pdf_converter();
        FAIL("no error");
    } catch (const freestand::IoError& e) {
        CHECK(e.code() == freestand::ExitCode::io);
        CHECK_THAT(e.what(), Catch::Contains("needs the program weasyprint"));
        CHECK_THAT(e.what(), Catch::Contains("scripts/setup.sh"));
        CHECK_THAT(e.what(), Catch::Contains(s.dir.string() + ":/nonexistent"));
    }
    // A file of that name that is not executable is not the converter either.
    std::ofstream(s.dir / "weasyprint") << "#!/bin/sh\n";
    CHECK_THROWS_AS(freestand::report::find_pdf_converter(), freestand::IoError);
    fs::permissions(s.dir / "weasyprint", fs::perms::owner_all);
    CHECK(freestand::report::find_pdf_converter() == s.dir / "weasyprint");
}

TEST_CASE("a failing converter is an IoError quoting its standard error", "[report][pdf]") {
    const Scratch s("fails");
    const fs::path bad = s.script("fails", "echo 'CSS: no layout for you' >&2; exit 3");
    try {
        (void)freestand::report::html_to_pdf(bad, kSmallHtml);
        FAIL("no error");
    } catch (const freestand::IoError& e) {
        CHECK_THAT(e.what(), Catch::Contains("failed with exit code 3"));
        CHECK_THAT(e.what(), Catch::Contains("CSS: no layout for you"));
    }
    const fs::path silent = s.script("silent", "exit 0");
    CHECK_THROWS_WITH(freestand::report::html_to_pdf(silent, kSmallHtml),
                      Catch::Contains("wrote no PDF"));
    // The converter gets the input and output paths last; one that writes something else.
    const fs::path not_pdf = s.script("notpdf", "for a; do last=$a; done; echo hello > \"$last\"");
    CHECK_THROWS_WITH(freestand::report::html_to_pdf(not_pdf, kSmallHtml),
                      Catch::Contains("not a PDF"));
}

TEST_CASE("a converter that does not finish is stopped at the time limit", "[report][pdf]") {
    const Scratch s("hangs");
    const fs::path hangs = s.script("hangs", "echo started >&2; sleep 30");
    const auto start = std::chrono::steady_clock::now();
    CHECK_THROWS_WITH(
        freestand::report::html_to_pdf(hangs, kSmallHtml, std::chrono::milliseconds(500)),
        Catch::Contains("did not finish within 0.5 s and was stopped") &&
            Catch::Contains("started"));
    // The whole process group is killed: the call returns long before the sleep ends.
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(10));
}

TEST_CASE("a run stopped by Ctrl-C or a timeout leaves no converter and no temporary folder",
          "[report][pdf]") {
    const Scratch s("stopped");
    const fs::path pid_file = s.dir / "converter.pid";
    // A converter that writes its process id and its input (the HTML in the run's temporary
    // folder: the arguments end with the input and the output) and sleeps in a child process.
    const fs::path slow =
        s.script("slow", "for a; do input=$out; out=$a; done; echo \"$$ $input\" > '" +
                             pid_file.string() + "'; sleep 30");
    struct Stop {
        int signal;
        bool to_group;  ///< Ctrl-C: SIGINT to the terminal's foreground process group
    };
    for (const Stop stop : {Stop{SIGINT, true}, Stop{SIGTERM, false}, Stop{SIGHUP, false}}) {
        INFO("signal " << stop.signal);
        fs::remove(pid_file);
        const pid_t run = ::fork();
        if (run == 0) {
            ::setpgid(0, 0);  // the run's own group, as a shell gives a foreground job
            // The signals' dispositions of the freestand executable, not the test runner's.
            for (const int signal : {SIGINT, SIGTERM, SIGHUP}) ::signal(signal, SIG_DFL);
            try {
                (void)freestand::report::html_to_pdf(slow, kSmallHtml);
            } catch (...) {
            }
            ::_exit(0);
        }
        const std::string started = await_file(pid_file);
        REQUIRE_FALSE(started.empty());
        const pid_t converter = static_cast<pid_t>(std::stol(started));
        const fs::path folder =
            fs::path(started.substr(started.find(' ') + 1, started.size() - started.find(' ') - 2))
                .parent_path();
        REQUIRE(fs::is_directory(folder));
        ::kill(stop.to_group ? -run : run, stop.signal);
        int status = 0;
        while (::waitpid(run, &status, 0) < 0) {
        }
        // The run ends as the signal ends a process (a shell shows 128 + signal)...
        CHECK(WIFSIGNALED(status));
        if (WIFSIGNALED(status)) CHECK(WTERMSIG(status) == stop.signal);
        // ... and leaves neither the converter's process group nor its folder behind.
        CHECK(group_gone(converter));
        CHECK_FALSE(fs::exists(folder));
        ::kill(-converter, SIGKILL);
        fs::remove_all(folder);
    }
}

TEST_CASE("html_to_pdf removes the temporary folders of runs that died", "[report][pdf]") {
    const Scratch s("stale");
    const fs::path stale = fs::temp_directory_path() /
                           ("freestand-pdf-" + std::to_string(dead_pid()) + "-abcdef");
    fs::create_directories(stale);
    std::ofstream(stale / "report.html") << kSmallHtml;
    const fs::path fake = s.script("fake", "for a; do last=$a; done; echo '%PDF-1.4' > \"$last\"");
    CHECK(freestand::report::html_to_pdf(fake, kSmallHtml).rfind("%PDF-", 0) == 0);
    CHECK_FALSE(fs::exists(stale));
    fs::remove_all(stale);
}

TEST_CASE("assess --pdf publishes report.pdf with the other files, the bytes of the HTML's PDF",
          "[report][pdf][cli]") {
    const Scratch s("assess");
    const fs::path out = s.dir / "out";
    const auto r = run_cli("assess cases/glovebox-steel-pads.toml --pga 0.1 --pdf --out '" +
                           out.string() + "'");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("report.pdf made by"));
    const std::string pdf = slurp(out / "report.pdf");
    CHECK(pdf.rfind("%PDF-", 0) == 0);
    for (const char* f : {"report.md", "report.html", "result.json"}) CHECK(fs::exists(out / f));
    // The marker of the published folder lists the PDF as one of the run's files.
    CHECK_THAT(slurp(out / ".freestand-run"), Catch::Contains("report.pdf"));
    // The same HTML converted again gives the same bytes (the HTML itself is byte-identical
    // per input, which the regress and batch tests check).
    const std::string again = freestand::report::html_to_pdf(
        freestand::report::find_pdf_converter(), slurp(out / "report.html"));
    CHECK(again == pdf);
}

TEST_CASE("assess --pdf without weasyprint stops before the assessment, exit 5", "[report][pdf][cli]") {
    const Scratch s("missing");
    const fs::path out = s.dir / "out";
    // PATH without weasyprint; the shell finds nothing else the command needs on it.
    const auto r = run_cli("assess cases/glovebox-steel-pads.toml --pdf --out '" + out.string() + "'",
                           "PATH=/nonexistent ");
    CHECK(r.exit_code == 5);
    CHECK_THAT(r.err, Catch::StartsWith("freestand assess: error: report.pdf needs the program weasyprint"));
    CHECK_THAT(r.err, Catch::Contains("scripts/setup.sh"));
    // Before the assessment: nothing printed, no folder.
    CHECK(r.out.empty());
    CHECK_FALSE(fs::exists(out));
}

TEST_CASE("fragility --pdf writes report.pdf, and with --shard is a usage error",
          "[report][pdf][cli]") {
    const Scratch s("fragility");
    const fs::path out = s.dir / "out";
    const std::string base = "fragility cases/block-ts1.toml --pga 0.2,0.4 --samples 4 --pool 2 "
                             "--threads 1 --out '" + out.string() + "' --pdf";
    const auto shard = run_cli(base + " --shard 1/2");
    CHECK(shard.exit_code == 2);
    CHECK_THAT(shard.err, Catch::Contains("--pdf makes report.pdf from report.html, which --shard "
                                          "does not write"));
    const auto missing = run_cli(base, "PATH=/nonexistent ");
    CHECK(missing.exit_code == 5);
    CHECK_THAT(missing.err, Catch::Contains("report.pdf needs the program weasyprint"));
    CHECK_FALSE(fs::exists(out));

    const auto r = run_cli(base);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(slurp(out / "report.pdf").rfind("%PDF-", 0) == 0);
    CHECK(fs::exists(out / "fragility.json"));
}

}  // namespace freestand_test_report_test_pdf
