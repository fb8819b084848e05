// Sample statistics and the exact binomial interval against published values.
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include "core/statistics.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_core_test_statistics {

using namespace freestand::core;

TEST_CASE("quantile interpolates between order statistics (type 7)", "[core][statistics]") {
    const std::vector<double> v{5.0, 1.0, 3.0, 2.0, 4.0};
    CHECK(quantile(v, 0.0) == 1.0);
    CHECK(quantile(v, 1.0) == 5.0);
    CHECK(quantile(v, 0.5) == 3.0);
    CHECK(quantile(v, 0.84) == Approx(4.36));  // position 4 x 0.84 = 3.36
    CHECK(quantile({7.0}, 0.84) == 7.0);
    CHECK(mean(v) == 3.0);
    CHECK_THROWS_AS(quantile({}, 0.5), std::invalid_argument);
    CHECK_THROWS_AS(quantile(v, 1.5), std::invalid_argument);
}

TEST_CASE("Clopper-Pearson 95% intervals match the exact binomial tables", "[core][statistics]") {
    // k = 0: upper = 1 - 0.025^(1/n); k = n: lower = 0.025^(1/n).
    auto ci = clopper_pearson(0, 7);
    CHECK(ci[0] == 0.0);
    CHECK(ci[1] == Approx(1.0 - std::pow(0.025, 1.0 / 7.0)).epsilon(1e-12));
    CHECK(ci[1] == Approx(0.4096).margin(1e-4));
    ci = clopper_pearson(7, 7);
    CHECK(ci[0] == Approx(std::pow(0.025, 1.0 / 7.0)).epsilon(1e-12));
    CHECK(ci[1] == 1.0);
    // Published: 3 of 10 -> [0.0667, 0.6525]; 1 of 5 -> [0.0051, 0.7164].
    ci = clopper_pearson(3, 10);
    CHECK(ci[0] == Approx(0.0667).margin(1e-4));
    CHECK(ci[1] == Approx(0.6525).margin(1e-4));
    ci = clopper_pearson(1, 5);
    CHECK(ci[0] == Approx(0.0051).margin(1e-4));
    CHECK(ci[1] == Approx(0.7164).margin(1e-4));
    CHECK_THROWS_AS(clopper_pearson(3, 2), std::invalid_argument);
    CHECK_THROWS_AS(clopper_pearson(0, 0), std::invalid_argument);
}

}  // namespace freestand_test_core_test_statistics
