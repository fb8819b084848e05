// Spectrum type: log-log interpolation, frequency grids, the spectrum file format and the
// vector-horizontal combination.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "spectra/spectrum.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_spectra_test_spectrum {

namespace fs = std::filesystem;
using namespace freestand;

namespace {

spectra::Spectrum two_points() {
    spectra::Spectrum s;
    s.damping = 0.05;
    s.frequency_hz = {1.0, 10.0};
    s.psa_g = {0.1, 1.0};
    s.label = "two points";
    return s;
}

fs::path temp_file(const std::string& name, const std::string& text) {
    const fs::path p = fs::temp_directory_path() / ("freestand_spectra_test_" + name);
    std::ofstream(p) << text;
    return p;
}

}  // namespace

TEST_CASE("psa_at interpolates on log-log axes and extends by constant SD and constant PSA",
          "[spectra][spectrum]") {
    const auto s = two_points();
    CHECK(s.psa_at(1.0) == Approx(0.1).epsilon(1e-15));
    CHECK(s.psa_at(10.0) == Approx(1.0).epsilon(1e-15));
    // Log-log midpoint: f = sqrt(1 * 10), PSA = sqrt(0.1 * 1).
    CHECK(s.psa_at(std::sqrt(10.0)) == Approx(std::sqrt(0.1)).epsilon(1e-14));
    // Slope 1 on log-log between the points: PSA = 0.1 f.
    CHECK(s.psa_at(2.0) == Approx(0.2).epsilon(1e-14));
    // Below the first point SD = PSA / omega^2 is constant: PSA ~ f^2.
    CHECK(s.psa_at(0.5) == Approx(0.025).epsilon(1e-15));
    CHECK(s.psa_at(40.0) == Approx(1.0).epsilon(1e-15));
}

TEST_CASE("psa_at rejects non-positive frequencies and an inconsistent spectrum",
          "[spectra][spectrum]") {
    const auto s = two_points();
    CHECK_THROWS_WITH(s.psa_at(0.0),
                      Catch::Contains("f_hz: frequency 0 Hz must be finite and > 0"));
    CHECK_THROWS_AS(s.psa_at(std::nan("")), InputError);
    CHECK_THROWS_WITH(s.psa_at(std::nan("")),
                      Catch::Contains("f_hz: frequency nan Hz must be finite and > 0"));
    spectra::Spectrum bad = s;
    bad.psa_g.pop_back();
    CHECK_THROWS_WITH(bad.psa_at(1.0), Catch::Contains("has 2 frequencies and 1 PSA values"));
}

TEST_CASE("log_frequencies: 0.1-100 Hz at 100 per decade is 301 points with exact decades",
          "[spectra][spectrum]") {
    const auto f = spectra::log_frequencies(0.1, 100.0, 100);
    REQUIRE(f.size() == 301);
    CHECK(f.front() == 0.1);
    CHECK(f[100] == 1.0);
    CHECK(f[200] == 10.0);
    CHECK(f.back() == 100.0);
    for (std::size_t i = 1; i < f.size(); ++i)
        CHECK(f[i] / f[i - 1] == Approx(std::pow(10.0, 0.01)).epsilon(1e-12));
    // 0.1-50 Hz is 2.699 decades: 270 intervals keep >= 100 per decade and land on 50 Hz.
    const auto g = spectra::log_frequencies(0.1, 50.0, 100);
    CHECK(g.size() == 271);
    CHECK(g.back() == 50.0);
}

TEST_CASE("log_frequencies rejects bad ranges naming the argument", "[spectra][spectrum]") {
    CHECK_THROWS_WITH(spectra::log_frequencies(0.0, 10.0, 100),
                      Catch::Contains("fmin_hz: value 0 must be"));
    CHECK_THROWS_WITH(spectra::log_frequencies(10.0, 10.0, 100),
                      Catch::Contains("fmax_hz: fmax 10 Hz must be greater than fmin 10 Hz"));
    CHECK_THROWS_WITH(spectra::log_frequencies(0.1, 10.0, 0),
                      Catch::Contains("per_decade: 0 points per decade; expected an integer >= 1"));
}

TEST_CASE("spectrum file round trip keeps every value, the damping and the label",
          "[spectra][spectrum]") {
    spectra::Spectrum s;
    s.damping = 0.07;
    s.label = "round trip";
    s.frequency_hz = spectra::log_frequencies(0.1, 100.0, 100);
    for (double f : s.frequency_hz) s.psa_g.push_back(0.3 / (1.0 + std::pow(std::log(f / 5.0), 2)));
    const fs::path p = fs::temp_directory_path() / "freestand_spectra_test_roundtrip.csv";
    spectra::write_spectrum_csv(s, p, {"source: a test", "units: Hz and g"});
    const std::string text = core::read_text_file(p);
    CHECK(text.rfind("# source: a test\n# units: Hz and g\n# label: round trip\n# damping: "
                     "0.07\nfrequency_hz,psa_g\n",
                     0) == 0);
    const auto r = spectra::read_spectrum_csv(p);
    CHECK(r.damping == s.damping);
    CHECK(r.label == s.label);
    CHECK(r.frequency_hz == s.frequency_hz);
    CHECK(r.psa_g == s.psa_g);
}

TEST_CASE("spectrum file: a minimal hand-written file reads", "[spectra][spectrum]") {
    const auto p = temp_file(
        "ok.csv", "# from a vendor\n#damping:0.05\n\nfrequency_hz,psa_g\n1, 0.2\n10,0.5\r\n");
    const auto s = spectra::read_spectrum_csv(p);
    CHECK(s.damping == 0.05);
    CHECK(s.label == "freestand_spectra_test_ok");
    CHECK(s.frequency_hz == std::vector<double>{1.0, 10.0});
    CHECK(s.psa_g == std::vector<double>{0.2, 0.5});
}

TEST_CASE("spectrum file errors name file, line and what was expected", "[spectra][spectrum]") {
    const std::string head = "# damping: 0.05\nfrequency_hz,psa_g\n";
    struct Case {
        const char* name;
        std::string text;
        const char* message;
    };
    const Case cases[] = {
        {"nodamp.csv", "# a comment\nfrequency_hz,psa_g\n1,0.1\n",
         ":2: damping: no \"# damping: <ratio>\" line before the header"},
        {"nodamp_nohead.csv", "# only comments\n", ":1: damping: no \"# damping: <ratio>\" line"},
        {"header.csv", "# damping: 0.05\nfreq,psa\n1,0.1\n",
         ":2: header: expected the header \"frequency_hz,psa_g\"; got \"freq,psa\""},
        {"nohead.csv", "# damping: 0.05\n", ":1: header: no header line"},
        {"order.csv", head + "1,0.1\n2,0.2\n2,0.3\n",
         ":5: frequency_hz: frequency 2 Hz does not increase (previous row 2 Hz)"},
        {"psa0.csv", head + "1,0.1\n2,0\n", ":4: psa_g: PSA 0 g must be > 0"},
        {"psaneg.csv", head + "1,-0.1\n2,0.1\n", ":3: psa_g: PSA -0.1 g must be > 0"},
        {"fneg.csv", head + "-1,0.1\n2,0.1\n", ":3: frequency_hz: frequency -1 Hz must be > 0"},
        {"number.csv", head + "1,0.1\n2,0.2x\n", ":4: psa_g: expected a PSA in g; got \"0.2x\""},
        {"fnumber.csv", head + "1,0.1\nabc,0.2\n",
         ":4: frequency_hz: expected a frequency in Hz; got \"abc\""},
        {"nan.csv", head + "1,0.1\n2,nan\n", ":4: psa_g: expected a PSA in g; got \"nan\""},
        {"columns.csv", head + "1,0.1,5\n",
         ":3: expected two columns \"frequency_hz,psa_g\"; got \"1,0.1,5\""},
        {"onecol.csv", head + "1\n", ":3: expected two columns"},
        {"damp_range.csv", "# damping: 5\nfrequency_hz,psa_g\n1,0.1\n2,0.1\n",
         ":1: damping: value 5 is out of range; expected (0, 1)"},
        {"damp_bad.csv", "# damping: five\nfrequency_hz,psa_g\n",
         ":1: damping: expected a damping ratio in (0, 1)"},
        {"damp_twice.csv", "# damping: 0.05\n# damping: 0.1\nfrequency_hz,psa_g\n",
         ":2: damping: damping given twice"},
        {"late_comment.csv", head + "1,0.1\n# late\n2,0.2\n", ":4: comment after the header"},
        {"onerow.csv", head + "1,0.1\n", ":3: 1 data rows; expected at least 2"},
    };
    for (const auto& c : cases) {
        const auto p = temp_file(c.name, c.text);
        INFO(c.name);
        CHECK_THROWS_AS(spectra::read_spectrum_csv(p), InputError);
        CHECK_THROWS_WITH(spectra::read_spectrum_csv(p),
                          Catch::StartsWith(p.string()) && Catch::Contains(c.message));
    }
    CHECK_THROWS_AS(
        spectra::read_spectrum_csv(fs::temp_directory_path() / "freestand_no_such_file.csv"),
        IoError);
}

TEST_CASE("write_spectrum_csv refuses mismatched arrays", "[spectra][spectrum]") {
    auto s = two_points();
    s.psa_g.push_back(2.0);
    const fs::path p = fs::temp_directory_path() / "freestand_spectra_test_bad_write.csv";
    CHECK_THROWS_WITH(spectra::write_spectrum_csv(s, p, {}),
                      Catch::Contains("2 frequencies and 3 PSA values"));
}

TEST_CASE("vector horizontal: sqrt(SA_big^2 + 0.16 SA_small^2) per frequency",
          "[spectra][spectrum]") {
    auto h1 = two_points();
    h1.psa_g = {0.3, 0.5};
    auto h2 = two_points();
    h2.psa_g = {0.4, 0.2};
    const auto v = spectra::combine_vector_horizontal(h1, h2);
    // 1 Hz: H2 larger, sqrt(0.4^2 + 0.16 * 0.3^2) = sqrt(0.1744); 10 Hz: sqrt(0.25 + 0.16 * 0.04).
    CHECK(v.psa_g[0] == Approx(0.417612260356).epsilon(1e-11));
    CHECK(v.psa_g[1] == Approx(0.506359556047).epsilon(1e-11));
    CHECK(v.frequency_hz == h1.frequency_hz);
    // h2 is read at h1's frequencies by log-log interpolation.
    auto h3 = two_points();
    h3.frequency_hz = {0.5, 20.0};
    h3.psa_g = {0.01, 0.01};
    const auto w = spectra::combine_vector_horizontal(h1, h3);
    CHECK(w.psa_g[0] == Approx(std::sqrt(0.09 + 0.16 * 1e-4)).epsilon(1e-12));
    h2.damping = 0.1;
    CHECK_THROWS_WITH(spectra::combine_vector_horizontal(h1, h2),
                      Catch::Contains("damping: cannot combine spectra at dampings 0.05 and 0.1"));
}

}  // namespace freestand_test_spectra_test_spectrum
