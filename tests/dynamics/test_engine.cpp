// The engines' shared skeleton (dynamics/engine.hpp): the chatter rule, the adaptive step's
// limits and the fixed-step driver, each on its own, as a new engine would use them.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "core/errors.hpp"
#include "dynamics/engine.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_dynamics_test_engine {

using namespace freestand;
using namespace freestand::dynamics::detail;

TEST_CASE("the chatter rule settles after 64 events in a row inside the interval") {
    ChatterGuard guard;
    constexpr double interval_s = 1e-9;
    // The first event opens the burst; the 64th after it inside the interval completes it.
    for (int i = 0; i < 64; ++i) CHECK_FALSE(guard.note(1.0, interval_s, "test integrator"));
    CHECK(guard.note(1.0, interval_s, "test integrator"));
    // An event after a pause starts again.
    CHECK_FALSE(guard.note(2.0, interval_s, "test integrator"));
    for (int i = 0; i < 100000; ++i) (void)guard.note(2.0, interval_s, "test integrator");
    CHECK_THROWS_WITH(guard.note(2.0, interval_s, "test integrator"),
                      "test integrator: events accumulate at t = 2 s without settling");
    CHECK_THROWS_AS(guard.note(2.0, interval_s, "test integrator"), NumericalError);
}

TEST_CASE("the adaptive step reaches the segment's end exactly and keeps a clipped step's length") {
    AdaptiveStep step;
    // The first proposal is 1 ms, here cut by the end 0.4 ms away.
    const double h = step.propose(0.0, 4e-4, 0.02, "test integrator");
    CHECK(h == 4e-4);
    CHECK(step.step_end(0.0, 4e-4) == 4e-4);
    // Accepted with room to grow: cut by the end, it keeps the longer step it was allowed.
    step.accept(1.5);
    CHECK(step.propose(4e-4, 1.0, 0.02, "test integrator") == 1e-3);
    // A step within round-off of the end is stretched onto it.
    const double end_s = 4e-4 + 1e-3 * (1.0 + 1e-14);
    CHECK(step.propose(4e-4, end_s, 0.02, "test integrator") == end_s - 4e-4);
    CHECK(step.step_end(4e-4, end_s) == end_s);
}

TEST_CASE("a rejected step shrinks, and a step below 1e-14 s is a NumericalError") {
    AdaptiveStep step;
    CHECK(step.propose(0.0, 1.0, 0.02, "test integrator") == 1e-3);
    step.reject(2.0);  // a rejection never grows the step
    CHECK(step.propose(0.0, 1.0, 0.02, "test integrator") == 1e-3);
    step.reject(0.2);
    CHECK(step.propose(0.0, 1.0, 0.02, "test integrator") == Approx(2e-4).epsilon(1e-15));
    step.retry_with(1e-15);
    CHECK_THROWS_WITH(step.propose(0.5, 1.0, 0.02, "test integrator"),
                      "test integrator: the step fell below 1e-14 s at t = 0.5 s");
}

TEST_CASE("the fixed-step driver takes n_sub steps per segment and stops where asked") {
    std::vector<double> steps, samples;
    auto step = [&](std::size_t, double t, double) {
        steps.push_back(t);
        return true;
    };
    auto sample = [&](std::size_t, double tb) {
        samples.push_back(tb);
        return false;
    };
    const FixedRun all = run_fixed_steps(0.01, 0.0025, 3, step, sample);
    CHECK_FALSE(all.stopped);
    CHECK(all.end_s == 0.01 * 3.0);  // sample times are k dt, as BaseMotion::t_k
    CHECK(steps.size() == 12);
    CHECK(steps[5] == 0.01 + 0.0025);
    CHECK(samples == std::vector<double>{0.01, 0.01 * 2.0, 0.01 * 3.0});

    // A step that asks to stop ends the run at its own end.
    const FixedRun stop = run_fixed_steps(
        0.01, 0.0025, 3, [](std::size_t k, double, double) { return k < 1; }, sample);
    CHECK(stop.stopped);
    CHECK(stop.end_s == 0.01 + 0.0025);
    // A sample that asks to stop ends it at the sample.
    const FixedRun at_sample = run_fixed_steps(
        0.01, 0.0025, 3, step, [](std::size_t k, double) { return k == 1; });
    CHECK(at_sample.stopped);
    CHECK(at_sample.end_s == 0.01 * 2.0);
}

TEST_CASE("a start is classified 1e-9 s after it, never past half the way to the sample") {
    CHECK(probe_time(1.0, 2.0) == 1.0 + 1e-9);
    const double near_s = 1.0 + 1e-9;
    CHECK(probe_time(1.0, near_s) == 1.0 + 0.5 * (near_s - 1.0));
    CHECK(probe_time(1.0, near_s) < near_s);
    CHECK(probe_time(1.0, 1.0) == 1.0);
}

}  // namespace freestand_test_dynamics_test_engine
