// Randomized robustness: asymmetric blocks, frictions, restitutions and inputs (records scaled
// up to 3.5x, strong vertical motion, sines up to 5 g) run to completion in both integrators
// with finite results. A wider version of this run (2400 cases) found the mu_k < tan(alpha) <
// mu_s case now covered in test_mechanics.cpp.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

#include "helpers.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_dynamics_test_randomized {

using namespace freestand;

namespace {
// Portable uniform [0, 1) from the top 53 bits (std:: distributions differ between libraries).
double uniform(std::mt19937_64& rng) {
    return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}
}  // namespace

TEST_CASE("randomized blocks and inputs complete with finite results", "[dynamics][hard]") {
    std::mt19937_64 rng(20261121);
    const auto rec = test::elcentro();
    for (int it = 0; it < 40; ++it) {
        const double bl = 0.05 + 0.5 * uniform(rng), br = 0.05 + 0.5 * uniform(rng);
        const double h = 0.1 + uniform(rng), m = 1.0 + 100.0 * uniform(rng);
        const double ic = m * ((bl + br) * (bl + br) / 4.0 + h * h) / 3.0 * (0.5 + uniform(rng));
        const auto blk = uniform(rng) < 0.5 ? block::Block::uniform(bl, h, m)
                                             : block::Block::general(bl, br, h, m, ic);
        const double mu = 1.2 * uniform(rng), mu_k = mu * (0.6 + 0.4 * uniform(rng));
        std::optional<double> r;
        if (uniform(rng) < 0.5) r = uniform(rng);
        const auto model = dynamics::make_block_model(blk, mu, mu_k, r);
        dynamics::Excitation e;
        if (it % 2 == 0) {
            const double scale = 0.5 + 3.0 * uniform(rng);
            e = dynamics::excitation_from_record(rec, scale);
            e.horizontal_mps2.resize(3001);  // 15 s keeps the test fast
            if (uniform(rng) < 0.4) {
                e.vertical_mps2.resize(e.horizontal_mps2.size());
                const double f = 0.5 + 2.0 * uniform(rng);
                for (std::size_t i = 0; i < e.vertical_mps2.size(); ++i)
                    e.vertical_mps2[i] = f * e.horizontal_mps2[(i + 400) % e.vertical_mps2.size()];
            }
        } else {
            e = dynamics::sine_excitation({0.05 + 5.0 * uniform(rng) * uniform(rng),
                                           0.3 + 20.0 * uniform(rng) * uniform(rng),
                                           1.0 + 3.0 * uniform(rng), 0.0, 0.0});
        }
        for (auto integ : {dynamics::Integrator::event, dynamics::Integrator::central_difference}) {
            INFO("case " << it << " integrator " << dynamics::integrator_name(integ));
            auto o = test::opts(integ);
            o.record_series = false;
            dynamics::Summary s;
            REQUIRE_NOTHROW(s = dynamics::simulate(model, e, o).summary);
            CHECK(std::isfinite(s.slide_max_m));
            CHECK(std::isfinite(s.rock_max_rad));
            CHECK(std::isfinite(s.top_accel_max_g));
            CHECK(s.rock_max_rad <= std::numbers::pi / 2 + 1e-3);
        }
    }
}

}  // namespace freestand_test_dynamics_test_randomized
