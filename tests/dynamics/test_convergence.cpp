// Convergence: the central-difference baseline approaches the event-driven answer at its
// expected order; the event-driven answer does not move when its tolerance tightens.
#include <catch2/catch.hpp>
#include <cmath>

#include "support/paths.hpp"
#include "helpers.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_dynamics_test_convergence {

using namespace freestand;
using dynamics::Integrator;

namespace {

// Observed order: least-squares slope of log2(error) against the number of halvings of dt.
double observed_order(const std::vector<double>& errors) {
    const double n = static_cast<double>(errors.size());
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < errors.size(); ++i) {
        const double x = static_cast<double>(i), y = std::log2(errors[i]);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    return -(n * sxy - sx * sy) / (n * sxx - sx * sx);
}

dynamics::Excitation pulse() {
    std::vector<double> ax(301, 0.0);
    for (std::size_t i = 0; i <= 100; ++i) {
        const double t = 0.01 * static_cast<double>(i);
        ax[i] = 4.905 * std::min(t / 0.5, 2.0 - t / 0.5);
    }
    return test::samples(0.01, ax);
}

// The event-driven answers a and b agree: the same impacts, mode changes and verdict, peaks and
// residual slip within rel.
void check_same_answer(const dynamics::Summary& a, const dynamics::Summary& b, double rel) {
    CHECK(a.impacts == b.impacts);
    CHECK(a.mode_changes == b.mode_changes);
    CHECK(a.overturned == b.overturned);
    CHECK(a.slide_max_m == Approx(b.slide_max_m).epsilon(rel).margin(1e-14));
    CHECK(a.rock_max_rad == Approx(b.rock_max_rad).epsilon(rel).margin(1e-14));
    CHECK(a.slide_residual_m == Approx(b.slide_residual_m).epsilon(rel).margin(1e-14));
}

dynamics::BlockModel block_06(double half_width_m, double mu) {
    return dynamics::make_block_model(block::Block::uniform(half_width_m, 0.6, 38.0), mu);
}

}  // namespace

TEST_CASE("central difference converges to the event-driven slide at second order",
          "[dynamics][convergence]") {
    // Smooth sliding phases are second order; the stick found by a sign check is up to one step
    // late, but the slip velocity is ~0 there, so it costs only O(dt^2) in displacement.
    const auto model = dynamics::make_block_model(block::Block::uniform(0.5, 0.5, 10.0), 0.2);
    const auto e = pulse();
    const double ref = dynamics::simulate(model, e, test::opts()).summary.slide_residual_m;
    std::vector<double> errs;
    for (double dt : {4e-4, 2e-4, 1e-4, 5e-5}) {
        const auto r = dynamics::simulate(model, e, test::opts(Integrator::central_difference, dt));
        errs.push_back(std::abs(r.summary.slide_residual_m - ref));
    }
    const double order = observed_order(errs);
    INFO("errors " << errs[0] << " " << errs[1] << " " << errs[2] << " " << errs[3] << " order " << order);
    CHECK(order > 1.8);
    CHECK(errs.back() < 1e-6 * ref);
}

TEST_CASE("central difference converges to the event-driven free rocking at first order",
          "[dynamics][convergence]") {
    // Impacts are found by the sign change of theta and reflected: first order in the impact
    // time, with an erratic constant (where the impact falls inside the step), hence a fit
    // over six halvings. Measured: largest rotation difference at the samples over 1.5 s.
    const auto blk = block::Block::uniform(0.2, 0.6, 20.0);
    const auto model = dynamics::make_block_model(blk, 1.0, std::nullopt, 0.9);
    auto o = test::opts();
    o.initial_rotation_rad = 0.5 * blk.alpha_rad(block::Edge::right);
    o.tail_s = 1.5;
    const auto e = test::samples(0.005, {0.0, 0.0});
    const auto ref = dynamics::simulate(model, e, o);
    std::vector<double> errs;
    for (double dt : {1e-3, 5e-4, 2.5e-4, 1.25e-4, 6.25e-5, 3.125e-5}) {
        auto oc = o;
        oc.integrator = Integrator::central_difference;
        oc.cd_dt_s = dt;
        const auto r = dynamics::simulate(model, e, oc);
        // Compare the rotation history at the samples.
        double worst = 0.0;
        for (std::size_t i = 0; i < std::min(r.series.size(), ref.series.size()); ++i)
            worst = std::max(worst, std::abs(r.series[i].rotation_rad - ref.series[i].rotation_rad));
        errs.push_back(worst);
    }
    const double order = observed_order(errs);
    INFO("errors " << errs[0] << " " << errs[2] << " " << errs[5] << " order " << order);
    CHECK(order > 0.8);
    CHECK(order < 1.5);
}

TEST_CASE("event-driven answer unchanged when the tolerance tightens", "[dynamics][convergence]") {
    const auto rec = test::elcentro();
    const auto blk = block::Block::uniform(0.15, 0.6, 38.0);
    struct Case { double pga_g, mu; };
    for (const Case c : {Case{0.6, 0.15}, Case{0.4, 0.8}, Case{0.6, 0.3}}) {
        const auto model = dynamics::make_block_model(blk, c.mu);
        const auto e = test::scaled_to(rec, c.pga_g);
        const auto loose = test::opts();  // default: rel 1e-9, abs 1e-11
        auto tight = test::opts();
        tight.rel_tol = 1e-12;
        tight.abs_tol = 1e-14;
        const auto a = dynamics::simulate(model, e, loose).summary;
        const auto b = dynamics::simulate(model, e, tight).summary;
        CHECK(a.overturned == b.overturned);
        // Measured at the default: 6.5e-9 relative (slide before an overturn, 0.6 g, mu 0.3),
        // 2.7e-10 for rock at 0.4 g, 0 for slide (Dormand-Prince steps: 6e-6 and 4e-8).
        CHECK(a.slide_max_m == Approx(b.slide_max_m).epsilon(1e-7).margin(1e-12));
        CHECK(a.rock_max_rad == Approx(b.rock_max_rad).epsilon(1e-7).margin(1e-12));
        CHECK(a.slide_residual_m == Approx(b.slide_residual_m).epsilon(1e-7).margin(1e-12));
    }
}

TEST_CASE("event-driven impacts inside a step are found: count unchanged at a tight tolerance",
          "[dynamics][convergence]") {
    // A near-elastic block (r = 0.98) barely lifting under El Centro #12 (x2.5, the 230
    // component as vertical): hundreds of impacts of tiny rebounds, where theta can dip below 0
    // and come back within one 5 ms step. 418 impacts: the earlier Dormand-Prince version of
    // this integrator at rel_tol 1e-13 (an independent reference; at its default tolerance,
    // reading only the step ends, it found 379, and the Taylor steps read at their ends 366).
    const auto h = core::read_at2(freestand::test::data_dir() + "/RSN175_IMPVALL.H_H-E12140.AT2");
    const auto v = core::read_at2(freestand::test::data_dir() + "/RSN175_IMPVALL.H_H-E12230.AT2");
    const auto e = dynamics::excitation_from_record(h, 2.5, &v, 2.5);
    const auto model = dynamics::make_block_model(block::Block::uniform(0.15, 0.45, 38.0), 0.72,
                                                  std::nullopt, 0.98);
    auto o = test::opts();
    o.record_series = false;
    auto tight = o;
    tight.rel_tol = 1e-13;
    tight.abs_tol = 1e-15;
    const auto a = dynamics::simulate(model, e, o).summary;
    const auto b = dynamics::simulate(model, e, tight).summary;
    CHECK(a.impacts == 418);
    CHECK(b.impacts == 418);
    CHECK(a.rock_max_rad == Approx(b.rock_max_rad).epsilon(1e-8));
}

TEST_CASE("event-driven answer unchanged when the same input is sampled 8x finer",
          "[dynamics][convergence]") {
    // Linear interpolation of a piecewise-linear input adds samples, not motion: the block sees
    // the same base acceleration, its steps are 8 times shorter and its event searches see
    // 8 times more step ends. Events located at the step ends instead of on the dense output
    // would move by up to a step (5 ms) and change the peaks at ~1e-3. The benchmark's slide,
    // rock and slide-rock cases (104, 26 and 38 mode changes; 148 and 145 impacts).
    const auto rec = test::elcentro();
    struct Case { double half_width_m, pga_g, mu; };
    for (const Case c : {Case{0.15, 0.5, 0.15}, Case{0.3, 0.9, 0.6}, Case{0.3, 0.9, 0.525}}) {
        const auto model = block_06(c.half_width_m, c.mu);
        const auto e = test::scaled_to(rec, c.pga_g);
        auto fine = e;
        fine.dt_s = e.dt_s / 8.0;
        fine.horizontal_mps2.clear();
        for (std::size_t i = 0; i + 1 < e.horizontal_mps2.size(); ++i)
            for (int j = 0; j < 8; ++j)
                fine.horizontal_mps2.push_back(e.horizontal_mps2[i] +
                                               (e.horizontal_mps2[i + 1] - e.horizontal_mps2[i]) * j / 8.0);
        fine.horizontal_mps2.push_back(e.horizontal_mps2.back());
        auto o = test::opts();
        o.record_series = false;
        const auto a = dynamics::simulate(model, e, o).summary;
        const auto b = dynamics::simulate(model, fine, o).summary;
        CAPTURE(c.half_width_m, c.mu);
        check_same_answer(a, b, 1e-8);  // measured: equal to 9 digits
    }
}

TEST_CASE("event-driven answer unchanged when contact steps are capped below the sample step",
          "[dynamics][convergence]") {
    // Friction exceeded and lift-off are read by their sign at step ends (impacts and slip
    // stops are searched inside): halving every contact step (2.5 ms on 5 ms samples) must not
    // find one more of them. Steps now end between samples too, an ulp short of one at t > 16 s
    // (where an ulp of t exceeds 1e-12 of the step), which left a step below 1e-14 s (Chi-Chi
    // at 32.005 s).
    // Measured on 90 cases (3 records, 2 blocks, 3 PGAs, 5 frictions): the same impacts, mode
    // changes and overturns, peaks within 1e-8 (3e-5 only after > 100 impacts).
    const auto elcentro = test::elcentro();
    const auto chichi = core::read_at2(freestand::test::data_dir() + "/RSN1546_CHICHI_TCU122-N.AT2");
    struct Case { const core::Record* rec; double half_width_m, pga_g, mu; };
    for (const Case c : {Case{&elcentro, 0.3, 0.9, 0.6},
                         Case{&elcentro, 0.3, 0.9, 0.525}, Case{&elcentro, 0.15, 0.9, 0.45},
                         Case{&chichi, 0.3, 0.9, 0.6}, Case{&chichi, 0.3, 0.9, 0.525}}) {
        const auto model = block_06(c.half_width_m, c.mu);
        const auto e = test::scaled_to(*c.rec, c.pga_g);
        auto o = test::opts();
        o.record_series = false;
        auto capped = o;
        capped.max_contact_step_s = 0.0025;
        const auto a = dynamics::simulate(model, e, o).summary;
        const auto b = dynamics::simulate(model, e, capped).summary;
        CAPTURE(c.rec->name, c.half_width_m, c.pga_g, c.mu);
        CHECK(b.steps > a.steps);  // the cap is applied
        check_same_answer(a, b, 1e-7);
    }
}

}  // namespace freestand_test_dynamics_test_convergence
