// The statistics of a simulated level (docs/methods.md s.6 step 3): the 84th percentile as an
// order statistic, NaN for sets without a value, exceedance counts with their exact interval.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include "assess/statistics.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_assess_test_statistics {

using namespace freestand::assess;

namespace {
std::vector<double> one_to(int n) {
    std::vector<double> v;
    for (int i = n; i >= 1; --i) v.push_back(i);  // descending: the order must not matter
    return v;
}
}  // namespace

TEST_CASE("the 84th percentile is the ceil(0.84 N)-th smallest peak", "[assess][statistics]") {
    CHECK(order_statistic(one_to(30), 0.84) == 26.0);  // ceil(25.2)
    CHECK(order_statistic(one_to(25), 0.84) == 21.0);  // 0.84 x 25 = 21 exactly, not 22
    CHECK(order_statistic(one_to(7), 0.84) == 6.0);    // ceil(5.88)
    CHECK(order_statistic(one_to(2), 0.84) == 2.0);
    CHECK(order_statistic(one_to(1), 0.84) == 1.0);
    CHECK(order_statistic(one_to(120), 0.84) == 101.0);  // ceil(100.8)
}

TEST_CASE("stats skip sets without a value and keep every set's value", "[assess][statistics]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const Stats s = stats_of({0.1, nan, 0.3, 0.2});
    CHECK(s.mean == Approx(0.2));
    CHECK(s.p84 == 0.3);
    CHECK(s.max == 0.3);
    REQUIRE(s.values.size() == 4);
    CHECK(std::isnan(s.values[1]));
    const Stats none = stats_of({nan, nan});
    CHECK(none.mean == 0.0);
    CHECK(none.max == 0.0);
    // A resample redoes them over the chosen sets, repeats counted.
    const Stats r = resample(s, {0, 0, 2});
    CHECK(r.values == std::vector<double>{0.1, 0.1, 0.3});
    CHECK(r.mean == Approx(0.5 / 3));
    CHECK(r.p84 == 0.3);
}

TEST_CASE("exceedances count sets beyond the limit, always-counted sets included",
          "[assess][statistics]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const Exceedance e = exceedance({0.01, 0.06, 0.05, 0.07}, 0.05);
    CHECK(e.k == 2);  // 0.05 is at the limit, not beyond it
    CHECK(e.n == 4);
    CHECK(e.ci95[0] > 0.0);
    CHECK(e.ci95[1] < 1.0);
    CHECK(e.ci95[0] < 0.5);
    CHECK(e.ci95[1] > 0.5);
    // Two overturned sets (NaN rotation) count once each.
    const Exceedance o = exceedance({0.1, nan, nan, 0.9}, 0.667, 2);
    CHECK(o.k == 3);
    CHECK(o.n == 4);
    const Exceedance zero = exceedance({0.1, 0.2}, 0.5);
    CHECK(zero.k == 0);
    CHECK(zero.ci95[0] == 0.0);
}

}  // namespace freestand_test_assess_test_statistics
