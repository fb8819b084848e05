#include "validate/specimens.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/units.hpp"
#include "rocking/checks.hpp"
#include "validate/rows.hpp"
#include "validate/thesis.hpp"

namespace freestand::validate {

namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;
const char* const group_key = "rigid-blocks";

std::string freq_key(double f_hz) { return fmt::format("{:g}hz", f_hz); }

// Table 3-6 gives the recorded table velocity only for the runs at 0.5, 1 and 2 Hz.
bool has_table_velocity(double f_hz) { return f_hz <= 2.0; }
double table_velocity_mps(const Specimen& s, double f_hz) {
    return value(fmt::format("{}.v_{:g}hz_mps", s.key, f_hz));
}

// Amplitude of a sine whose velocity amplitude A g / (2 pi f) is the recorded velocity.
double implied_amplitude_g(double v_mps, double f_hz) {
    return two_pi * f_hz * v_mps / thesis_g_mps2;
}

std::string outcome_text(const dynamics::Summary& s) {
    if (s.overturned) {
        return fmt::format("overturned at {:.2f} s (mode {}, {})", *s.overturn_time_s,
                           *s.overturn_mode,
                           *s.overturn_mode == 1 ? "after impacts" : "without impact");
    }
    if (s.rock_max_rad == 0.0) return "standing; no uplift";
    return fmt::format("standing; peak rotation {} rad = {:.2f} alpha", sig(s.rock_max_rad),
                       s.rock_max_over_alpha);
}

std::string short_outcome(const dynamics::Summary& s) {
    if (s.overturned) return "overturns";
    return fmt::format("keeps it standing (peak {} rad = {:.2f} alpha)", sig(s.rock_max_rad),
                       s.rock_max_over_alpha);
}

std::string test_text(const Specimen& s, double f_hz) {
    return fmt::format("{} (alpha {:.3f} rad, R {:.2f} m, {:g} kg) on steel, {:g} g sine at {:g} Hz, "
                       "{:g} s",
                       s.name, s.alpha_rad, s.R_m, s.mass_kg, sine_amplitude_g(), f_hz,
                       sine_duration_s());
}

// What the model gives at the amplitude the recorded table velocity implies (Table 3-6).
std::string implied_amplitude_text(const Specimen& s, double f_hz) {
    const double v = table_velocity_mps(s, f_hz);
    const double a = implied_amplitude_g(v, f_hz);
    const auto implied = sine_run(specimen_model(s, value("steel.restitution")), a, f_hz);
    return fmt::format(
        "The recorded table velocity {:g} m/s (Table 3-6) is the velocity amplitude of a "
        "{:.2f} g sine at {:g} Hz: at {:.2f} g the model {}.",
        v, a, f_hz, a, short_outcome(implied));
}

// What the model gives with Housner's restitution instead of the measured average.
std::string housner_text(const Specimen& s, double f_hz, const dynamics::Summary& at_08) {
    const double r_housner = specimen_block(s).housner_restitution(block::Edge::right);
    const auto housner = sine_run(specimen_model(s, r_housner), sine_amplitude_g(), f_hz);
    if (housner.overturned == at_08.overturned) return "";
    return fmt::format(
        " The restitution 0.98 is the average on steel (Table 3-3), and the thesis found it "
        "falling from TS1 to TS3 (s.3.3.4.3); with Housner's r = {:.2f} for this block the model "
        "{} at {:g} g.",
        r_housner, short_outcome(housner), sine_amplitude_g());
}

// The thesis's velocity bound against its own formula (Eq. 3.41).
std::string ishiyama_text(const Specimen& s, double f_hz) {
    if (!has_table_velocity(f_hz)) return "";
    const double v_thesis = value(s.key + ".vpeak_mps");
    const double v_formula =
        rocking::ishiyama_velocity_mps(specimen_block(s), block::Edge::right);
    const double v_table = table_velocity_mps(s, f_hz);
    if (!(v_formula < v_table && v_table <= v_thesis)) return "";
    return fmt::format(
        " The thesis explains the survival by Vpeak {:g} m/s > {:g} m/s recorded, but its own "
        "Eq. 3.41 with Table 3-2's R and alpha gives {:.3f} m/s, below the recorded velocity: "
        "the bound does not rule overturning out.",
        v_thesis, v_table, v_formula);
}

Row sine_row(const Specimen& s, double f_hz) {
    Row row;
    row.group = group_key;
    row.id = fmt::format("{}-{}", s.key, freq_key(f_hz));
    row.kind = Kind::outcome;
    row.test = test_text(s, f_hz);
    row.sources = {s.key + ".alpha_rad", s.key + ".R_m", s.key + ".mass_kg", s.key + ".p_radps",
                   "steel.mu_s", "steel.restitution", "ts.sine_g", "ts.duration_s"};
    const auto run = sine_run(specimen_model(s, value("steel.restitution")), sine_amplitude_g(),
                              f_hz);
    row.predicted = outcome_text(run);
    if (!run.overturned) {
        row.unit = "rad";
        row.predicted_value = run.rock_max_rad;
    }
    if (has_table_velocity(f_hz)) {
        const bool observed = thesis_overturned(s, f_hz);
        row.thesis = observed ? "overturned" : "kept rocking, did not overturn";
        row.sources.push_back(f_hz < 2.0 ? "ts.overturn_below_2hz" : "ts.overturn_2hz");
        const bool same = observed == run.overturned;
        row.difference = same ? "same outcome" : "opposite outcome";
        row.agreement = same ? Agreement::agrees : Agreement::differs;
        std::string reason;
        if (!same) {
            reason += (reason.empty() ? "" : " ") +
                      std::string("Candidate reasons, each run through the model:");
        }
        reason += (reason.empty() ? "" : " ") + implied_amplitude_text(s, f_hz);
        if (!same) {
            reason += housner_text(s, f_hz, run) + ishiyama_text(s, f_hz);
            row.sources.insert(row.sources.end(),
                               {s.key + ".vpeak_mps", "ts.ishiyama_eq",
                                "ts.restitution_slenderness"});
        }
        row.sources.insert(row.sources.end(),
                           {fmt::format("{}.v_{:g}hz_mps", s.key, f_hz), "ts.velocity_integrated",
                            "ts.stroke_m"});
        row.reason = reason;
        apply_stroke_rule(row, sine_amplitude_g(), f_hz);
        return row;
    }
    row.thesis =
        "did not overturn; peak rotation only in Fig. 3-13 (lost), falling with frequency, "
        "'virtual zero' at the highest";
    row.sources.insert(row.sources.end(), {"ts.higher_frequencies", "ts.virtual_zero"});
    row.difference = run.overturned ? "opposite outcome" : "same outcome (no overturn)";
    row.agreement = run.overturned ? Agreement::differs : Agreement::agrees;
    row.reason = "The thesis's peak rotations are in Fig. 3-13, lost in the text: the outcome is "
                 "compared, the angle is not.";
    return row;
}

Row ishiyama_row(const Specimen& s) {
    Row row;
    row.group = group_key;
    row.id = s.key + "-ishiyama";
    // The thesis's formula with the thesis's R and alpha: a check of its arithmetic.
    row.kind = Kind::by_construction;
    row.test = fmt::format("{} Ishiyama velocity bound, Eq. 3.41 with Table 3-2's R and alpha",
                           s.name);
    const double v_thesis = value(s.key + ".vpeak_mps");
    const double v = rocking::ishiyama_velocity_mps(specimen_block(s), block::Edge::right);
    row.thesis = fmt::format("Vpeak {:g} m/s (Table 3-6)", v_thesis);
    row.predicted = fmt::format("{:.4f} m/s (rocking::ishiyama_velocity_mps)", v);
    row.sources = {s.key + ".alpha_rad", s.key + ".R_m", s.key + ".vpeak_mps", "ts.ishiyama_eq"};
    compare_numbers(row, v_thesis, v, "m/s", 0.0, 0.01);
    if (row.agreement == Agreement::differs) {
        // V grows as sqrt(R) at fixed alpha (Eq. 3.41).
        const double r_needed = s.R_m * (v_thesis / v) * (v_thesis / v);
        row.reason = fmt::format(
            "The thesis's Vpeak does not follow from its Eq. 3.41 with its own R {:g} m and "
            "alpha {:g} rad: {:g} m/s would need R = {:.2f} m. A slip in the thesis's "
            "arithmetic, not a model difference.",
            s.R_m, s.alpha_rad, v_thesis, r_needed);
    }
    return row;
}

}  // namespace

const std::vector<Specimen>& specimens() {
    static const std::vector<Specimen> list = [] {
        std::vector<Specimen> out;
        for (const char* key : {"ts1", "ts2", "ts3"}) {
            const std::string k = key;
            out.push_back(Specimen{fmt::format("TS{}", k.back()), k, value(k + ".alpha_rad"),
                                   value(k + ".R_m"), value(k + ".mass_kg"),
                                   value(k + ".p_radps")});
        }
        return out;
    }();
    return list;
}

double sine_amplitude_g() { return value("ts.sine_g"); }
double sine_duration_s() { return value("ts.duration_s"); }
double table_stroke_m() { return value("ts.stroke_m"); }

double sine_travel_m(double amplitude_g, double frequency_hz) {
    return amplitude_g * thesis_g_mps2 / (two_pi * frequency_hz * two_pi * frequency_hz);
}

bool within_stroke(double travel_m) { return travel_m <= table_stroke_m(); }

bool table_can_play(double amplitude_g, double frequency_hz) {
    return within_stroke(sine_travel_m(amplitude_g, frequency_hz));
}

void apply_stroke_rule(Row& row, double amplitude_g, double frequency_hz) {
    const double need_m = sine_travel_m(amplitude_g, frequency_hz);
    if (within_stroke(need_m)) return;
    row.agreement = Agreement::not_runnable;
    const std::string why = fmt::format(
        "Not runnable on the thesis's table: a {:g} g sine at {:g} Hz needs +-{:.3f} m of table "
        "travel (A g / (2 pi f)^2); the table has +-{:.3f} m (Table 3-1), so the test cannot have "
        "been this input (see the notes). Shown, not counted.",
        amplitude_g, frequency_hz, need_m, table_stroke_m());
    row.reason = row.reason.empty() ? why : why + " " + row.reason;
    if (std::find(row.sources.begin(), row.sources.end(), "ts.stroke_m") == row.sources.end())
        row.sources.push_back("ts.stroke_m");
}

const std::vector<double>& sine_frequencies_hz() {
    static const std::vector<double> list{0.5, 1.0, 2.0, 3.0, 5.0, 10.0};
    return list;
}

block::Block specimen_block(const Specimen& s) {
    const double b = s.R_m * std::sin(s.alpha_rad);
    const double h = s.R_m * std::cos(s.alpha_rad);
    // docs/methods.md s.1: p^2 = M g R / I_O and I_O = I_c + M R^2.
    const double i_edge = s.mass_kg * thesis_g_mps2 * s.R_m / (s.p_radps * s.p_radps);
    return block::Block::general(b, b, h, s.mass_kg, i_edge - s.mass_kg * s.R_m * s.R_m);
}

dynamics::BlockModel specimen_model(const Specimen& s, double restitution) {
    const double mu = value("steel.mu_s");
    return dynamics::make_block_model(specimen_block(s), mu, mu, restitution);
}

dynamics::Summary sine_run(const dynamics::BlockModel& model, double amplitude_g,
                           double frequency_hz) {
    dynamics::SineSpec spec;
    spec.amplitude_g = amplitude_g;
    spec.frequency_hz = frequency_hz;
    spec.duration_s = sine_duration_s();
    dynamics::Options opt;
    opt.record_series = false;
    opt.g_mps2 = thesis_g_mps2;
    return dynamics::simulate(model, dynamics::sine_excitation(spec), opt).summary;
}

bool thesis_overturned(const Specimen& s, double frequency_hz) {
    // s.3.3.4.1: all three overturned below 2 Hz; at 2 Hz TS1 and TS2 did, TS3 kept rocking.
    if (frequency_hz < 2.0) return true;
    if (frequency_hz == 2.0) return s.key != "ts3";
    return false;
}

Group specimen_group() {
    Group g;
    g.key = group_key;
    g.title = "Rigid steel blocks TS1-TS3 under 0.8 g sines (thesis s.3.3.4.1)";
    g.method =
        "Time-history simulation of the planar rigid block (docs/methods.md s.3, event-driven "
        "integrator) under the thesis's sine; Ishiyama's bound (docs/methods.md s.5) from "
        "rocking::ishiyama_velocity_mps.";
    g.tolerance =
        "Outcomes (overturned or not) must match. The velocity bound agrees within 1% (the "
        "thesis prints three digits and rounds R to the centimetre).";
    g.assumptions = {
        "Each specimen is a rigid planar block with Table 3-2's alpha, R and M; b = R sin(alpha), "
        "h = R cos(alpha); I_c = M g R / p^2 - M R^2 from Table 3-2's p (headed Hz, but the "
        "values are rad/s: a uniform TS1 would have p = sqrt(3 g / 4 R) = 3.44 rad/s; the "
        "thin-walled box has 3.34)",
        "friction mu_s = mu_k = 0.72 (steel, s.3.3.3.2); restitution 0.98 (steel, average, "
        "Table 3-3) on angular velocity at every impact",
        "input: the sine of docs/methods.md s.3 (from rest at t = 0, full amplitude at once, no "
        "ramp: the thesis states none), 0.8 g (Table 3-5), 5 s (the duration s.3.3.5.1 gives for "
        "the harmonic tests 'similar to the case of pure rocking'), then 10 s of free motion",
        "planar motion: the out-of-plane rocking the thesis recorded (0.6 g lateral at 2 Hz, "
        "s.3.3.4.2) is not modelled",
        fmt::format("g = {} m/s^2", units::g_mps2),
    };
    return g;
}

std::vector<Row> specimen_rows() {
    std::vector<Row> rows;
    for (const Specimen& s : specimens()) {
        for (double f : sine_frequencies_hz()) rows.push_back(sine_row(s, f));
    }
    for (const Specimen& s : specimens()) rows.push_back(ishiyama_row(s));
    return rows;
}

std::vector<std::string> specimen_notes() {
    std::vector<std::string> notes;
    std::string travel;
    for (double f : sine_frequencies_hz()) {
        travel += fmt::format("{}{:g} Hz {:.3f} m", travel.empty() ? "" : ", ", f,
                              sine_travel_m(sine_amplitude_g(), f));
    }
    notes.push_back(fmt::format(
        "Stroke. A sine of amplitude A at f moves the table +-A g / (2 pi f)^2. At {:g} g: {}. "
        "The table's stroke is +-{:.3f} m (Table 3-1; the thesis's own Eq. 3.42), so the 0.5 and "
        "1 Hz runs at {:g} g were beyond it; the largest sine it can play is {:.3f} g at 0.5 Hz, "
        "{:.3f} g at 1 Hz and {:.2f} g at 2 Hz. The rows of sines beyond it (here and in Table "
        "3-4) are marked not runnable and not counted.",
        sine_amplitude_g(), travel, table_stroke_m(), sine_amplitude_g(),
        table_stroke_m() / sine_travel_m(1.0, 0.5), table_stroke_m() / sine_travel_m(1.0, 1.0),
        table_stroke_m() / sine_travel_m(1.0, 2.0)));
    std::string implied;
    double half_lo = 1e9, half_hi = 0.0;
    for (const Specimen& s : specimens()) {
        for (double f : {0.5, 1.0, 2.0}) {
            const double v = table_velocity_mps(s, f);
            const double a = implied_amplitude_g(v, f);
            implied += fmt::format("{}{} {:g} Hz {:g} m/s -> {:.2f} g", implied.empty() ? "" : "; ",
                                   s.name, f, v, a);
            half_lo = std::min(half_lo, a / 2.0);
            half_hi = std::max(half_hi, a / 2.0);
        }
    }
    notes.push_back(fmt::format(
        "Recorded velocities. Table 3-6 lists the table's peak velocity, integrated from the "
        "recorded acceleration (s.3.3.4.1). Read as the velocity amplitude A g / (2 pi f) of a "
        "sine, each implies an amplitude A well below {:g} g: {}. (Read as the peak 2 A g / "
        "(2 pi f) of a velocity integrated from rest, A would be half that, {:.2f}-{:.2f} g, "
        "below the uplift thresholds g tan(alpha) of TS2 and TS3, which overturned: the first "
        "reading is the consistent one.) At 0.5 and 1 Hz even these velocities exceed what the "
        "stroke allows, 2 pi f x {:.3f} m = {:.3f} and {:.3f} m/s.",
        sine_amplitude_g(), implied, half_lo, half_hi, table_stroke_m(),
        two_pi * 0.5 * table_stroke_m(),
        two_pi * 1.0 * table_stroke_m()));
    return notes;
}

}  // namespace freestand::validate
