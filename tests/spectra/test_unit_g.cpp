// Spectra in the caller's unit g (a case's site.g_mps2): PSA = omega^2 SD / g, and RG 1.60's
// displacement point converted with it.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "core/record.hpp"
#include "spectra/design.hpp"
#include "spectra/response.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_spectra_test_unit_g {

using namespace freestand;

namespace {
constexpr double standard_g_mps2 = 9.80665;
}

TEST_CASE("a record's PSA is in the caller's unit g", "[spectra][gravity]") {
    const core::Record r{"r", "s", "h1", 0.01, {0.0, 1.0, -2.0, 0.5, 0.0, 0.0, 0.0, 0.0}};
    const std::vector<double> f{1.0, 5.0};
    const spectra::ResponseSpectra rs =
        spectra::response_spectra(r, {0.05}, f, spectra::ResponseOptions{}, standard_g_mps2);
    const std::vector<double> psa = spectra::psa_g(r, 0.05, f, standard_g_mps2);
    for (std::size_t i = 0; i < f.size(); ++i) {
        const double w = 2.0 * 3.141592653589793 * f[i];
        CHECK(rs.psa_g[0][i] == Approx(w * w * rs.sd_m[0][i] / standard_g_mps2).epsilon(1e-14));
        CHECK(psa[i] == Approx(w * w * rs.sd_m[0][i] / standard_g_mps2).epsilon(1e-14));
    }
}

TEST_CASE("RG 1.60 below 0.25 Hz is its ground displacement in the caller's unit g",
          "[spectra][design][gravity]") {
    // Constant spectral displacement below D: PSA in g goes as 1 / g; PGA above 33 Hz.
    const std::vector<double> f{0.1, 50.0};
    const spectra::Spectrum thesis = spectra::rg160(0.3, 0.05, false, f);
    const spectra::Spectrum standard = spectra::rg160(0.3, 0.05, false, f, standard_g_mps2);
    CHECK(standard.psa_g[0] == Approx(thesis.psa_g[0] * 9.81 / standard_g_mps2).epsilon(1e-13));
    CHECK(standard.psa_g[1] == thesis.psa_g[1]);
}

}  // namespace freestand_test_spectra_test_unit_g
