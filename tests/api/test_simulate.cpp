// api::simulate: which model a request runs, the checks of a request no command line can make,
// and the request fields its errors name.
#include <catch2/catch.hpp>

#include "api/simulate.hpp"
#include "core/errors.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_api_test_simulate {

using namespace freestand;

dynamics::SineSpec sine(double amplitude_g) {
    dynamics::SineSpec s;
    s.amplitude_g = amplitude_g;
    s.frequency_hz = 2.0;
    s.duration_s = 1.0;
    return s;
}

// A squat block (tan(alpha) = 1 > mu_s): it slides and cannot rock.
api::SimulateRequest slider() {
    api::SimulateRequest r;
    r.box.half_width_m = 0.3;
    r.box.half_height_m = 0.3;
    r.box.mass_kg = 100.0;
    r.mu_s = 0.2;
    r.excitation.sine = sine(0.4);
    return r;
}

core::Record record(std::size_t n) {
    core::Record rec;
    rec.name = "pulse";
    rec.dt_s = 0.01;
    rec.accel_mps2.assign(n, 0.0);
    return rec;
}

void check_refused(const api::SimulateRequest& r, const std::string& field) {
    INFO(field);
    try {
        api::simulate(r);
        FAIL("accepted");
    } catch (const InputError& e) {
        CHECK(e.where().field == field);
    }
}

TEST_CASE("simulate runs the model its request describes", "[api][simulate]") {
    api::SimulateRequest r = slider();
    CHECK(std::holds_alternative<api::PlanarRun>(api::simulate(r).run));
    r.excitation.sine.reset();
    r.excitation.sine_y = sine(0.4);
    r.excitation.sine_y->phase_deg = 90.0;
    CHECK(std::holds_alternative<api::BiaxialRun>(api::simulate(r).run));
    r = slider();
    r.flexible = dynamics::FlexibleMode{};
    r.flexible->frequency_hz = 4.0;
    CHECK(std::holds_alternative<api::FlexibleRun>(api::simulate(r).run));
    r = slider();
    r.unit2 = api::JoinedUnit{slider().box, 0.3, std::nullopt, std::nullopt, 0.5};
    const api::SimulateResult pair = api::simulate(r);
    REQUIRE(std::holds_alternative<api::PairRun>(pair.run));
    CHECK(api::to_json(pair)["tunnel_height_m"] == 0.5);
}

TEST_CASE("simulate's time-in-mode keys are the modes' one spelling", "[api][simulate]") {
    api::SimulateRequest rocker = slider();
    rocker.box.half_height_m = 1.2;  // tan(alpha) = 0.25 < mu_s = 0.3: it can rock
    rocker.mu_s = 0.3;
    const auto keys = api::to_json(api::simulate(rocker))["time_in_mode_s"];
    for (const char* word : {"rest", "slide", "rock", "slide-rock", "flight"}) CHECK(keys.contains(word));
    CHECK_FALSE(keys.contains("slide_rock"));
}

TEST_CASE("simulate labels a record run with the record's name and scales its samples",
          "[api][simulate]") {
    api::SimulateRequest r = slider();
    r.excitation.sine.reset();
    r.excitation.horizontal = record(200);
    r.excitation.horizontal->accel_mps2[10] = 1.0;
    r.excitation.scale = 3.0;
    const api::SimulateResult result = api::simulate(r);
    CHECK(result.excitation_label == "pulse");
    // pga_g of the scaled samples: 3 m/s^2 over g = 9.81 m/s^2.
    CHECK(api::to_json(result)["pga_g"].get<double>() == Approx(3.0 / 9.81).epsilon(1e-12));
}

TEST_CASE("simulate refuses a request that mixes models, naming the field", "[api][simulate]") {
    api::SimulateRequest r = slider();
    r.excitation.horizontal = record(100);
    check_refused(r, "excitation");  // a sine and a record
    r = slider();
    r.excitation.vertical = record(100);
    check_refused(r, "excitation");  // a vertical without its horizontal
    r = slider();
    r.excitation.sine.reset();
    r.excitation.sine_y = sine(0.4);
    r.restitution = 0.5;
    check_refused(r, "restitution");  // the biaxial model has no rocking
    r.restitution.reset();
    r.flexible = dynamics::FlexibleMode{};
    check_refused(r, "flexible");
    r.flexible.reset();
    r.unit2 = api::JoinedUnit{slider().box, 0.3, std::nullopt, std::nullopt, 0.5};
    check_refused(r, "unit2");
    r = slider();
    r.unit2 = api::JoinedUnit{slider().box, 0.3, std::nullopt, std::nullopt, 0.5};
    r.record_series = true;
    check_refused(r, "unit2");
}

TEST_CASE("simulate's errors name the request's fields", "[api][simulate]") {
    api::SimulateRequest r = slider();
    r.cd_dt_s = 0.0;
    check_refused(r, "cd_dt_s");
    r = slider();
    r.box.half_width_m = 200.0;
    check_refused(r, "box.half_width_m");
    r = slider();
    r.unit2 = api::JoinedUnit{slider().box, 2.5, std::nullopt, std::nullopt, 0.5};
    check_refused(r, "unit2.mu_s");
    r.unit2->mu_s = 0.3;
    r.unit2->box.half_height_m = -1.0;
    check_refused(r, "unit2.box.half_height_m");
    r.unit2->box.half_height_m = 0.3;
    r.unit2->tunnel_height_m = -1.0;
    check_refused(r, "tunnel_height_m");
    r = slider();
    r.excitation.sine.reset();
    r.excitation.sine_y = sine(-0.4);
    check_refused(r, "sine_y.amplitude_g");
    r.excitation.sine_y = sine(0.4);
    r.box.half_height_m = 1.2;  // tan(alpha) = 0.25 < mu_s = 0.6 and 0.4 g: it would rock
    r.mu_s = 0.6;
    check_refused(r, "sine_y");
    r = slider();
    r.flexible = dynamics::FlexibleMode{};
    r.flexible->frequency_hz = 1001.0;
    check_refused(r, "flexible.f");
}

TEST_CASE("simulate refuses a central-difference step above the flexible mode's limit",
          "[api][simulate]") {
    // The command line's case (tests/dynamics/test_cli_flexible.cpp): the mode at 500 Hz is
    // below the rigid limit of these samples and its stability limit 9.15e-05 s below 1e-4 s.
    api::SimulateRequest r;
    r.box.half_width_m = 0.15;
    r.box.half_height_m = 0.6;
    r.box.mass_kg = 38.0;
    r.mu_s = 0.3;
    r.excitation.sine = sine(0.5);
    r.excitation.sine->duration_s = 5.0;
    r.flexible = dynamics::FlexibleMode{};
    r.flexible->frequency_hz = 500.0;
    r.integrator = dynamics::Integrator::central_difference;
    CHECK_THROWS_AS(api::simulate(r), NumericalError);
    r.cd_dt_s = 1e-5;
    CHECK_NOTHROW(api::simulate(r));
}

TEST_CASE("integrator names", "[api][simulate]") {
    CHECK(api::integrator_named("event") == dynamics::Integrator::event);
    CHECK(api::integrator_named("cd") == dynamics::Integrator::central_difference);
    CHECK_FALSE(api::integrator_named("rk4"));
}

}  // namespace freestand_test_api_test_simulate
