// `freestand fragility` and `freestand merge` at the command line (README "Fragility"): the
// outputs, their byte identity across threads and shards, the progress bar's silence off a
// terminal, and errors.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "support/paths.hpp"
#include "support/run_cli.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_fragility_test_fragility_cli {

namespace fs = std::filesystem;
using freestand::test::run_cli;
using freestand::test::slurp;

namespace {

// A block that slides and rocks (0.4 x 0.4 x 1.2 m: tan alpha = 1/3) on friction uniform on
// [0.2, 0.4] and restitution lognormal; the user suite is two short sines, so no history has
// to be generated and the test is fast.
struct Scene {
    fs::path dir;
    std::string case_file, rec_a, rec_b;
    explicit Scene(const std::string& tag) {
        dir = fs::temp_directory_path() /
              ("freestand_fragcli_" + tag + "_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
        rec_a = (dir / "a.csv").string();
        rec_b = (dir / "b.csv").string();
        write_sine(rec_a, 1.5);
        write_sine(rec_b, 3.0);
        case_file = (dir / "block.toml").string();
        std::ofstream(case_file) << R"([component]
name = "Test block"
mass_kg = 200.0
width_m = 0.4
depth_m = 0.4
height_m = 1.2
mu_s = 0.3
restitution = 0.9
allowable_slide_m = 0.02
[site]
pga_g = [0.3]
[options]
seed = 5
[uncertainty]
mu_s = { dist = "uniform", lo = 0.2, hi = 0.4 }
restitution = { dist = "lognormal", median = 0.85, beta = 0.1 }
)";
    }
    ~Scene() { fs::remove_all(dir); }
    static void write_sine(const std::string& file, double f_hz) {
        std::ofstream out(file);
        out << "time_s,accel_g\n";
        for (int i = 0; i <= 4000; ++i) {
            const double t = i * 0.002;
            out << t << "," << std::sin(2.0 * M_PI * f_hz * t) * std::min(1.0, t) << "\n";
        }
    }
    std::string args(const std::string& out, const std::string& more = "",
                     int samples = 12) const {
        return "fragility '" + case_file + "' --pga 0.2:0.6:0.2 --samples " +
               std::to_string(samples) + " --records '" + rec_a + "' '" + rec_b + "' --out '" +
               (dir / out).string() + "' " + more;
    }
};

const std::vector<std::string> kOutputs{"fragility.json", "samples.csv", "report.md",
                                        "report.html", "fragility.svg"};

void check_same_outputs(const fs::path& a, const fs::path& b) {
    for (const std::string& f : kOutputs) {
        INFO(f);
        REQUIRE(fs::exists(a / f));
        CHECK(slurp(a / f) == slurp(b / f));
    }
}

}  // namespace

TEST_CASE("fragility writes fragility.json, samples.csv and the reports, --json prints the file",
          "[fragility][cli]") {
    const Scene s("outputs");
    const auto r = run_cli(s.args("one", "--threads 1"));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    // Not a terminal: no progress bar, nothing on stderr.
    CHECK(r.err.empty());
    for (const std::string& f : kOutputs) CHECK(fs::exists(s.dir / "one" / f));
    const auto j = nlohmann::json::parse(slurp(s.dir / "one" / "fragility.json"));
    REQUIRE(j["levels"].size() == 3);
    CHECK(j["levels"][0]["pga_g"] == 0.2);
    CHECK(j["levels"][0]["n"] == 12);
    for (const char* e : {"overturn", "slide", "rock", "any"}) {
        INFO(e);
        const auto& c = j["levels"][2]["events"][e];
        CHECK(c["k"].get<int>() >= 0);
        CHECK(c["p"].get<double>() == Approx(c["k"].get<int>() / 12.0));
        CHECK(c["ci"][0].get<double>() <= c["p"].get<double>());
        CHECK(c["ci"][1].get<double>() >= c["p"].get<double>());
        CHECK(j["fit"].contains(e));
    }
    CHECK(j["stamp"]["seed"] == 5);
    // samples.csv: a header and one row per sample.
    const std::string csv = slurp(s.dir / "one" / "samples.csv");
    CHECK(std::count(csv.begin(), csv.end(), '\n') == 1 + 3 * 12);
    CHECK(csv.rfind("level,sample,pga_g,motion,mu_s,restitution_x,restitution_y,slide_max_m,"
                    "rock_max_over_alpha,overturned\n",
                    0) == 0);
    CHECK(csv.find("a.csv") != std::string::npos);
    CHECK(csv.find("b.csv") != std::string::npos);
    // The HTML report is self-contained and draws the curves.
    const std::string html = slurp(s.dir / "one" / "report.html");
    CHECK(html.find("<svg") != std::string::npos);
    CHECK(html.find("src=\"http") == std::string::npos);
    const auto printed = run_cli(s.args("two", "--threads 1 --json"));
    REQUIRE(printed.exit_code == 0);
    CHECK(printed.out == slurp(s.dir / "one" / "fragility.json"));
}

TEST_CASE("fragility outputs are the same bytes for any thread count and any sharding",
          "[fragility][cli][reproducible]") {
    const Scene s("bytes");
    REQUIRE(run_cli(s.args("t1", "--threads 1")).exit_code == 0);
    REQUIRE(run_cli(s.args("t3", "--threads 3")).exit_code == 0);
    check_same_outputs(s.dir / "t1", s.dir / "t3");
    // Three shards into one folder (as a job array would), merged; then two shards in two
    // folders.
    for (int k = 1; k <= 3; ++k) {
        const auto r = run_cli(s.args("shards3", "--shard " + std::to_string(k) + "/3"));
        INFO(r.err);
        REQUIRE(r.exit_code == 0);
        CHECK(r.out.find("shard " + std::to_string(k) + " of 3") != std::string::npos);
    }
    auto m = run_cli("merge '" + (s.dir / "shards3").string() + "' --out '" +
                     (s.dir / "m3").string() + "'");
    INFO(m.err);
    REQUIRE(m.exit_code == 0);
    check_same_outputs(s.dir / "t1", s.dir / "m3");
    REQUIRE(run_cli(s.args("sa", "--shard 1/2")).exit_code == 0);
    REQUIRE(run_cli(s.args("sb", "--shard 2/2")).exit_code == 0);
    m = run_cli("merge '" + (s.dir / "sb").string() + "' '" + (s.dir / "sa").string() +
                "' --out '" + (s.dir / "m2").string() + "' --json");
    REQUIRE(m.exit_code == 0);
    check_same_outputs(s.dir / "t1", s.dir / "m2");
    CHECK(m.out == slurp(s.dir / "t1" / "fragility.json"));
}

TEST_CASE("merge refuses incomplete, repeated or mixed shards, naming them",
          "[fragility][cli][errors]") {
    const Scene s("merge");
    REQUIRE(run_cli(s.args("a", "--shard 1/3")).exit_code == 0);
    REQUIRE(run_cli(s.args("a", "--shard 3/3")).exit_code == 0);
    auto r = run_cli("merge '" + (s.dir / "a").string() + "' --out '" + (s.dir / "m").string() + "'");
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("shard 2 of 3") != std::string::npos);
    CHECK_FALSE(fs::exists(s.dir / "m"));
    // Another seed is another run: its shard does not complete this one.
    REQUIRE(run_cli(s.args("b", "--shard 2/3 --seed 6")).exit_code == 0);
    r = run_cli("merge '" + (s.dir / "a").string() + "' '" + (s.dir / "b").string() + "' --out '" +
                (s.dir / "m").string() + "'");
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("shard-2-of-3.jsonl") != std::string::npos);
    CHECK_FALSE(fs::exists(s.dir / "m"));
    // The same shard twice.
    fs::create_directories(s.dir / "c");
    fs::copy_file(s.dir / "a" / "shard-1-of-3.jsonl", s.dir / "c" / "shard-1-of-3.jsonl");
    REQUIRE(run_cli(s.args("d", "--shard 2/3")).exit_code == 0);
    r = run_cli("merge '" + (s.dir / "a").string() + "' '" + (s.dir / "c").string() + "' '" +
                (s.dir / "d").string() + "' --out '" + (s.dir / "m").string() + "'");
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("shard 1 of 3") != std::string::npos);
    // A line that is not JSON names the file and line.
    std::ofstream(s.dir / "d" / "shard-2-of-3.jsonl", std::ios::app) << "{not json\n";
    r = run_cli("merge '" + (s.dir / "a").string() + "' '" + (s.dir / "d").string() + "' --out '" +
                (s.dir / "m").string() + "'");
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("shard-2-of-3.jsonl:") != std::string::npos);
}

TEST_CASE("fragility options are checked before any sample runs", "[fragility][cli][errors]") {
    const Scene s("options");
    const std::string base = "fragility '" + s.case_file + "' --records '" + s.rec_a + "' ";
    const auto fails = [&](const std::string& more, int code, const std::string& text) {
        const auto r = run_cli(base + more + " --out '" + (s.dir / "x").string() + "'");
        INFO(more << " -> " << r.err);
        CHECK(r.exit_code == code);
        CHECK(r.err.find(text) != std::string::npos);
        CHECK_FALSE(fs::exists(s.dir / "x"));
    };
    fails("--pga 0.3:0.1:0.1", 2, "--pga");
    fails("--pga 0.1,0.1", 3, "increasing");
    fails("--pga 0.1,4", 3, "pga");
    fails("--samples 0", 3, "samples");
    fails("--samples 2.5", 2, "--samples");
    fails("--shard 4/3", 2, "--shard");
    fails("--shard 0/3", 2, "--shard");
    fails("--threads -1", 2, "--threads");
    // Counts that are not whole are refused, not truncated (2.5 ran 2 threads, 2.5 sets 2).
    fails("--threads 1.5", 2, "--threads: expected a whole number");
    fails("--pool 2.5", 2, "--pool: expected a whole number");
    fails("--seed -3", 2, "--seed");
    const auto missing = run_cli("fragility '" + s.case_file + "' --records '" +
                                 (s.dir / "nope.csv").string() + "' --out '" +
                                 (s.dir / "x").string() + "'");
    CHECK(missing.exit_code != 0);
    CHECK(missing.err.find("nope.csv") != std::string::npos);
}

TEST_CASE("on a terminal, a fragility run longer than a second draws a progress bar on stderr "
          "and stdout is unchanged",
          "[fragility][cli][progress]") {
    // util-linux `script` gives the command a pseudo-terminal; without it the test cannot run.
    if (std::system("command -v script >/dev/null 2>&1") != 0) {
        WARN("no `script` command: the terminal case is untested here");
        return;
    }
    const Scene s("tty");
    const fs::path pty_text = s.dir / "pty.txt";
    const fs::path json_out = s.dir / "stdout.json";
    // 9000 samples on one thread: several seconds, so the bar shows (a run under a second
    // draws none).
    const std::string inner = std::string("'") + freestand::test::exe() + "' " +
                              s.args("tty", "--json --threads 1", 3000) + " >'" +
                              json_out.string() + "'";
    std::string quoted;  // inner, single-quoted for sh -c inside script -c
    for (char ch : inner) quoted += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
    const std::string cmd = "cd '" + std::string(freestand::test::source_dir()) + "' && script -qec '" +
                            quoted + "' /dev/null >'" + pty_text.string() + "' 2>&1";
    REQUIRE(std::system(cmd.c_str()) == 0);
    const std::string bar = slurp(pty_text);
    INFO(bar);
    CHECK(bar.find("9000/9000 samples") != std::string::npos);
    CHECK(bar.find("/s,") != std::string::npos);
    CHECK(bar.find("left") != std::string::npos);
    // The JSON on stdout is the file's bytes: the bar never mixes into it.
    CHECK(slurp(json_out) == slurp(s.dir / "tty" / "fragility.json"));
    // 36 samples take far less than a second: no bar at all.
    const std::string quick = std::string("'") + freestand::test::exe() + "' " +
                              s.args("quick", "--json") + " >'" + json_out.string() + "'";
    std::string quick_quoted;
    for (char ch : quick) quick_quoted += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
    REQUIRE(std::system(("script -qec '" + quick_quoted + "' /dev/null >'" + pty_text.string() +
                         "' 2>&1").c_str()) == 0);
    CHECK(slurp(pty_text).find("samples") == std::string::npos);
}

}  // namespace freestand_test_fragility_test_fragility_cli
