#include <catch2/catch.hpp>

#include "block/block.hpp"
#include "core/errors.hpp"
#include "rocking/checks.hpp"
#include "rocking/equivalent_linear.hpp"
#include "rocking/flexible.hpp"
#include "rocking/summary.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_rocking_test_errors {

using freestand::block::Block;
using freestand::block::Edge;
using freestand::spectra::Spectrum;
using namespace freestand::rocking;

namespace {
Spectrum flat(double psa_g, double damping) {
    Spectrum s;
    s.damping = damping;
    s.label = "flat";
    s.frequency_hz = {0.1, 1.0, 10.0};
    s.psa_g = {psa_g, psa_g, psa_g};
    return s;
}
const Block blk = Block::uniform(0.15, 0.6, 38.0);
}  // namespace

TEST_CASE("rocking error paths name the field", "[rocking][errors]") {
    Spectrum bad = flat(0.3, 0.05);
    bad.psa_g.pop_back();
    CHECK_THROWS_WITH(DampedSpectra({bad}), Catch::Contains("3 frequencies and 2 PSA values"));
    CHECK_THROWS_WITH(peak_pseudo_velocity_mps(bad), Catch::Contains("3 frequencies and 2 PSA"));
    const DampedSpectra ok({flat(0.3, 0.05)});
    CHECK_THROWS_WITH(ok.at(0.0), Catch::Contains("damping"));
    CHECK_THROWS_WITH(ok.at(1.0), Catch::Contains("damping"));
    const DampedSpectra gen([](double) { return Spectrum{}; }, "empty generator");
    CHECK_THROWS_WITH(gen.at(0.05), Catch::Contains("0 frequencies"));
    ElOptions o;
    o.pga_h_g = -0.1;
    CHECK_THROWS_WITH(equivalent_linear_rocking(blk, Edge::left, ok, {}, o), Catch::Contains("pga_h_g"));
    o.pga_h_g = 0.5;
    o.grid_points = 5;
    CHECK_THROWS_WITH(equivalent_linear_rocking(blk, Edge::left, ok, {}, o), Catch::Contains("grid_points"));
    o.grid_points = 2000;
    VerticalDemand v;
    v.ratio = -1.0;
    CHECK_THROWS_WITH(equivalent_linear_rocking(blk, Edge::left, ok, v, o), Catch::Contains("vertical ratio"));
    FlexibleInput fi;
    fi.fixed_base_hz = 5.0;
    fi.uplift_threshold_g = 0.0;
    CHECK_THROWS_WITH(flexible_screen(flat(0.3, 0.05), fi), Catch::Contains("uplift_threshold_g"));
    RockingInput in;
    in.pga_v_g = 1.0;
    CHECK_THROWS_WITH(rocking_checks(blk, in), Catch::Contains("pga_v_g"));
    in.pga_v_g.reset();
    in.pgv_mps = -1.0;
    CHECK_THROWS_WITH(rocking_checks(blk, in), Catch::Contains("pgv_mps"));
}

TEST_CASE("rocking_checks without a spectrum reports what is missing", "[rocking][summary]") {
    RockingInput in;
    in.mu_s = 0.5;
    const RockingChecks r = rocking_checks(blk, in);
    CHECK_FALSE(r.right.el);
    CHECK(r.spectral_reason == "needs a horizontal spectrum");
    CHECK_FALSE(r.initiation);
    CHECK(r.initiation_reason.find("peak horizontal acceleration") != std::string::npos);
    in.pga_h_g = 0.3;
    in.pgv_mps = 0.2;
    const RockingChecks r2 = rocking_checks(blk, in);
    REQUIRE(r2.initiation);
    CHECK(r2.initiation->governing().mode == freestand::sliding::Mode::rock);
    CHECK(*r2.pgv_below_ishiyama);  // 0.2 < 0.2823 m/s
}

TEST_CASE("the PGA defaults to the spectrum's last point, with a caution below 33 Hz",
          "[rocking][summary]") {
    RockingInput in;
    in.horizontal = DampedSpectra({flat(0.3, 0.05)});  // ends at 10 Hz
    const RockingChecks r = rocking_checks(blk, in);
    REQUIRE(r.pga_h_g);
    CHECK(*r.pga_h_g == 0.3);
    CHECK(r.pga_h_source ==
          "spectrum PSA at its highest frequency, 10 Hz < 33 Hz: may exceed the PGA; give the "
          "PGA explicitly");
    Spectrum wide = flat(0.3, 0.05);
    wide.frequency_hz.back() = 33.0;
    in.horizontal = DampedSpectra({wide});
    CHECK(rocking_checks(blk, in).pga_h_source == "spectrum ZPA");
    in.pga_h_g = 0.2;
    CHECK(rocking_checks(blk, in).pga_h_source == "given");
}

}  // namespace freestand_test_rocking_test_errors
