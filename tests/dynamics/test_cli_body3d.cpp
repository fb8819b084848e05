// `freestand simulate --model 3d`: the JSON fields, the series CSV, the library's numbers, and
// errors naming the flag or the field.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "dynamics/body3d.hpp"
#include "support/paths.hpp"
#include "support/run_cli.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_dynamics_test_cli_body3d {

using freestand::test::run_cli;

TEST_CASE("simulate --model 3d prints the 3D body's JSON, the library's numbers", "[3d][cli]") {
    const auto r = run_cli("simulate --model 3d --block b=0.2,d=0.35,h=0.6,m=150 --mu 1 "
                           "--sine 0.5g,2Hz,3s --json");
    REQUIRE(r.exit_code == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j.at("model") == "3d");
    for (const char* key : {"tilt_max_rad", "tilt_max_over_critical", "overturned", "slide_max_m",
                            "twist_max_rad", "time_in_state_s", "steps", "unconverged_steps"})
        CHECK(j.contains(key));
    for (const char* state : {"rest", "slide", "edge", "vertex", "flight"})
        CHECK(j.at("time_in_state_s").contains(state));
    // The same body and sine through the library.
    using namespace freestand;
    const auto m = dynamics::make_body3d_model(dynamics::box_body(0.2, 0.35, 0.6, 150.0), 1.0);
    dynamics::SineSpec spec{0.5, 2.0, 3.0};
    const auto e = dynamics::biaxial_sine_excitation(spec, 0.0);
    auto y_at_rest = e;
    std::fill(y_at_rest.y_mps2.begin(), y_at_rest.y_mps2.end(), 0.0);
    dynamics::Body3dOptions o;
    o.record_series = false;
    const auto lib = dynamics::simulate_body3d(m, y_at_rest, o);
    CHECK(j.at("tilt_max_rad").get<double>() == lib.summary.tilt_max_rad);
    CHECK(j.at("time_in_state_s").at("edge").get<double>() > 1.0);
}

TEST_CASE("simulate --model 3d --restitution is the library's restitution on angular velocity",
          "[3d][cli]") {
    const auto r = run_cli("simulate --model 3d --block b=0.2,d=0.35,h=0.6,m=150 --mu 1 "
                           "--restitution 0.6 --sine 0.5g,2Hz,3s --json");
    REQUIRE(r.exit_code == 0);
    using namespace freestand;
    const auto m = dynamics::make_body3d_model(dynamics::box_body(0.2, 0.35, 0.6, 150.0), 1.0,
                                               std::nullopt, 0.0, 0.6);
    auto e = dynamics::biaxial_sine_excitation(dynamics::SineSpec{0.5, 2.0, 3.0}, 0.0);
    std::fill(e.y_mps2.begin(), e.y_mps2.end(), 0.0);
    dynamics::Body3dOptions o;
    o.record_series = false;
    const auto lib = dynamics::simulate_body3d(m, e, o);
    CHECK(nlohmann::json::parse(r.out).at("tilt_max_rad").get<double>() == lib.summary.tilt_max_rad);
}

TEST_CASE("simulate --model 3d --block takes the CG's offset and the inertia, as the library",
          "[3d][cli]") {
    const std::string body = "b=0.2,d=0.35,h=0.6,m=150,cgx=0.05,cgy=-0.1,ixx=30,iyy=25,izz=12";
    const auto r = run_cli("simulate --model 3d --block " + body +
                           " --mu 1 --sine 0.5g,2Hz,3s --json");
    REQUIRE(r.exit_code == 0);
    using namespace freestand;
    auto b = dynamics::box_body(0.2, 0.35, 0.6, 150.0);
    for (auto& v : b.footprint_m) v -= Eigen::Vector2d(0.05, -0.1);
    b.inertia_cg_kgm2 = Eigen::Vector3d(30.0, 25.0, 12.0).asDiagonal();
    auto e = dynamics::biaxial_sine_excitation(dynamics::SineSpec{0.5, 2.0, 3.0}, 0.0);
    std::fill(e.y_mps2.begin(), e.y_mps2.end(), 0.0);
    dynamics::Body3dOptions o;
    o.record_series = false;
    const auto lib = dynamics::simulate_body3d(dynamics::make_body3d_model(b, 1.0), e, o);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j.at("tilt_max_rad").get<double>() == lib.summary.tilt_max_rad);
    CHECK(j.at("twist_max_rad").get<double>() == lib.summary.twist_max_rad);
    // Off its middle the body twists under input along x; centred it does not.
    const auto centred = run_cli("simulate --model 3d --block b=0.2,d=0.35,h=0.6,m=150 --mu 1 "
                                 "--sine 0.5g,2Hz,3s --json");
    CHECK(j.at("tilt_max_rad").get<double>() !=
          nlohmann::json::parse(centred.out).at("tilt_max_rad").get<double>());
    const auto outside = run_cli("simulate --model 3d --block b=0.2,d=0.35,h=0.6,cgx=0.2 --mu 1 "
                                 "--sine 0.5g,2Hz,1s");
    CHECK(outside.exit_code == 3);
    CHECK_THAT(outside.err, Catch::Contains("--block cgx") && Catch::Contains("inside the footprint"));
    const auto partial = run_cli("simulate --model 3d --block b=0.2,d=0.35,h=0.6,ixx=3 --mu 1 "
                                 "--sine 0.5g,2Hz,1s");
    CHECK(partial.exit_code == 2);
    CHECK_THAT(partial.err, Catch::Contains("all three of ixx, iyy and izz"));
    const auto negative = run_cli("simulate --model 3d --block b=0.2,d=0.35,h=0.6,ixx=3,iyy=-1,"
                                  "izz=2 --mu 1 --sine 0.5g,2Hz,1s");
    CHECK(negative.exit_code == 3);
    CHECK_THAT(negative.err, Catch::Contains("--block ixx, iyy, izz"));
}

TEST_CASE("simulate --model 3d --sine-y --out writes the series", "[3d][cli]") {
    const auto dir = std::filesystem::temp_directory_path() / "freestand_cli_body3d";
    std::filesystem::create_directories(dir);
    const auto csv = dir / "series.csv";
    const auto r = run_cli("simulate --model 3d --block b=0.2,d=0.2,h=0.7 --mu 1 "
                           "--sine-y 0.42g,2Hz,2s,phase=0 --out '" + csv.string() + "'");
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("model                 3D rigid body"));
    const std::string text = freestand::test::slurp(csv);
    CHECK_THAT(text, Catch::Contains("time_s,slide_x_m,slide_y_m,tilt_rad,tilt_over_critical,"
                                     "twist_rad,state\n"));
    CHECK_THAT(text, Catch::Contains(",vertex\n"));  // diagonal input: on a corner
    std::filesystem::remove_all(dir);
}

TEST_CASE("simulate --model 3d --flexible carries the mode along x and y, as the library",
          "[3d][cli][flexible]") {
    const auto dir = std::filesystem::temp_directory_path() / "freestand_cli_body3d_mode";
    std::filesystem::create_directories(dir);
    const auto csv = dir / "series.csv";
    const std::string run = "simulate --model 3d --block b=0.2,d=0.35,h=0.6,m=150 --mu 1 "
                            "--sine-y 0.3g,2Hz,3s,phase=90 --dt 2.5e-4 "
                            "--flexible f=8,mass=0.4,height=0.9 ";
    const auto r = run_cli(run + "--json");
    REQUIRE(r.exit_code == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j.at("mode").at("frequency_x_hz") == 8.0);
    CHECK(j.at("mode").at("frequency_y_hz") == 8.0);
    CHECK(j.at("mode").at("mass_fraction") == 0.4);
    using namespace freestand;
    const auto rigid = dynamics::make_body3d_model(dynamics::box_body(0.2, 0.35, 0.6, 150.0), 1.0);
    const auto m = dynamics::with_mode(rigid, {8.0, 8.0, 0.02, 0.4, 0.9});
    const auto e = dynamics::biaxial_sine_excitation(dynamics::SineSpec{0.3, 2.0, 3.0}, 90.0);
    dynamics::Body3dOptions o;
    o.dt_s = 2.5e-4;
    o.record_series = false;
    const auto lib = dynamics::simulate_body3d(m, e, o);
    CHECK(j.at("modal_max_m").get<double>() == lib.summary.modal_max_m);
    CHECK(j.at("tilt_max_rad").get<double>() == lib.summary.tilt_max_rad);
    CHECK(lib.summary.modal_max_m > 1e-3);
    // The defaults are the planar body's: 0.613 M at 0.726 of the height (2 h = 1.2 m).
    const auto d = run_cli("simulate --model 3d --block b=0.2,d=0.35,h=0.6 --mu 1 "
                           "--sine 0.1g,2Hz,1s --flexible f=8 --json");
    REQUIRE(d.exit_code == 0);
    const auto jd = nlohmann::json::parse(d.out).at("mode");
    CHECK(jd.at("mass_fraction").get<double>() == 0.613);
    CHECK(jd.at("height_m").get<double>() == Approx(0.726 * 1.2));
    // Text and series name the mode and carry q.
    const auto t = run_cli(run + "--out '" + csv.string() + "'");
    REQUIRE(t.exit_code == 0);
    CHECK_THAT(t.out, Catch::Contains("3D body with a mode along x and y: f 8 / 8 Hz"));
    CHECK_THAT(freestand::test::slurp(csv),
               Catch::Contains("twist_rad,state,modal_x_m,modal_y_m\n"));
    const auto bad = run_cli(run + "--flexible f=-1");
    CHECK(bad.exit_code != 0);
    const auto named = run_cli("simulate --model 3d --block b=0.2,d=0.35,h=0.6 --mu 1 "
                               "--sine 0.1g,2Hz,1s --flexible f=-1");
    CHECK(named.exit_code == 3);
    CHECK_THAT(named.err, Catch::Contains("--flexible f: "));
    std::filesystem::remove_all(dir);
}

TEST_CASE("simulate --model 3d --steps-only takes every phase by steps, and the JSON says which",
          "[3d][cli]") {
    const std::string base = "simulate --model 3d --block b=0.2,d=0.35,h=0.6,m=150 --mu 1 "
                             "--sine 0.5g,2Hz,3s --dt 1e-3 --json";
    const auto phased = run_cli(base);
    const auto stepped = run_cli(base + " --steps-only");
    REQUIRE(phased.exit_code == 0);
    REQUIRE(stepped.exit_code == 0);
    const auto a = nlohmann::json::parse(phased.out);
    const auto b = nlohmann::json::parse(stepped.out);
    CHECK(a.at("phases") == true);
    CHECK(b.at("phases") == false);
    // Rocking on a sticking edge: taken whole by default, by steps with --steps-only.
    CHECK(a.at("phase_time_s").at("edge_sticking").get<double>() > 1.0);
    for (const char* phase : {"edge_sticking", "edge_slipping", "flat_slide"})
        CHECK(b.at("phase_time_s").at(phase).get<double>() == 0.0);
    CHECK(b.at("steps").get<double>() > 1.5 * a.at("steps").get<double>());
    CHECK(a.at("tilt_max_rad").get<double>() ==
          Approx(b.at("tilt_max_rad").get<double>()).epsilon(0.01));
    const auto planar = run_cli("simulate --block b=0.2,h=0.6 --mu 1 --sine 0.5g,2Hz,1s "
                                "--steps-only");
    CHECK(planar.exit_code == 2);
    CHECK_THAT(planar.err, Catch::Contains("--steps-only: only with --model 3d"));
}

TEST_CASE("simulate --model 3d names what it does not take", "[3d][cli]") {
    const std::string base = "simulate --model 3d --mu 1 --sine 0.5g,2Hz,1s ";
    const auto missing = run_cli(base + "--block b=0.2,h=0.6");
    CHECK(missing.exit_code == 2);
    CHECK_THAT(missing.err, Catch::Contains("--block: the 3D body needs b"));
    const auto top = run_cli(base + "--block b=0.2,d=0.2,h=0.6 --top 1.5");
    CHECK(top.exit_code == 2);
    CHECK_THAT(top.err, Catch::Contains("--top: not used by --model 3d"));
    const auto restitution = run_cli(base + "--block b=0.2,d=0.2,h=0.6 --restitution 1.5");
    CHECK(restitution.exit_code == 3);
    CHECK_THAT(restitution.err, Catch::Contains("--restitution"));
    const auto bad = run_cli(base + "--block b=-0.2,d=0.2,h=0.6");
    CHECK(bad.exit_code == 3);
    CHECK_THAT(bad.err, Catch::Contains("--block b (half-width along x, m): "));
    // Errors of the request name the options they came from, never the request's fields.
    for (const auto& [extra, flag] : std::vector<std::pair<std::string, std::string>>{
             {"--block b=0.2,d=0.2,h=0.6 --dt 0", "--dt: "},
             {"--block b=0.2,d=0.2,h=0.6,height=0.3", "--block height (total height, m): "},
             {"--block b=0.2,d=0.2,h=0.6 --integrator cd", "--integrator: "},
             {"--block b=0.2,d=0.2,h=0.6 --block2 b=0.2,h=0.6 --mu2 0.5 --tunnel-height 1",
              "--model 3d: "}}) {
        INFO(extra);
        const auto r = run_cli(base + extra);
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.err, Catch::Contains(flag));
    }
    const auto coarse = run_cli(base + "--block b=0.05,d=0.05,h=0.1 --dt 0.005");
    CHECK(coarse.exit_code == 3);
    CHECK_THAT(coarse.err, Catch::Contains("too coarse"));
    const auto model = run_cli("simulate --model 4d --mu 1 --sine 0.5g,2Hz,1s --block b=0.2,h=0.6");
    CHECK(model.exit_code == 2);
    CHECK_THAT(model.err, Catch::Contains("--model: expected planar or 3d"));
}

}  // namespace freestand_test_dynamics_test_cli_body3d
