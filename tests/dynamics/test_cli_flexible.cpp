// `freestand simulate --flexible`: the JSON fields (modal peak, uplift, the defaults stated as
// assumptions), the series CSV, and errors naming the option.
#include <catch2/catch.hpp>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "support/run_cli.hpp"
#include "support/special_files.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_dynamics_test_cli_flexible {

using freestand::test::run_cli;

TEST_CASE("simulate --flexible prints the modal peak, the uplift and its assumptions",
          "[flexible][cli]") {
    // tan(alpha) = 1/3 and 0.1 g at the fixed-base frequency: the flexible body uplifts.
    const std::string common = "simulate --block b=0.25,h=0.75,m=1000 --mu 0.8 --sine 0.1g,4Hz,5s ";
    const auto r = run_cli(common + "--flexible f=4 --json");
    REQUIRE(r.exit_code == 0);
    const auto j = nlohmann::ordered_json::parse(r.out);
    CHECK(j["model"] == "flexible");
    CHECK(j["uplifted"] == true);
    CHECK(j["modal_max_m"].get<double>() > 0.0);
    CHECK(j["modal_drift_max"].get<double>() ==
          Approx(j["modal_max_m"].get<double>() / (0.726 * 1.5)).epsilon(1e-12));
    CHECK(j["flexible_mode"]["mass_fraction"].get<double>() == 0.613);
    CHECK(j["flexible_mode"]["damping"].get<double>() == 0.02);
    CHECK(j["assumptions"].size() == 2);
    CHECK_FALSE(j.contains("top_accel_max_g"));
    const auto given = run_cli(common + "--flexible f=4,zeta=0.05,mass=0.7,height=1.0 --json");
    REQUIRE(given.exit_code == 0);
    const auto g = nlohmann::json::parse(given.out);
    CHECK(g["flexible_mode"]["height_m"].get<double>() == 1.0);
    CHECK(g["assumptions"].empty());
    // The rigid block under the same input stays down.
    const auto rigid = nlohmann::json::parse(run_cli(common + "--json").out);
    CHECK(rigid["rock_max_rad"].get<double>() == 0.0);
}

TEST_CASE("simulate --flexible --integrator cd runs the central-difference baseline",
          "[flexible][cli]") {
    const std::string common =
        "simulate --block b=0.25,h=0.75,m=1000 --mu 0.8 --sine 0.1g,4Hz,5s --flexible f=4 --json";
    const auto ev = nlohmann::json::parse(run_cli(common).out);
    const auto r = run_cli(common + " --integrator cd --dt 1e-4");
    REQUIRE(r.exit_code == 0);
    const auto cd = nlohmann::json::parse(r.out);
    CHECK(ev["integrator"] == "event");
    CHECK(cd["integrator"] == "cd");
    CHECK(cd["uplifted"] == true);
    // 1e-4 s puts each switch up to a step late: within 1% of the event-driven peaks here.
    CHECK(cd["modal_max_m"].get<double>() == Approx(ev["modal_max_m"].get<double>()).epsilon(0.01));
    CHECK(cd["rock_max_rad"].get<double>() == Approx(ev["rock_max_rad"].get<double>()).epsilon(0.01));
}

TEST_CASE("simulate --flexible writes the modal series", "[flexible][cli]") {
    const auto out = std::filesystem::temp_directory_path() / "freestand_flexible_series.csv";
    std::filesystem::remove(out);
    const auto r = run_cli("simulate --block b=0.25,h=0.75,m=1000 --mu 0.8 --sine 0.1g,4Hz,1s "
                           "--flexible f=4 --out '" + out.string() + "'");
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("base uplifted") != std::string::npos);
    const std::string csv = freestand::test::slurp(out);
    CHECK(csv.find("time_s,slide_m,rotation_rad,modal_m,mode") != std::string::npos);
    std::filesystem::remove(out);
}

TEST_CASE("simulate --flexible names bad values", "[flexible][cli][errors]") {
    struct Case { std::string flex, expect; int code; };
    const std::vector<Case> cases = {
        {"--flexible zeta=0.02", "--flexible: expected f=HZ", 2},
        {"--flexible f=4,spin=1", "--flexible: unknown key \"spin\"", 2},
        {"--flexible f=x", "--flexible f", 2},
        {"--flexible f=-4", "--flexible f: fixed-base frequency must be > 0 Hz; got -4", 3},
        {"--flexible f=4,zeta=1", "--flexible zeta: modal damping ratio must be in [0, 1); got 1", 3},
        {"--flexible f=4,mass=0", "--flexible mass: modal mass fraction must be in (0, 1); got 0", 3},
        {"--flexible f=4,height=-1", "--flexible height: modal height must be > 0 m; got -1", 3},
        {"--flexible f=4 --block2 b=0.3,h=0.8,m=500 --mu2 0.5 --tunnel-height 1",
         "--flexible: runs alone", 2},
        {"--flexible f=4 --sine-y 0.1g,4Hz,1s", "exactly one of", 2},
    };
    for (const auto& c : cases) {
        INFO(c.flex);
        const auto r = run_cli("simulate --block b=0.25,h=0.75,m=1000 --mu 0.8 --sine 0.1g,4Hz,1s " +
                               c.flex);
        CHECK(r.exit_code == c.code);
        CHECK(r.err.find(c.expect) != std::string::npos);
    }
}

TEST_CASE("simulate --flexible names the model that ran and why", "[flexible][cli]") {
    const auto r = run_cli("simulate --block b=0.15,h=0.6,m=38 --mu 0.3 --sine 0.5g,2Hz,5s "
                           "--flexible f=1000 --json");
    REQUIRE(r.exit_code == 0);
    const auto j = nlohmann::ordered_json::parse(r.out);
    CHECK(j["model"] == "flexible");
    // The mode moves with the base from 50 kHz (a 0.1 ms impact leaves it 1% of its velocity
    // change), far above the 1000 Hz a case or --flexible may give.
    CHECK(j["rigid_above_hz"].get<double>() == Approx(50249.4).epsilon(1e-5));
    CHECK(j["model_reason"] == "the mode at 1000 Hz is below 5.025e+04 Hz, where it would move "
                               "with the base: the flexible body ran");
}

TEST_CASE("simulate --flexible reports a body toppling after the input as overturned",
          "[flexible][cli][overturn]") {
    const auto r = run_cli("simulate --block b=0.15,h=0.6,m=38 --mu 0.3 --sine 0.5g,2Hz,5s "
                           "--flexible f=0.01 --json");
    REQUIRE(r.exit_code == 0);
    const auto j = nlohmann::ordered_json::parse(r.out);
    CHECK(j["overturned"] == true);
    CHECK(j["overturn_criterion"] != "none");
    CHECK(j["overturn_time_s"].get<double>() >= 5.0);
}

TEST_CASE("simulate --flexible refuses a mode above the case key's limit and an unstable cd step",
          "[flexible][cli][errors]") {
    const std::string common = "simulate --block b=0.15,h=0.6,m=38 --mu 0.3 --sine 0.5g,2Hz,5s ";
    for (const char* f : {"1001", "1e6", "1e8"}) {
        INFO("f = " << f);
        const auto r = run_cli(common + "--flexible f=" + f);
        CHECK(r.exit_code == 3);
        CHECK(r.err.find("--flexible f: fixed-base frequency (Hz): ") != std::string::npos);
        CHECK(r.err.find("is above the limit 1000 (README, Limits)") != std::string::npos);
        CHECK(r.out.empty());
    }
    for (const char* f : {"500", "1000"}) {
        INFO("f = " << f);
        const auto r = run_cli(common + "--flexible f=" + f + " --integrator cd --json");
        CHECK(r.exit_code == 4);
        CHECK(r.err.find("the central-difference step 0.0001 s (a step of 9.62e-05 s on the "
                         "input's samples) exceeds the stability limit ") != std::string::npos);
        CHECK(r.err.find(std::string("of the elastic mode at f = ") + f + " Hz") !=
              std::string::npos);
        CHECK(r.out.empty());
    }
    // Within the limit it runs.
    CHECK(run_cli(common + "--flexible f=500 --integrator cd --dt 1e-5 --json").exit_code == 0);
}

}  // namespace freestand_test_dynamics_test_cli_flexible
