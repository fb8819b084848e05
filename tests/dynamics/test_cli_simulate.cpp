// `freestand simulate`: JSON keys, CSV output, and errors naming the option.
#include <catch2/catch.hpp>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/paths.hpp"
#include "support/run_cli.hpp"
#include "support/special_files.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_dynamics_test_cli_simulate {

using freestand::test::run_cli;
namespace test = freestand::test;

TEST_CASE("simulate --json prints the summary keys in order", "[dynamics][cli]") {
    const auto r = run_cli("simulate --block b=0.15,h=0.6,m=38 --mu 0.15 --sine 0.4g,2Hz,3s,ramp=1s --json");
    REQUIRE(r.exit_code == 0);
    const auto j = nlohmann::ordered_json::parse(r.out);
    std::vector<std::string> keys;
    for (const auto& item : j.items()) keys.push_back(item.key());
    const std::vector<std::string> first = {"slide_max_m", "slide_residual_m", "rock_max_rad",
        "rock_max_over_alpha", "overturned", "overturn_time_s", "overturn_mode", "impacts",
        "mode_changes", "top_accel_max_g", "amplification", "wall_s", "integrator"};
    REQUIRE(keys.size() >= first.size());
    CHECK(std::vector<std::string>(keys.begin(), keys.begin() + 13) == first);
    CHECK(j["slide_max_m"].get<double>() > 0.0);
    CHECK(j["overturn_time_s"].is_null());
    CHECK(j["integrator"] == "event");
}

TEST_CASE("simulate --integrator cd --out writes a CSV with units", "[dynamics][cli]") {
    const auto out = std::filesystem::temp_directory_path() / "freestand_sim_series.csv";
    std::filesystem::remove(out);
    const auto r = run_cli("simulate --block b=0.15,h=0.6,m=38 --mu 0.8 --motion "
                           "tests/data/RSN175_IMPVALL.H_H-E12140.AT2 --scale 2 --integrator cd "
                           "--dt 1e-4 --out '" + out.string() + "'");
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("integrator            cd") != std::string::npos);
    const std::string csv = freestand::test::slurp(out);
    CHECK(csv.find("# units: time s, slide m") != std::string::npos);
    CHECK(csv.find("time_s,slide_m,slide_velocity_mps,rotation_rad") != std::string::npos);
    std::filesystem::remove(out);
}

TEST_CASE("simulate --cg takes classify's x=OFFSET,h=HEIGHT as well as x,y from the left edge",
          "[dynamics][cli]") {
    const std::string common = "simulate --block b=0.15,h=0.6,m=38 --inertia 3.5 --mu 0.6 "
                               "--sine 0.6g,1.5Hz,3s,ramp=0.5s --json";
    const auto left_edge = run_cli(common + " --cg 0.2,0.5");
    const auto offset = run_cli(common + " --cg x=0.05,h=0.5");
    const auto mirrored = run_cli(common + " --cg x=-0.05,h=0.5");
    REQUIRE(left_edge.exit_code == 0);
    REQUIRE(offset.exit_code == 0);
    REQUIRE(mirrored.exit_code == 0);
    const auto a = nlohmann::json::parse(left_edge.out), b = nlohmann::json::parse(offset.out),
               c = nlohmann::json::parse(mirrored.out);
    CHECK(a["rock_max_rad"].get<double>() > 0.0);
    // 0.15 + 0.05 and 0.15 - 0.05 against 0.2 and 0.3 - 0.2: equal to round-off.
    CHECK(a["rock_max_rad"].get<double>() == Approx(b["rock_max_rad"].get<double>()).epsilon(1e-9));
    CHECK(a["impacts"] == b["impacts"]);
    // The mirror-image CG changes the answer: the offset is read, not ignored.
    CHECK(a["rock_max_rad"] != c["rock_max_rad"]);
}

TEST_CASE("simulate rejects bad blocks naming the option", "[dynamics][cli][errors]") {
    struct Case { std::string args, expect; int code; };
    const std::vector<Case> cases = {
        {"--block b=-0.1,h=0.6,m=38 --mu 0.2 --sine 0.5g,2Hz,1s", "--block b", 3},
        {"--block b=0.1,h=0.6,m=0 --mu 0.2 --sine 0.5g,2Hz,1s", "--block m", 3},
        {"--block b=0.1,h=0.6,m=3 --mu -0.2 --sine 0.5g,2Hz,1s", "--mu", 3},
        {"--block b=0.1,h=0.6,m=3 --mu 0.2 --restitution 1.5 --sine 0.5g,2Hz,1s", "--restitution", 3},
        {"--block b=0.1,h=0.6,m=3 --mu 0.2 --inertia -1 --sine 0.5g,2Hz,1s", "--inertia", 3},
        {"--block b=0.1,h=0.6,m=3 --mu 0.2 --top 0.3 --sine 0.5g,2Hz,1s", "--top", 3},
        // One parser with classify and rock: the same names and exit codes.
        {"--block b=0.1,h=0.6,m=3 --mu 0.2 --cg x=0.15,h=0.5 --inertia 1 --sine 0.5g,2Hz,1s", "--cg x (right of the base's centre", 3},
        {"--block b=0.1,h=0.6,m=3 --mu 0.2 --cg 0.1 --sine 0.5g,2Hz,1s", "--cg: expected x,y or x=OFFSET,h=HEIGHT", 2},
        {"--block b=0.1,h=0.6,m=3 --mu 0.2 --cg 0.12,0.5 --sine 0.5g,2Hz,1s", "--inertia: a CG position away from the box centre needs", 3},
        {"--block b=0.1,h=0.6,m=3 --mu 0.2", "exactly one of --motion, --sine and --sine-y", 2},
        {"--block b=0.1,h=0.6,m=3 --mu 0.2 --sine 0.5g,2Hz", "--sine", 2},
        {"--block b=0.1,h=0.6,m=3 --mu 0.2 --sine 0.5g,2Hz,1s --integrator rk", "--integrator", 2},
    };
    for (const auto& c : cases) {
        INFO(c.args);
        const auto r = run_cli("simulate " + c.args);
        CHECK(r.exit_code == c.code);
        CHECK(r.err.find("freestand simulate: error:") != std::string::npos);
        CHECK(r.err.find(c.expect) != std::string::npos);
    }
}

TEST_CASE("simulate --out naming the --motion file is refused and the input kept",
          "[dynamics][cli][errors]") {
    const auto dir = std::filesystem::temp_directory_path() / "freestand_sim_own_input";
    std::filesystem::create_directories(dir);
    const auto motion = dir / "motion.AT2";
    std::filesystem::copy_file(std::filesystem::path(freestand::test::source_dir()) /
                                   "tests/data/RSN175_IMPVALL.H_H-E12140.AT2",
                               motion, std::filesystem::copy_options::overwrite_existing);
    const std::string before = freestand::test::slurp(motion);
    const auto r = run_cli("simulate --block b=0.15,h=0.6,m=38 --mu 0.15 --motion '" +
                           motion.string() + "' --out '" + motion.string() + "'");
    CHECK(r.exit_code == 5);
    CHECK(r.err.find(motion.string() + ": refusing to overwrite an input file") != std::string::npos);
    CHECK(freestand::test::slurp(motion) == before);
    CHECK_FALSE(std::filesystem::exists(dir / "motion.AT2.tmp"));
    std::filesystem::remove_all(dir);
}

TEST_CASE("simulate --out shows control characters of the motion's name as hexadecimal escapes",
          "[dynamics][cli][hardening]") {
    // A motion file named with ESC and BEL must not put them raw into the CSV's comment line,
    // where `head series.csv` would change the terminal's title.
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "freestand_sim_control_name";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path motion = dir / "a\x1b]0;pwned\x07" "b.csv";
    std::ofstream(motion) << "# dt_s: 0.01\naccel_g\n0\n0.1\n0\n";
    const std::string m = "'" + motion.string() + "'";
    // The planar block, biaxial sliding and the 3D body each write the label.
    for (const std::string& model :
         {"--block b=0.15,h=0.6,m=38 --motion " + m,
          "--block b=0.3,h=0.6,m=38 --mu-k 0.2 --motion " + m + " --motion-y " + m,
          "--model 3d --block b=0.15,d=0.2,h=0.6,m=38 --motion " + m}) {
        INFO(model);
        const auto r = run_cli("simulate --mu 0.5 " + model + " --out '" +
                               (dir / "series.csv").string() + "'");
        REQUIRE(r.exit_code == 0);
        const std::string csv = freestand::test::slurp(dir / "series.csv");
        CHECK_THAT(csv.substr(0, csv.find('\n') + 1),
                   Catch::Contains("excitation a\\x1B]0;pwned\\x07b"));
        for (char c : csv) CHECK_FALSE((c != '\n' && static_cast<unsigned char>(c) < 0x20));
    }
    fs::remove_all(dir);
}

TEST_CASE("simulate --out never replaces a FIFO, a device or a symlink", "[dynamics][cli][hardening]") {
    // Replacing any of them with a regular file, and exiting 0, would be the failure.
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "freestand_sim_special_out";
    fs::remove_all(dir);
    fs::create_directories(dir);
    REQUIRE(::mkfifo((dir / "fifo").c_str(), 0600) == 0);
    std::ofstream(dir / "kept.csv") << "kept\n";
    fs::create_symlink(dir / "kept.csv", dir / "link.csv");
    const std::string run = "simulate --block b=0.15,h=0.6,m=38 --mu 0.5 --sine 0.1g,2Hz,2s --out ";
    const auto fifo = run_cli(run + "'" + (dir / "fifo").string() + "'");
    CHECK(fifo.exit_code == 5);
    CHECK_THAT(fifo.err, Catch::Contains("fifo: exists and is not a regular file (a device, FIFO "
                                         "or folder); refusing to replace it"));
    CHECK(fs::is_fifo(dir / "fifo"));
    if (const auto dev = test::make_null_device(dir)) {
        const auto device = run_cli(run + "'" + dev->string() + "'");
        CHECK(device.exit_code == 5);
        CHECK(fs::is_character_file(*dev));
    } else {
        WARN("not root: mknod refused, the device case is not run");
    }
    const auto link = run_cli(run + "'" + (dir / "link.csv").string() + "'");
    CHECK(link.exit_code == 5);
    CHECK_THAT(link.err, Catch::Contains("link.csv: exists and is not a regular file (a symbolic "
                                         "link); refusing to replace it"));
    CHECK(fs::is_symlink(dir / "link.csv"));
    CHECK(freestand::test::slurp(dir / "kept.csv") == "kept\n");
    fs::remove_all(dir);
}

}  // namespace freestand_test_dynamics_test_cli_simulate
