// The rest tests of Table 3-4 (thesis s.3.3.4.1): TS1-TS3 under sines at and just below the
// static uplift threshold X_s = g tan(alpha), which the thesis saw leave every specimen at rest.
#include <fmt/format.h>

#include <cmath>

#include "assess/verdict.hpp"
#include "validate/rows.hpp"
#include "validate/specimens.hpp"
#include "validate/thesis.hpp"

namespace freestand::validate {

namespace {

const char* const rest_key = "rigid-blocks-rest";

// Table 3-4's six runs: two amplitudes per specimen, run n on specimen (n - 1) / 2.
std::vector<RestRun> make_rest_runs() {
    std::vector<RestRun> runs;
    for (int n = 1; n <= 6; ++n) {
        const Specimen& s = specimens()[static_cast<std::size_t>((n - 1) / 2)];
        const std::string key = fmt::format("{}.rest_run{}_g", s.key, n);
        runs.push_back(RestRun{n, s, key, value(key)});
    }
    return runs;
}

// docs/methods.md s.2 "No motion": the report's own line between rest and motion.
bool no_motion(const dynamics::Summary& r) {
    return !r.overturned && r.rock_max_rad < assess::no_motion_rock_rad &&
           r.slide_max_m < assess::no_motion_slide_m;
}

std::string rest_outcome_text(const dynamics::Summary& r) {
    if (r.overturned) return fmt::format("overturned at {:.2f} s", *r.overturn_time_s);
    if (r.rock_max_rad == 0.0 && r.slide_max_m == 0.0) return "rest: no uplift, no slip";
    return fmt::format("{}: peak rotation {:.2g} rad ({:.2g} alpha), peak slip {:.2f} mm",
                       no_motion(r) ? "rest (below the no-motion thresholds)" : "rocks",
                       r.rock_max_rad, r.rock_max_over_alpha, r.slide_max_m * 1000.0);
}

Row rest_row(const RestRun& run, double f_hz) {
    const Specimen& s = run.specimen;
    const double uplift_g = std::tan(s.alpha_rad);
    Row row;
    row.group = rest_key;
    row.kind = Kind::outcome;
    row.id = fmt::format("{}-rest-{:g}g-{:g}hz", s.key, run.amplitude_g, f_hz);
    row.test = fmt::format(
        "{} on steel, {:g} g sine at {:g} Hz, {:g} s (Table 3-4 run {}; "
        "g tan(alpha) = {:.4f} g)",
        s.name, run.amplitude_g, f_hz, sine_duration_s(), run.number, uplift_g);
    row.thesis = "rest state: no rocking initiation (Table 3-4)";
    row.sources = {s.key + ".alpha_rad",
                   s.key + ".R_m",
                   s.key + ".mass_kg",
                   s.key + ".p_radps",
                   "steel.mu_s",
                   "steel.restitution",
                   run.key,
                   "ts.rest_frequencies",
                   "ts.rest_all",
                   "ts.duration_s"};
    const dynamics::Summary r =
        sine_run(specimen_model(s, value("steel.restitution")), run.amplitude_g, f_hz);
    row.predicted = rest_outcome_text(r);
    row.unit = "rad";
    row.predicted_value = r.rock_max_rad;
    const bool rest = no_motion(r);
    row.difference = rest ? "same outcome (rest)" : "opposite outcome";
    row.agreement = rest ? Agreement::agrees : Agreement::differs;
    if (!rest && run.amplitude_g > uplift_g) {
        row.reason = fmt::format(
            "The sine is {:.2f}% above the block's uplift threshold g tan(alpha) = {:.4f} g, "
            "alpha being {:g} rad as Table 3-2 prints it (three digits: tan(alpha) is known to "
            "+-{:.4f}); the thesis's X_s rounds the threshold to {:g} g and tests at it.",
            100.0 * (run.amplitude_g / uplift_g - 1.0), uplift_g, s.alpha_rad,
            0.0005 / (std::cos(s.alpha_rad) * std::cos(s.alpha_rad)), run.amplitude_g);
    } else if (!rest) {
        row.reason = "The block moves below its static thresholds: a difference in the model.";
    }
    apply_stroke_rule(row, run.amplitude_g, f_hz);
    return row;
}

}  // namespace

const std::vector<RestRun>& rest_runs() {
    static const std::vector<RestRun> runs = make_rest_runs();
    return runs;
}

const std::vector<double>& rest_frequencies_hz() {
    static const std::vector<double> list{0.5, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
    return list;
}

Group rest_group() {
    Group g;
    g.key = rest_key;
    g.title =
        "Rigid steel blocks TS1-TS3 at and below the uplift threshold: the rest tests of "
        "Table 3-4 (thesis s.3.3.4.1)";
    g.method =
        "Time-history simulation of the planar rigid block (docs/methods.md s.3, event-driven "
        "integrator) under each sine of Table 3-4, as for the 0.8 g sines.";
    g.tolerance = fmt::format(
        "Outcome rows: rest where the peak rotation stays below {:g} rad and the peak slip below "
        "{:g} mm (the no-motion thresholds of docs/methods.md s.2). A sine whose table travel A g "
        "/ (2 pi f)^2 exceeds the stroke (+-{:g} m, Table 3-1) is not runnable and not counted.",
        assess::no_motion_rock_rad, assess::no_motion_slide_m * 1000.0, table_stroke_m());
    g.assumptions = {
        "the blocks, friction (0.72) and restitution (0.98) of the 0.8 g sine rows",
        "Table 3-4's amplitudes, each at 0.5 Hz and 1 to 10 Hz by 1 Hz (66 sines, the thesis's "
        "count); the sine of docs/methods.md s.3 from rest, no ramp, 5 s (Table 3-4 states no "
        "duration: that of s.3.3.5.1's harmonic tests), then 10 s of free motion",
    };
    return g;
}

std::vector<Row> rest_rows() {
    std::vector<Row> rows;
    for (const RestRun& run : rest_runs()) {
        for (double f : rest_frequencies_hz()) rows.push_back(rest_row(run, f));
    }
    return rows;
}

}  // namespace freestand::validate
