// Contact mechanics: the section-2 classification, the slide-rock 3x3 system and overturning.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "dynamics/mechanics.hpp"
#include "helpers.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_dynamics_test_mechanics {

using namespace freestand;
using namespace freestand::dynamics::detail;
using dynamics::Mode;

TEST_CASE("uplift friction of a uniform block equals Shenton's mu_crit", "[dynamics][mechanics]") {
    // mu_crit(A) = (A (1 + 4 g^2) + 3 g) / (4 + g^2 + 3 A g), g = b/h (Shenton 1996,
    // docs/methods.md s.2); mu_crit(tan alpha) = tan alpha.
    const auto blk = block::Block::uniform(0.15, 0.6, 38.0);
    const double gam = 0.25, G = 9.81;
    for (double A : {0.25, 0.3, 0.5, 1.0}) {
        const double mu_crit = (A * (1.0 + 4.0 * gam * gam) + 3.0 * gam) / (4.0 + gam * gam + 3.0 * A * gam);
        const Geometry g = make_geometry(dynamics::make_block_model(blk, 1.0));
        const Accel a = rock_accel(g, 1, 0.0, 0.0, {-A * G, G});  // base to the left: right edge
        CHECK(std::abs(a.F) / a.N == Approx(mu_crit).epsilon(1e-12));
        if (A == 0.25) CHECK(mu_crit == Approx(gam).epsilon(1e-15));
        if (A == 0.25) continue;
        // Just above mu_crit: pure rock; just below (but above tan alpha): slide-rock.
        const auto above = make_geometry(dynamics::make_block_model(blk, mu_crit * 1.001));
        const auto below = make_geometry(dynamics::make_block_model(blk, std::max(0.2501, mu_crit * 0.999)));
        CHECK(classify_from_rest(above, {-A * G, G}).mode == Mode::rock);
        CHECK(classify_from_rest(below, {-A * G, G}).mode == Mode::slide_rock);
        CHECK(classify_from_rest(below, {-A * G, G}).s == 1);
    }
    // mu_s <= tan(alpha): slides, whatever A (section 2).
    const auto low = make_geometry(dynamics::make_block_model(blk, 0.2));
    CHECK(classify_from_rest(low, {-2.0 * G, G}).mode == Mode::slide);
    CHECK(classify_from_rest(low, {-2.0 * G, G}).sigma == 1);
    CHECK(classify_from_rest(low, {-0.2 * G, G}).mode == Mode::rest);
    CHECK(classify_from_rest(low, {0.0, -0.1}).mode == Mode::flight);
}

TEST_CASE("slide-rock 3x3 system reduces to rock when kinetic friction equals the need",
          "[dynamics][mechanics]") {
    // With mu_k = |F_rock| / N_rock and slip opposing F, the sliding contact carries exactly the
    // rocking reactions: u'' = 0 and the same theta''. Asymmetric block, either edge, theta' != 0.
    const auto blk = block::Block::general(0.12, 0.2, 0.5, 30.0, 1.7);
    for (int s : {-1, 1}) {
        const Base base{-0.4 * s * 9.81, 9.81 - 1.0};
        const double th = 0.05, om = 0.3;
        const Geometry g0 = make_geometry(dynamics::make_block_model(blk, 2.0));
        const Accel rock = rock_accel(g0, s, th, om, base);
        const double mu = std::abs(rock.F) / rock.N;
        const Geometry g = make_geometry(dynamics::make_block_model(blk, mu, mu));
        const Accel sr = slide_rock_accel(g, s, rock.F > 0.0 ? -1 : 1, th, om, base);
        CHECK(sr.u_dd == Approx(0.0).margin(1e-12));
        CHECK(sr.th_dd == Approx(rock.th_dd).epsilon(1e-12));
        CHECK(sr.N == Approx(rock.N).epsilon(1e-12));
    }
}

TEST_CASE("friction lifts a sliding block only if mu_k > tan(alpha)", "[dynamics][mechanics]") {
    const auto blk = block::Block::uniform(0.1, 0.5, 10.0);  // tan(alpha) = 0.2
    CHECK(classify_sliding(make_geometry(dynamics::make_block_model(blk, 0.3, 0.19)), 1.0).mode == Mode::slide);
    const auto g = make_geometry(dynamics::make_block_model(blk, 0.3, 0.25));
    CHECK(classify_sliding(g, -1.0).mode == Mode::slide_rock);
    CHECK(classify_sliding(g, -1.0).s == -1);
    const Accel a = slide_rock_accel(g, -1, -1, 0.0, 0.0, {0.0, 9.81});
    CHECK(a.th_dd > 0.0);
}

TEST_CASE("overturning: criteria and modes", "[dynamics][mechanics]") {
    const auto blk = block::Block::uniform(0.15, 0.6, 38.0);
    const double alpha = blk.alpha_rad(block::Edge::right);
    const auto model = dynamics::make_block_model(blk, 1.0);
    for (auto integ : {dynamics::Integrator::event, dynamics::Integrator::central_difference}) {
        auto o = test::opts(integ);
        // Released past alpha with the base at rest: nothing can bring it back (mode 2).
        o.initial_rotation_rad = 1.05 * alpha;
        auto r = dynamics::simulate(model, test::samples(0.01, {0.0, 0.0}), o).summary;
        CHECK(r.overturned);
        CHECK(*r.overturn_mode == 2);
        CHECK(r.overturn_criterion == dynamics::OverturnCriterion::past_alpha_after_excitation);
        // Released inside alpha: rocks back and settles.
        o.initial_rotation_rad = -0.95 * alpha;
        r = dynamics::simulate(model, test::samples(0.01, {0.0, 0.0}), o).summary;
        CHECK(!r.overturned);
        CHECK(r.impacts > 0);
    }
    // El Centro x3 on a steel-like base: rocks, impacts, then tips over (mode 1, theta = pi/2).
    const auto e = dynamics::excitation_from_record(test::elcentro(), 3.0);
    const auto r = dynamics::simulate(dynamics::make_block_model(blk, 0.8), e, test::opts()).summary;
    CHECK(r.overturned);
    CHECK(*r.overturn_mode == 1);
    CHECK(r.overturn_criterion == dynamics::OverturnCriterion::angle_half_pi);
    CHECK(r.rock_max_rad == Approx(std::numbers::pi / 2).epsilon(1e-12));
}

TEST_CASE("asymmetric block uplifts over the edge with the smaller alpha", "[dynamics][mechanics]") {
    // tan(alpha_L) = 0.2, tan(alpha_R) = 0.4; a base accelerating right tips it over the left
    // edge (docs/methods.md s.3 sign convention), so 0.3 g uplifts it one way only.
    const auto blk = block::Block::general(0.1, 0.2, 0.5, 30.0, 1.5);
    const auto model = dynamics::make_block_model(blk, 1.0);
    for (auto integ : {dynamics::Integrator::event, dynamics::Integrator::central_difference}) {
        const auto right = dynamics::simulate(model, test::samples(0.01, std::vector<double>(30, 0.3 * 9.81)), test::opts(integ));
        CHECK(right.summary.rock_max_rad > 0.0);
        CHECK(right.series[5].rotation_rad < 0.0);  // on the left edge
        const auto left = dynamics::simulate(model, test::samples(0.01, std::vector<double>(30, -0.3 * 9.81)), test::opts(integ));
        CHECK(left.summary.mode_changes == 0);
    }
}

TEST_CASE("mu_k < tan(alpha) < mu_s < mu_crit: the block slides flat", "[dynamics][mechanics]") {
    // Found by a randomized run (events piled up at one instant): static friction could lift
    // the right edge but the slipping contact cannot (slide-rock gives theta'' < 0 at theta = 0),
    // so the consistent motion is flat sliding (mu_k h < b_R: no uplift while sliding).
    const auto blk = block::Block::general(0.1442629869839388, 0.11351712022040122,
                                           0.99121111720226718, 72.115090827907579,
                                           30.795168046729575);
    const auto model = dynamics::make_block_model(blk, 0.12820233747383283, 0.10962314963478123);
    const Geometry g = make_geometry(model);
    const Base base{-2.971549, 9.81};
    CHECK(rock_accel(g, 1, 0.0, 0.0, base).th_dd > 0.0);
    CHECK(slide_rock_accel(g, 1, 1, 0.0, 0.0, base).th_dd < 0.0);
    const Start st = classify_from_rest(g, base);
    CHECK(st.mode == Mode::slide);
    CHECK(st.sigma == 1);
    const auto r = dynamics::simulate(model, test::samples(0.005, std::vector<double>(100, base.ax)),
                                      test::opts());
    CHECK(r.summary.rock_max_rad == 0.0);
    CHECK(r.summary.slide_max_m > 0.0);
}

TEST_CASE("slide-rock accelerations satisfy the three rows of the contact system",
          "[dynamics][mechanics]") {
    // Residuals of the rows (docs/methods.md s.3) for the eliminated solution, both edges and slip
    // directions, asymmetric block:
    //   M u'' + M s R c theta'' + sigma mu N = -M (s R sn w^2 + xg'')
    //   M R sn theta'' - N = M (R c w^2 - G)
    //   s I_c theta'' + (s R sn - sigma mu R c) N = 0
    const block::Block blk = block::Block::general(0.2, 0.35, 0.7, 50.0, 2.1);
    const Geometry g = make_geometry(dynamics::make_block_model(blk, 0.4));
    for (int s : {1, -1}) {
        for (int sigma : {1, -1}) {
            for (double th : {0.0, 0.05, 0.4}) {
                for (double w : {0.0, -1.3, 2.0}) {
                    const Base b{2.7 * s, 9.81 * 1.2};
                    const Accel a = slide_rock_accel(g, s, sigma, th, w, b);
                    const auto i = static_cast<std::size_t>(Geometry::index(s));
                    const double R = g.R[i], sn = std::sin(g.alpha[i] - th), c = std::cos(g.alpha[i] - th);
                    const double ds = s, dsig = sigma, mu = g.mu_k, M = g.M;
                    const double r1 = M * a.u_dd + M * ds * R * c * a.th_dd + dsig * mu * a.N + M * (ds * R * sn * w * w + b.ax);
                    const double r2 = M * R * sn * a.th_dd - a.N - M * (R * c * w * w - b.G);
                    const double r3 = ds * g.Ic * a.th_dd + (ds * R * sn - dsig * mu * R * c) * a.N;
                    const double scale = M * 9.81 * 10.0;
                    CHECK(std::abs(r1) < 1e-12 * scale);
                    CHECK(std::abs(r2) < 1e-12 * scale);
                    CHECK(std::abs(r3) < 1e-12 * scale);
                    CHECK(a.F == Approx(-dsig * mu * a.N));
                }
            }
        }
    }
}

}  // namespace freestand_test_dynamics_test_mechanics
