#pragma once
/// The thesis's rigid steel specimens TS1-TS3 under 0.8 g sines (thesis s.3.3.4.1, Tables 3-2,
/// 3-3, 3-5, 3-6) through freestand's simulator (docs/methods.md s.3) and its Ishiyama bound
/// (docs/methods.md s.5).
#include <string>
#include <vector>

#include "assess/case.hpp"
#include "block/block.hpp"
#include "dynamics/body3d.hpp"
#include "dynamics/simulate.hpp"
#include "validate/validate.hpp"

namespace freestand::validate {

/// One specimen as Table 3-2 gives it.
struct Specimen {
    std::string name;      ///< "TS1", "TS2", "TS3"
    std::string key;       ///< fact key prefix, "ts1"
    double alpha_rad = 0;  ///< critical angle
    double R_m = 0;        ///< CG to rocking edge
    double mass_kg = 0;
    double p_radps = 0;    ///< frequency parameter p = sqrt(M g R / I_O)
};

/// TS1, TS2, TS3 from the thesis facts.
const std::vector<Specimen>& specimens();

/// Gravity of the thesis's arithmetic and of these runs, m/s^2.
inline constexpr double thesis_g_mps2 = units::g_thesis_mps2;
/// Amplitude of the thesis's sines, g (Table 3-5).
double sine_amplitude_g();
/// Duration of every sine, s (s.3.3.5.1: 5 s, "similar to the case of pure rocking").
double sine_duration_s();
/// The frequencies compared, Hz (docs/methods.md s.13): 0.5, 1, 2, 3, 5, 10.
const std::vector<double>& sine_frequencies_hz();
/// Half-stroke of the thesis's shake table, m (Table 3-1).
double table_stroke_m();
/// Table travel a sine needs: amplitude A g / (2 pi f)^2 of its displacement, m (g = thesis_g_mps2).
double sine_travel_m(double amplitude_g, double frequency_hz);
/// True when a travel of +-travel_m fits the table's stroke (<= table_stroke_m()).
bool within_stroke(double travel_m);
/// True when the thesis's table can play the sine: within_stroke(sine_travel_m(A, f)).
bool table_can_play(double amplitude_g, double frequency_hz);
/// Where the table cannot play the sine, marks the row Agreement::not_runnable and puts the
/// travel against the stroke first in its reason (the comparison stays shown); else nothing.
void apply_stroke_rule(Row& row, double amplitude_g, double frequency_hz);

/// The planar block: b = R sin(alpha), h = R cos(alpha) and I_c = M g R / p^2 - M R^2, so that
/// the block has exactly Table 3-2's alpha, R, M and p.
block::Block specimen_block(const Specimen& s);

/// The block on the steel plate: mu_s = mu_k = 0.72 (s.3.3.3.2), restitution r (Table 3-3's
/// 0.98 on steel unless given), top corners at 2 h.
dynamics::BlockModel specimen_model(const Specimen& s, double restitution);

/// One sine run (docs/methods.md s.3 harmonic convention: from rest, no ramp) of
/// sine_duration_s(), event-driven integrator, default tolerances.
dynamics::Summary sine_run(const dynamics::BlockModel& model, double amplitude_g,
                           double frequency_hz);

/// Did the thesis see specimen s overturn at frequency f (0.5-2 Hz only; s.3.3.4.1)?
bool thesis_overturned(const Specimen& s, double frequency_hz);

/// The group, its rows (sine runs, then the Ishiyama bounds) and the notes on what the table
/// could physically deliver.
Group specimen_group();
std::vector<Row> specimen_rows();
std::vector<std::string> specimen_notes();

/// One run of Table 3-4 (specimens_rest.cpp): a specimen under sines of one amplitude.
struct RestRun {
    int number = 0;  ///< run number in Table 3-4, 1-6
    Specimen specimen;
    std::string key;  ///< fact key of its amplitude, e.g. "ts1.rest_run1_g"
    double amplitude_g = 0.0;
};
/// Table 3-4's six runs, two amplitudes per specimen (X_s = g tan(alpha) and just below).
const std::vector<RestRun>& rest_runs();
/// Table 3-4's frequencies: 0.5 Hz, then 1 to 10 Hz by 1 Hz.
const std::vector<double>& rest_frequencies_hz();
/// The rest tests: one row per run and frequency (66), outcome rows under the stroke rule.
Group rest_group();
std::vector<Row> rest_rows();

/// The random 0.8 g table test of s.3.3.4 (specimens_random.cpp): each specimen under every
/// history of a case's bank, horizontal record only, scaled to 0.8 g.
struct RandomRuns {
    std::string histories;                             ///< where the histories came from, in words
    std::vector<std::vector<dynamics::Summary>> runs;  ///< [specimen][history]
    /// The 3D body of each specimen under the same records, [specimen][history].
    std::vector<std::vector<dynamics::Body3dSummary>> runs3d;
    double pgd_mean_m = 0.0;            ///< mean peak ground displacement of the scaled records, m
    double pgd_max_m = 0.0;             ///< largest of them, m
    double highpass_hz = 0.0;           ///< the case's energy high-pass corner, Hz
    double highpass_disp_mean_m = 0.0;  ///< mean peak displacement after that high-pass, m
};
/// Runs the specimens under the histories of histories_case (named case_label in the rows):
/// its options.histories_per_level sets from assess::HistoryBank, on every core; deterministic.
RandomRuns run_random(const assess::Case& histories_case, const std::string& case_label);
Group random_group(const RandomRuns& runs);
std::vector<Row> random_rows(const RandomRuns& runs);
/// What the table's stroke says about the random test's motion.
std::string random_note(const RandomRuns& runs);

}  // namespace freestand::validate
