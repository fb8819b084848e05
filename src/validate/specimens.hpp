#pragma once
/// The thesis's rigid steel specimens TS1-TS3 under 0.8 g sines (thesis s.3.3.4.1, Tables 3-2,
/// 3-3, 3-5, 3-6) through freestand's simulator (docs/methods.md s.3) and its Ishiyama bound
/// (docs/methods.md s.5).
#include <string>
#include <vector>

#include "block/block.hpp"
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
inline constexpr double thesis_g_mps2 = 9.81;
/// Amplitude of the thesis's sines, g (Table 3-5).
double sine_amplitude_g();
/// Duration of every sine, s (s.3.3.5.1: 5 s, "similar to the case of pure rocking").
double sine_duration_s();
/// The frequencies compared, Hz (issue 13 s.3): 0.5, 1, 2, 3, 5, 10.
const std::vector<double>& sine_frequencies_hz();
/// Half-stroke of the thesis's shake table, m (Table 3-1).
double table_stroke_m();

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

}  // namespace freestand::validate
