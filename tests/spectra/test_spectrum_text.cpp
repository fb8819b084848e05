// The target spectrum file's bytes as the record readers take them: a UTF-8 BOM dropped, UTF-16
// refused with a message saying so.
#include <catch2/catch.hpp>

#include <string>

#include "core/errors.hpp"
#include "spectra/spectrum.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_spectra_test_spectrum_text {

using namespace freestand;

namespace {
const std::string kFile = "# damping: 0.05\nfrequency_hz,psa_g\n1,0.1\n10,1\n";
}  // namespace

TEST_CASE("a target spectrum file with a UTF-8 BOM reads as without it", "[spectra][spectrum]") {
    const spectra::Spectrum s = spectra::parse_spectrum_csv("\xEF\xBB\xBF" + kFile, "bom.csv");
    CHECK(s.damping == 0.05);
    CHECK(s.frequency_hz == std::vector<double>{1.0, 10.0});
    CHECK(s.label == "bom");
}

TEST_CASE("a UTF-16 target spectrum file is refused as UTF-16", "[spectra][spectrum]") {
    std::string utf16 = "\xFF\xFE";
    for (char c : kFile) utf16 += std::string{c, '\0'};
    CHECK_THROWS_WITH(spectra::parse_spectrum_csv(utf16, "w.csv"),
                      "w.csv:1: UTF-16 text; save it as UTF-8 (the encoding freestand reads)");
}

}  // namespace freestand_test_spectra_test_spectrum_text
