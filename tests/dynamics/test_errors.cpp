// Failure paths of the dynamics API: each names the field and what was expected.
#include <catch2/catch.hpp>
#include <limits>

#include "core/errors.hpp"
#include "helpers.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_dynamics_test_errors {

using namespace freestand;
using Catch::Matchers::Message;

TEST_CASE("sine_excitation rejects bad parameters", "[dynamics][errors]") {
    CHECK_THROWS_MATCHES(dynamics::sine_excitation({-0.1, 2.0, 5.0, 0.0, 0.0}), InputError,
                         Message("sine.amplitude_g: must be >= 0 g; got -0.1"));
    CHECK_THROWS_MATCHES(dynamics::sine_excitation({0.5, 0.0, 5.0, 0.0, 0.0}), InputError,
                         Message("sine.frequency_hz: value 0 must be a finite number > 0"));
    CHECK_THROWS_MATCHES(dynamics::sine_excitation({0.5, 2.0, -1.0, 0.0, 0.0}), InputError,
                         Message("sine.duration_s: value -1 must be a finite number > 0"));
    CHECK_THROWS_MATCHES(dynamics::sine_excitation({0.5, 2.0, 5.0, -1.0, 0.0}), InputError,
                         Message("sine.ramp_s: must be >= 0 s; got -1"));
    CHECK_THROWS_MATCHES(dynamics::sine_excitation({0.5, 2.0, 5.0, 0.0, -0.01}), InputError,
                         Message("sine.dt_s: value -0.01 must be a finite number > 0"));
}

TEST_CASE("excitation_from_record rejects a non-finite scale", "[dynamics][errors]") {
    CHECK_THROWS_MATCHES(
        dynamics::excitation_from_record(test::elcentro(), std::numeric_limits<double>::infinity()),
        InputError, Message("scale: must be finite; got inf"));
}

TEST_CASE("simulate rejects inconsistent inputs and settings", "[dynamics][errors]") {
    const auto model = dynamics::make_block_model(block::Block::uniform(0.15, 0.6, 38.0), 0.3);
    auto e = test::samples(0.0, {0.0, 1.0});
    CHECK_THROWS_MATCHES(dynamics::simulate(model, e), InputError,
                         Message("excitation dt_s: value 0 must be a finite number > 0"));
    e = test::samples(0.01, {0.0, 1.0}, {0.0});
    CHECK_THROWS_MATCHES(dynamics::simulate(model, e), InputError,
                         Message("excitation vertical_mps2: must be empty or as long as the "
                                 "horizontal samples"));
    e = test::samples(0.01, {0.0, 1.0});
    auto o = test::opts(dynamics::Integrator::central_difference, -1e-4);
    CHECK_THROWS_MATCHES(dynamics::simulate(model, e, o), InputError,
                         Message("cd_dt_s: value -0.0001 must be a finite number > 0"));
    o = test::opts();
    o.rel_tol = 0.0;
    CHECK_THROWS_MATCHES(dynamics::simulate(model, e, o), InputError,
                         Message("rel_tol: value 0 must be a finite number > 0"));
    o = test::opts();
    o.max_contact_step_s = 0.0;
    CHECK_THROWS_MATCHES(dynamics::simulate(model, e, o), InputError,
                         Message("max_contact_step_s (s): value 0 is out of range; expected (0, 1]"));
    o.max_contact_step_s = 2.0;
    CHECK_THROWS_MATCHES(dynamics::simulate(model, e, o), InputError,
                         Message("max_contact_step_s (s): value 2 is out of range; expected (0, 1]"));
    CHECK_THROWS_MATCHES(dynamics::make_block_model(block::Block::uniform(0.15, 0.6, 38.0), 0.3,
                                                    std::nullopt, std::nullopt, 0.5),
                         InputError,
                         Message("top_height_m: top height must be >= the CG height 0.6 m; got 0.5"));
}

}  // namespace freestand_test_dynamics_test_errors
