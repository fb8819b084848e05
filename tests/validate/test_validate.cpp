// The validation table: every row of docs/methods.md s.13, each complete.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "support/paths.hpp"
#include "support/shipped_validation.hpp"
#include "assess/verdict.hpp"
#include "core/errors.hpp"
#include "validate/specimens.hpp"
#include "validate/thesis.hpp"
#include "validate/validate.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_validate_test_validate {

namespace fs = std::filesystem;
using namespace freestand::validate;

namespace {

const Validation& shipped() { return freestand::test::shipped_validation(); }

const Row& row(const std::string& id) {
    const auto& rows = shipped().rows;
    const auto it = std::find_if(rows.begin(), rows.end(), [&](const Row& r) { return r.id == id; });
    if (it == rows.end()) FAIL("no row " << id);
    return *it;
}

// Table 3-2 of the thesis (s.3.3.3.1): critical angle alpha (rad) and diagonal length R (m).
struct Specimen {
    const char* key;
    double alpha_rad;
    double R_m;
};
constexpr Specimen table_3_2[] = {{"ts1", 0.245, 0.62}, {"ts2", 0.322, 0.47}, {"ts3", 0.463, 0.34}};
constexpr double g_mps2 = 9.81;

// Ishiyama's bound, the thesis's Eq. 3.41: V = 0.4 sqrt(8 g R (1 - cos a) / (3 cos a)), m/s.
double ishiyama_mps(const Specimen& s) {
    const double c = std::cos(s.alpha_rad);
    return 0.4 * std::sqrt(8.0 * g_mps2 * s.R_m * (1.0 - c) / (3.0 * c));
}

// The R (m) at which Eq. 3.41 gives v_mps for the specimen's alpha.
double ishiyama_R_m(const Specimen& s, double v_mps) {
    const double c = std::cos(s.alpha_rad);
    return (v_mps / 0.4) * (v_mps / 0.4) * 3.0 * c / (8.0 * g_mps2 * (1.0 - c));
}

}  // namespace

TEST_CASE("the validation has every row of the thesis comparison, each with the thesis's outcome",
          "[validate][slow]") {
    // s.3.3.4.1 (text of Fig. 3-13): all three overturned below 2 Hz; at 2 Hz TS1 and TS2
    // overturned and TS3 kept rocking; above, only peak angles (Fig. 3-13, lost) remain.
    for (const Specimen& s : table_3_2) {
        const std::string ts = s.key;
        for (const char* f : {"0.5", "1"}) CHECK(row(ts + "-" + f + "hz").thesis == "overturned");
        CHECK(row(ts + "-2hz").thesis ==
              (ts == "ts3" ? "kept rocking, did not overturn" : "overturned"));
        for (const char* f : {"3", "5", "10"})
            CHECK_THAT(row(ts + "-" + f + "hz").thesis, Catch::StartsWith("did not overturn"));
        CHECK(row(ts + "-ishiyama").unit == "m/s");
    }
    for (const char* id :
         {"gb-asce-0.2g-thesis-inputs", "gb-energy-0.2g-thesis-inputs",
          "pair-asce-0.2g-thesis-inputs", "pair-energy-0.2g-thesis-inputs",
          "gb-asce-0.2g-pipeline", "gb-energy-0.2g-pipeline", "gb-asce-0.3g-pipeline",
          "gb-energy-0.3g-pipeline", "pair-asce-0.2g-pipeline", "pair-energy-0.2g-pipeline",
          "gb-pvc-0.1g", "gb-pvc-0.15g", "gb-pvc-0.2g", "gb-pvc-0.3g", "gb-steel-pads-0.1g",
          "gb-steel-pads-0.2g", "gb-steel-pads-0.3g"})
        CHECK_NOTHROW(row(id));
}

TEST_CASE("every row has the thesis, the prediction, the difference and a reason where they "
          "disagree",
          "[validate][slow]") {
    const Validation& v = shipped();
    REQUIRE(v.groups.size() == 7);
    for (const Row& r : v.rows) {
        INFO(r.id);
        CHECK(std::any_of(v.groups.begin(), v.groups.end(),
                          [&](const Group& g) { return g.key == r.group; }));
        CHECK(!r.test.empty());
        CHECK(!r.thesis.empty());
        CHECK(!r.predicted.empty());
        CHECK(!r.difference.empty());
        CHECK(!r.sources.empty());
        if (r.agreement != Agreement::agrees) CHECK(!r.reason.empty());
        // Only sines can be beyond the table's stroke, and only outcome rows are sines.
        if (r.agreement == Agreement::not_runnable) CHECK(r.kind == Kind::outcome);
        if (r.thesis_value) {
            // The thesis's value is one the row cites, in the row's unit (thesis.cpp).
            REQUIRE(r.predicted_value);
            REQUIRE(r.difference_value);
            CHECK(std::any_of(r.sources.begin(), r.sources.end(), [&](const std::string& key) {
                const Fact& f = fact(key);
                return f.value && *f.value == *r.thesis_value && f.unit == r.unit;
            }));
        }
    }
    for (const Group& g : v.groups) {
        CHECK(!g.method.empty());
        CHECK(!g.tolerance.empty());
        CHECK(!g.assumptions.empty());
    }
    CHECK(v.notes.size() == 3);
    CHECK(v.case_files.size() == case_names().size());
}

TEST_CASE("the thesis's own arithmetic is reproduced, its TS3 bound is not", "[validate][slow]") {
    // s.5.5: 47 and 56 mm; s.6.4: 56 and 58 mm, all to the thesis's millimetre.
    const std::pair<const char*, double> thesis_mm[] = {{"gb-asce-0.2g-thesis-inputs", 47.0},
                                                        {"gb-energy-0.2g-thesis-inputs", 56.0},
                                                        {"pair-asce-0.2g-thesis-inputs", 56.0},
                                                        {"pair-energy-0.2g-thesis-inputs", 58.0}};
    for (const auto& [id, mm] : thesis_mm) {
        INFO(id);
        REQUIRE(row(id).predicted_value);
        CHECK(std::abs(*row(id).predicted_value - mm) <= 0.5);
        CHECK(row(id).agreement == Agreement::agrees);
    }
    // Table 3-6's bounds (0.283, 0.326, 0.499 m/s) beside Eq. 3.41 worked here from Table 3-2:
    // TS1 and TS2 to the thesis's three digits, TS3's 0.499 needs a longer diagonal.
    const double table_3_6_mps[] = {0.283, 0.326, 0.499};
    for (std::size_t i = 0; i < 3; ++i) {
        const Specimen& s = table_3_2[i];
        const Row& r = row(std::string(s.key) + "-ishiyama");
        INFO(r.id);
        REQUIRE(r.predicted_value);
        REQUIRE(r.thesis_value);
        CHECK(*r.predicted_value == Approx(ishiyama_mps(s)).epsilon(1e-9));
        CHECK(*r.thesis_value == table_3_6_mps[i]);
        const bool thesis_arithmetic = std::abs(ishiyama_mps(s) - table_3_6_mps[i]) <= 0.0005;
        CHECK(thesis_arithmetic == (i < 2));
        CHECK((r.agreement == Agreement::agrees) == thesis_arithmetic);
    }
    const Row& ts3 = row("ts3-ishiyama");
    CHECK(*ts3.difference_value == Approx(ishiyama_mps(table_3_2[2]) - 0.499).epsilon(1e-9));
    CHECK_THAT(ts3.reason, Catch::Contains(fmt::format("would need R = {:.2f} m",
                                                       ishiyama_R_m(table_3_2[2], 0.499))));
}

TEST_CASE("rigid-block rows state the thesis's outcome and explain TS3 at 2 Hz",
          "[validate][slow]") {
    // At 2 Hz the model overturns all three; the thesis saw TS1 and TS2 overturn, TS3 rock.
    for (const char* ts : {"ts1", "ts2"}) {
        const Row& r = row(std::string(ts) + "-2hz");
        INFO(r.id);
        CHECK_THAT(r.predicted, Catch::StartsWith("overturned"));
        CHECK(r.agreement == Agreement::agrees);
    }
    const Row& ts3 = row("ts3-2hz");
    CHECK_THAT(ts3.predicted, Catch::StartsWith("overturned"));
    CHECK(ts3.agreement == Agreement::differs);
    CHECK(ts3.reason.find("Eq. 3.41") != std::string::npos);
    CHECK(ts3.reason.find("Table 3-6") != std::string::npos);
    // Above 2 Hz: standing, the peak angle falling with frequency towards the thesis's "virtual
    // zero" (s.3.3.4.1), at 10 Hz below a twentieth of alpha.
    for (const Specimen& s : table_3_2) {
        std::vector<double> peak_rad;
        for (const char* f : {"3", "5", "10"}) {
            const Row& r = row(std::string(s.key) + "-" + f + "hz");
            INFO(r.id);
            CHECK_THAT(r.predicted, Catch::StartsWith("standing"));
            REQUIRE(r.predicted_value);
            CHECK(*r.predicted_value < s.alpha_rad);
            peak_rad.push_back(*r.predicted_value);
        }
        INFO(s.key);
        CHECK(peak_rad[0] > peak_rad[1]);
        CHECK(peak_rad[1] > peak_rad[2]);
        CHECK(peak_rad[2] < 0.05 * s.alpha_rad);
    }
    // The stroke caveat on every 0.5 and 1 Hz row.
    for (const char* id : {"ts1-0.5hz", "ts2-1hz", "ts3-0.5hz"})
        CHECK(row(id).reason.find("+-0.075 m (Table 3-1)") != std::string::npos);
    CHECK(row("ts1-10hz").predicted.rfind("standing", 0) == 0);
}

TEST_CASE("glove-box modes: rest at 0.1 g on PVC and to 0.3 g on steel pads", "[validate][slow]") {
    CHECK(row("gb-pvc-0.1g").predicted.rfind("rest", 0) == 0);
    CHECK(row("gb-pvc-0.2g").predicted.rfind("slide", 0) == 0);
    for (const char* id : {"gb-steel-pads-0.1g", "gb-steel-pads-0.2g", "gb-steel-pads-0.3g"}) {
        INFO(id);
        CHECK(row(id).predicted.rfind("rest", 0) == 0);
        // s.5.7: rest up to 0.3 g on steel pads: no slide in any history.
        REQUIRE(row(id).predicted_value);
        CHECK(*row(id).predicted_value == 0.0);
    }
}

TEST_CASE("validation without the shipped cases is an I/O error naming the file", "[validate]") {
    const fs::path none = fs::temp_directory_path() /
                          ("freestand_validate_no_cases_" + std::to_string(::getpid()));
    fs::create_directories(none);
    CHECK_FALSE(has_cases(none));
    CHECK(has_cases(fs::path(freestand::test::source_dir()) / "cases"));
    CHECK_THROWS_AS(run(none), freestand::IoError);
    CHECK_THROWS_WITH(run(none), Catch::Contains("glovebox-single.toml: cannot open file for "
                                                 "reading"));
    fs::remove_all(none);
}

TEST_CASE("the unbraced pair's tunnel demand stands beside the thesis at 0.2, 0.3 and 0.4 g",
          "[validate][slow]") {
    const Validation& v = shipped();
    std::vector<const Row*> rows;
    for (const Row& r : v.rows)
        if (r.group == "joined") rows.push_back(&r);
    REQUIRE(rows.size() == 4);
    CHECK(rows[3]->id == "braced-pair-integrity-0.4g");
    rows.pop_back();
    CHECK(rows[0]->id == "unbraced-pair-0.2g");
    CHECK(rows[0]->thesis_value == 7.0);
    CHECK(rows[0]->sources == std::vector<std::string>{"unbraced.relative_0.2g_mm"});
    CHECK(rows[1]->id == "unbraced-pair-0.3g");
    CHECK(rows[1]->agreement == Agreement::not_comparable);
    CHECK(rows[2]->id == "unbraced-pair-0.4g");
    CHECK(rows[2]->thesis_value == 25.0);
    for (const Row* r : rows) REQUIRE(r->predicted_value);
    // s.6.3: at most 7 mm up to 0.2 g, 25 mm at 0.4 g; the lower friction bound predicts more
    // at both, so both differ, and the relative slide grows with the level.
    CHECK(*rows[0]->predicted_value > 1.2 * 7.0);
    CHECK(rows[0]->agreement == Agreement::differs);
    CHECK(*rows[2]->predicted_value > 1.2 * 25.0);
    CHECK(rows[2]->agreement == Agreement::differs);
    CHECK(*rows[0]->predicted_value < *rows[1]->predicted_value);
    CHECK(*rows[1]->predicted_value < *rows[2]->predicted_value);
    for (const Row* r : rows) CHECK(r->predicted.find("common lower friction bound") != std::string::npos);
}

TEST_CASE("on steel pads the flexible-body model uplifts at 0.3-0.4 g without overturning, as the "
          "thesis's frequency-induced rocking", "[validate][slow][flexible]") {
    for (const char* id : {"gb-steel-flexible-0.3g", "gb-steel-flexible-0.4g"}) {
        INFO(id);
        const Row& r = row(id);
        CHECK(r.agreement == Agreement::agrees);
        CHECK(r.difference == "uplift, no overturning");
        CHECK(r.predicted.find(" 0 overturned") != std::string::npos);
    }
    // At 0.2 g the thesis expects rest: any uplift stays below the 0.003 rad low-motion threshold.
    CHECK(row("gb-steel-flexible-0.2g").difference == "no measurable rocking");
}

TEST_CASE("tally counts each kind apart, agreements among the rows that compare", "[validate]") {
    const auto make = [](Kind k, Agreement a) {
        Row r;
        r.kind = k;
        r.agreement = a;
        return r;
    };
    const std::vector<Row> rows{make(Kind::outcome, Agreement::agrees),
                                make(Kind::quantitative, Agreement::differs),
                                make(Kind::outcome, Agreement::not_runnable),
                                make(Kind::quantitative, Agreement::agrees),
                                make(Kind::quantitative, Agreement::not_comparable),
                                make(Kind::outcome, Agreement::differs),
                                make(Kind::outcome, Agreement::agrees)};
    const std::vector<Tally> t = tally(rows);
    REQUIRE(t.size() == 3);
    CHECK(t[0].kind == Kind::by_construction);
    CHECK(t[0].rows == 0);
    CHECK(t[0].compared() == 0);
    CHECK(t[1].kind == Kind::outcome);
    CHECK(t[1].rows == 4);
    CHECK(t[1].agrees == 2);
    CHECK(t[1].differs == 1);
    CHECK(t[1].not_runnable == 1);
    CHECK(t[1].compared() == 3);
    CHECK(t[2].kind == Kind::quantitative);
    CHECK(t[2].rows == 3);
    CHECK(t[2].agrees == 1);
    CHECK(t[2].differs == 1);
    CHECK(t[2].not_comparable == 1);
    CHECK(t[2].compared() == 2);
    CHECK(std::string(to_string(Kind::by_construction)) == "by construction");
    CHECK(std::string(to_string(Agreement::not_runnable)) == "not runnable");
}

TEST_CASE("the shipped validation's tallies add up, and its rows have the kinds they state",
          "[validate][slow]") {
    const Validation& v = shipped();
    const std::vector<Tally> t = tally(v.rows);
    int rows = 0;
    for (const Tally& k : t) {
        INFO(to_string(k.kind));
        CHECK(k.rows > 0);
        CHECK(k.agrees + k.differs + k.not_comparable + k.not_runnable == k.rows);
        rows += k.rows;
    }
    CHECK(rows == static_cast<int>(v.rows.size()));
    // The thesis's arithmetic with its own inputs, and the friction taken from the onset.
    for (const char* id : {"gb-asce-0.2g-thesis-inputs", "pair-energy-0.2g-thesis-inputs",
                           "ts3-ishiyama", "gb-pvc-0.15g", "braced-pair-integrity-0.4g"})
        CHECK(row(id).kind == Kind::by_construction);
    for (const char* id : {"ts1-2hz", "ts2-rest-0.3g-1hz", "ts3-random-0.8g", "gb-pvc-0.2g",
                           "gb-steel-flexible-0.3g"})
        CHECK(row(id).kind == Kind::outcome);
    for (const char* id :
         {"gb-asce-0.2g-pipeline", "braced-energy-0.2g-pipeline", "unbraced-pair-0.4g"})
        CHECK(row(id).kind == Kind::quantitative);
    // 6 of the 0.8 g sines (0.5 and 1 Hz) and 9 of Table 3-4's are beyond the stroke.
    CHECK(t[1].not_runnable == 15);
}

TEST_CASE("Table 3-4's rest tests: 66 sines, each not runnable exactly where beyond the stroke",
          "[validate][slow]") {
    int n = 0;
    for (const Row& r : shipped().rows) {
        if (r.group != "rigid-blocks-rest") continue;
        ++n;
        INFO(r.id);
        CHECK(r.kind == Kind::outcome);
        CHECK(r.thesis == "rest state: no rocking initiation (Table 3-4)");
        REQUIRE(r.predicted_value);
        CHECK(r.unit == "rad");
    }
    CHECK(n == 66);
    for (const RestRun& run : rest_runs()) {
        for (double f : rest_frequencies_hz()) {
            const Row& r =
                row(fmt::format("{}-rest-{:g}g-{:g}hz", run.specimen.key, run.amplitude_g, f));
            INFO(r.id);
            CHECK(std::find(r.sources.begin(), r.sources.end(), run.key) != r.sources.end());
            if (!table_can_play(run.amplitude_g, f)) {
                CHECK(r.agreement == Agreement::not_runnable);
                CHECK_THAT(r.reason, Catch::StartsWith("Not runnable on the thesis's table"));
            } else {
                // Rest is the no-motion line of docs/methods.md s.2 (0.003 rad).
                CHECK((r.agreement == Agreement::agrees) ==
                      (*r.predicted_value < freestand::assess::no_motion_rock_rad));
            }
        }
    }
    // 0.3 g at 1 Hz needs 74.5 mm: runnable; 0.33 g at 1 Hz needs 82 mm: not.
    CHECK(row("ts2-rest-0.3g-1hz").agreement != Agreement::not_runnable);
    CHECK(row("ts2-rest-0.33g-1hz").agreement == Agreement::not_runnable);
    // Below g tan(alpha) with mu 0.72 above the amplitude: no uplift, no slip at all.
    CHECK(row("ts1-rest-0.2g-2hz").predicted == "rest: no uplift, no slip");
    CHECK(*row("ts1-rest-0.2g-2hz").predicted_value == 0.0);
}

TEST_CASE("the 0.8 g sines at 0.5 and 1 Hz are not runnable and say so", "[validate][slow]") {
    for (const char* ts : {"ts1", "ts2", "ts3"}) {
        for (const char* f : {"0.5hz", "1hz"}) {
            const Row& r = row(std::string(ts) + "-" + f);
            INFO(r.id);
            CHECK(r.agreement == Agreement::not_runnable);
            CHECK_THAT(r.reason, Catch::StartsWith("Not runnable on the thesis's table"));
        }
        CHECK(row(std::string(ts) + "-2hz").agreement != Agreement::not_runnable);
    }
}

TEST_CASE("the random 0.8 g test: the outcome of most histories beside the thesis's",
          "[validate][slow]") {
    for (const char* ts : {"ts1", "ts2", "ts3"}) {
        const Row& r = row(std::string(ts) + "-random-0.8g");
        INFO(r.id);
        CHECK(r.kind == Kind::outcome);
        CHECK(r.group == "rigid-blocks-random");
        const bool thesis_overturned = std::string(ts) != "ts3";
        CHECK(r.thesis == (thesis_overturned ? "overturned" : "stood (sustained the shaking)"));
        REQUIRE(r.predicted_value);
        CHECK(*r.predicted_value >= 0.0);
        CHECK(*r.predicted_value <= 1.0);
        CHECK(r.unit == "fraction of histories");
        // freestand predicts overturning when more than half its histories overturn.
        const bool predicts = *r.predicted_value > 0.5;
        CHECK((r.agreement == Agreement::agrees) == (predicts == thesis_overturned));
        CHECK_THAT(r.reason, Catch::Contains("+-0.075 m (Table 3-1)"));
        CHECK(std::find(r.sources.begin(), r.sources.end(), "ts.random_outcome") !=
              r.sources.end());
        // The 3D body beside: under the table's one component along its axis it repeats the
        // planar block (docs/methods.md s.11 check 3), to within a tenth of the histories.
        std::smatch m;
        const std::regex body3d(
            "the 3D body \\(a square footprint assumed\\): overturned in (\\d+) of (\\d+)");
        REQUIRE(std::regex_search(r.predicted, m, body3d));
        const double n = std::stod(m[2].str());
        CHECK(std::abs(std::stod(m[1].str()) - *r.predicted_value * n) <= 0.1 * n);
    }
}

TEST_CASE("glove-box sliding: ASCE 4 at 0.1 g, the pair at 0.4 g and the braced pair",
          "[validate][slow]") {
    // Thesis values: s.5.5 (4 mm), s.6.4 (134 / 165 mm at 0.4 g, 4 mm at 0.1 g), s.7.4 (57,
    // 91, 134 mm energy; 4, 56, 105, 165 mm ASCE 4).
    const std::vector<std::pair<std::string, double>> expected{
        {"gb-asce-0.1g-pipeline", 4.0},         {"pair-asce-0.1g-pipeline", 4.0},
        {"pair-energy-0.4g-pipeline", 134.0},   {"pair-asce-0.4g-pipeline", 165.0},
        {"braced-energy-0.2g-pipeline", 57.0},  {"braced-energy-0.3g-pipeline", 91.0},
        {"braced-energy-0.4g-pipeline", 134.0}, {"braced-asce-0.1g-pipeline", 4.0},
        {"braced-asce-0.2g-pipeline", 56.0},    {"braced-asce-0.3g-pipeline", 105.0},
        {"braced-asce-0.4g-pipeline", 165.0}};
    for (const auto& [id, thesis_mm] : expected) {
        const Row& r = row(id);
        INFO(id);
        CHECK(r.kind == Kind::quantitative);
        CHECK(r.unit == "mm");
        REQUIRE(r.thesis_value);
        CHECK(*r.thesis_value == thesis_mm);
        REQUIRE(r.predicted_value);
        // The group's 20% tolerance, stated before comparing: the energy balance lands within
        // it at every level, ASCE 4's spectral estimate above it from 0.2 g.
        const bool within = std::abs(*r.predicted_value - thesis_mm) <= 0.2 * thesis_mm;
        CHECK((r.agreement == Agreement::agrees) == within);
        const bool energy = id.find("-energy-") != std::string::npos;
        const bool at_rest = id.find("-0.1g-") != std::string::npos;
        CHECK(within == energy);
        if (!energy && !at_rest) CHECK(*r.predicted_value > thesis_mm);
    }
    // The braced and the s.6.4 pair compare with one and the same assessment.
    for (const char* level : {"asce-0.1g", "asce-0.2g", "energy-0.3g", "asce-0.4g"}) {
        INFO(level);
        CHECK(*row(std::string("braced-") + level + "-pipeline").predicted_value ==
              *row(std::string("pair-") + level + "-pipeline").predicted_value);
    }
    // At 0.1 g the box stays at rest at the lower friction bound: freestand predicts no slide,
    // which the thesis's test saw, against its ASCE 4 value.
    const Row& low = row("gb-asce-0.1g-pipeline");
    CHECK(*low.predicted_value == 0.0);
    CHECK(low.agreement == Agreement::differs);
    CHECK(std::find(low.sources.begin(), low.sources.end(), "gb.test_rest_0.1") !=
          low.sources.end());
    CHECK(row("braced-pair-integrity-0.4g").agreement == Agreement::agrees);
}

}  // namespace freestand_test_validate_test_validate
