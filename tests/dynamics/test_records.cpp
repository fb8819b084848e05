// Real motion: the shipped records, scaled to slide and to rock, give the same answer from
// both integrators within the baseline's own error (estimated as |CD(dt) - CD(dt/2)| x 4,
// a first-order Richardson bound, plus a floor).
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "support/paths.hpp"
#include "helpers.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_dynamics_test_records {

using namespace freestand;
using dynamics::Integrator;

TEST_CASE("shipped records: event-driven and central difference agree", "[dynamics][records]") {
    const auto blk = block::Block::uniform(0.15, 0.6, 38.0);  // tan(alpha) = 0.25
    for (const char* name : {"RSN175_IMPVALL.H_H-E12140.AT2", "RSN175_IMPVALL.H_H-E12230.AT2",
                             "RSN1546_CHICHI_TCU122-N.AT2"}) {
        const auto rec = core::read_at2(std::string(freestand::test::data_dir()) + "/" + name);
        struct Case { double pga_g, mu; };
        for (const Case c : {Case{0.5, 0.15}, Case{0.3, 0.8}}) {
            INFO(name << " pga " << c.pga_g << " mu " << c.mu);
            const auto model = dynamics::make_block_model(blk, c.mu);
            const auto e = test::scaled_to(rec, c.pga_g);
            auto o = test::opts();
            o.record_series = false;
            const auto ed = dynamics::simulate(model, e, o).summary;
            o.integrator = Integrator::central_difference;
            o.cd_dt_s = 1e-4;
            const auto cd = dynamics::simulate(model, e, o).summary;
            o.cd_dt_s = 5e-5;
            const auto cd2 = dynamics::simulate(model, e, o).summary;
            CHECK(!ed.overturned);
            CHECK(ed.overturned == cd.overturned);
            const double tol_slide = 4.0 * std::abs(cd.slide_max_m - cd2.slide_max_m) + 1e-6;
            const double tol_rock = 4.0 * std::abs(cd.rock_max_rad - cd2.rock_max_rad) + 1e-5;
            CHECK(std::abs(ed.slide_max_m - cd.slide_max_m) <= tol_slide);
            CHECK(std::abs(ed.rock_max_rad - cd.rock_max_rad) <= tol_rock);
            if (c.mu < 0.25) CHECK(ed.slide_max_m > 1e-3);
            else CHECK(ed.rock_max_rad > 1e-4);
        }
    }
}

}  // namespace freestand_test_dynamics_test_records
