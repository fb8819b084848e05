// The engines' shared skeleton (dynamics/engine.hpp, event_search.hpp): the chatter rule, the
// adaptive step's limits, the fixed-step and event-driven drivers and the event search, each on
// its own, as a new engine would use them.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <optional>
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
    const RunEnd all = run_fixed_steps(0.01, 0.0025, 3, step, sample);
    CHECK_FALSE(all.stopped);
    CHECK(all.end_s == 0.01 * 3.0);  // sample times are k dt, as BaseMotion::t_k
    CHECK(steps.size() == 12);
    CHECK(steps[5] == 0.01 + 0.0025);
    CHECK(samples == std::vector<double>{0.01, 0.01 * 2.0, 0.01 * 3.0});

    // A step that asks to stop ends the run at its own end.
    const RunEnd stop = run_fixed_steps(
        0.01, 0.0025, 3, [](std::size_t k, double, double) { return k < 1; }, sample);
    CHECK(stop.stopped);
    CHECK(stop.end_s == 0.01 + 0.0025);
    // A sample that asks to stop ends it at the sample.
    const RunEnd at_sample = run_fixed_steps(
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

// A body for run_segments on sample times k * 0.01 s that records what the driver asks of it:
// it rests through segments [rest_from, rest_to), meets an event in the middle of every other
// segment, overturns in segment overturn_k and settles for good at settle_s.
struct ToyBody {
    std::size_t rest_from = 99, rest_to = 99, overturn_k = 99;
    double settle_s = 1e9;
    bool over = false;
    std::vector<double> advanced_to, samples;

    double t_k(std::size_t k) const { return 0.01 * static_cast<double>(k); }
    double mid(std::size_t k) const { return 0.5 * (t_k(k) + t_k(k + 1)); }
    RestRun rest_run(std::size_t k, std::size_t) const {
        if (k != rest_from) return {k, false};
        return {rest_to, t_k(rest_to) >= settle_s};
    }
    double advance(std::size_t& k, double t, double tb) {
        const double reached = (k % 2 == 1 && t < mid(k)) ? mid(k) : tb;
        if (k == overturn_k) over = true;
        advanced_to.push_back(reached);
        return reached;
    }
    bool overturned() const { return over; }
    void sample(std::size_t, double tb) { samples.push_back(tb); }
    bool ends_at(double tb) const { return tb >= settle_s; }
};

TEST_CASE("the event driver advances event by event to each segment's end and samples there") {
    ToyBody body;
    const RunEnd run = run_segments(body, 4);
    CHECK_FALSE(run.stopped);
    CHECK(run.end_s == body.t_k(4));
    // Segments 1 and 3 stop at their middle event first.
    CHECK(body.advanced_to == std::vector<double>{0.01, body.mid(1), 0.01 * 2.0, 0.01 * 3.0,
                                                  body.mid(3), 0.01 * 4.0});
    CHECK(body.samples == std::vector<double>{0.01, 0.01 * 2.0, 0.01 * 3.0, 0.01 * 4.0});
}

TEST_CASE("the event driver passes rest runs, and stops on settling or overturning") {
    ToyBody rests;
    rests.rest_from = 0;
    rests.rest_to = 3;
    const RunEnd passed = run_segments(rests, 4);
    CHECK_FALSE(passed.stopped);
    CHECK(rests.advanced_to == std::vector<double>{rests.mid(3), 0.01 * 4.0});  // segment 3 only
    CHECK(rests.samples == std::vector<double>{0.01 * 4.0});

    ToyBody settles_at_rest = rests;
    settles_at_rest.advanced_to.clear();
    settles_at_rest.samples.clear();
    settles_at_rest.settle_s = 0.03;
    const RunEnd rest_end = run_segments(settles_at_rest, 4);
    CHECK(rest_end.stopped);
    CHECK(rest_end.end_s == settles_at_rest.t_k(3));
    CHECK(settles_at_rest.advanced_to.empty());

    ToyBody settles;
    settles.settle_s = 0.02;
    const RunEnd settled = run_segments(settles, 4);
    CHECK(settled.stopped);
    CHECK(settled.end_s == 0.01 * 2.0);
    CHECK(settles.samples == std::vector<double>{0.01, 0.01 * 2.0});

    ToyBody overturns;
    overturns.overturn_k = 1;
    const RunEnd over = run_segments(overturns, 4);
    CHECK(over.stopped);
    CHECK(over.end_s == overturns.mid(1));  // the time reached, not the segment's end
    CHECK(overturns.samples == std::vector<double>{0.01});
}

enum class ToyEv { none, a, b, c };

TEST_CASE("the first event of a step is the earliest, and a tie goes to the first in order") {
    const std::array<ToyEv, 4> events = {ToyEv::b, ToyEv::none, ToyEv::a, ToyEv::c};
    auto at = [](double ta, double tb, double tc) {
        return [=](ToyEv e) -> std::optional<double> {
            const double te = e == ToyEv::a ? ta : e == ToyEv::b ? tb : tc;
            if (te < 0.0) return std::nullopt;
            return te;
        };
    };
    const EventAt<ToyEv> none = first_event(events, 1.0, at(-1.0, -1.0, -1.0));
    CHECK(none.event == ToyEv::none);
    CHECK(none.t_s == 1.0);
    const EventAt<ToyEv> earliest = first_event(events, 1.0, at(0.5, 0.7, 0.3));
    CHECK(earliest.event == ToyEv::c);
    CHECK(earliest.t_s == 0.3);
    const EventAt<ToyEv> tie = first_event(events, 1.0, at(0.5, 0.5, 0.6));
    CHECK(tie.event == ToyEv::b);
}

TEST_CASE("a sign change is located from +, after a rise out of 0, or at once from below") {
    auto line = [](double tq) { return 0.25 - tq; };
    CHECK_FALSE(sign_change(line, 0.0, 0.2, line(0.0), line(0.2)).has_value());
    CHECK(*sign_change(line, 0.0, 1.0, line(0.0), line(1.0)) == Approx(0.25).epsilon(1e-14));
    // 0 at the start and rising: the crossing after the rise, not the start.
    auto arch = [](double tq) { return tq * (0.5 - tq); };
    CHECK(*sign_change(arch, 0.0, 1.0, 0.0, arch(1.0)) == Approx(0.5).epsilon(1e-14));
    // 0 at the start and falling, or below 0: the event is at the start.
    auto down = [](double tq) { return -tq; };
    CHECK(*sign_change(down, 0.0, 1.0, 0.0, -1.0) == 0.0);
    CHECK(*sign_change(down, 0.1, 1.0, -0.1, -1.0) == 0.1);
}

TEST_CASE("a dip below 0 inside a step is found between positive ends") {
    // (t - 0.5)^2 - 0.01: positive at 0 and 1, below 0 on (0.4, 0.6).
    auto f = [](double tq) { return (tq - 0.5) * (tq - 0.5) - 0.01; };
    auto df = [](double tq) { return 2.0 * (tq - 0.5); };
    const std::optional<double> te = dip_below_zero(f, df, 0.0, 1.0, f(0.0), df(0.0), df(1.0));
    REQUIRE(te.has_value());
    CHECK(*te == Approx(0.4).epsilon(1e-14));
    // A minimum above 0 is no event.
    auto g = [](double tq) { return (tq - 0.5) * (tq - 0.5) + 0.01; };
    CHECK_FALSE(dip_below_zero(g, df, 0.0, 1.0, g(0.0), df(0.0), df(1.0)).has_value());
}

TEST_CASE("a rise scan finds the first positive probe, or stops at a negative one if asked") {
    // Negative on (0, 0.3), positive after: an excursion after a dip.
    auto f = [](double tq) { return tq - 0.3; };
    const RiseStart on = rise_scan(f, 0.0, 1.0, BelowZero::scan_on);
    CHECK(on.t_s == 0.375);  // probe 3 of 8
    CHECK(on.f == 0.375 - 0.3);
    const RiseStart ends = rise_scan(f, 0.0, 1.0, BelowZero::ends_scan);
    CHECK(ends.t_s == 0.0);
    CHECK(ends.f == 0.0);
}

TEST_CASE("a flight scan probes equal sub-steps until one holds the event") {
    std::vector<std::pair<double, double>> probes;
    const bool found = scan_flight(1.0, 4, [&](double prev, double tau) {
        probes.emplace_back(prev, tau);
        return tau > 0.6;
    });
    CHECK(found);
    CHECK(probes == std::vector<std::pair<double, double>>{{0.0, 0.25}, {0.25, 0.5}, {0.5, 0.75}});
    CHECK_FALSE(scan_flight(1.0, 4, [](double, double) { return false; }));
}

}  // namespace freestand_test_dynamics_test_engine
