#pragma once
/// Sizes every stage bounds before it allocates or loops, so that nothing runs unbounded.
/// Each is documented in the README's "Limits" table; exceeding one is an InputError (exit 3)
/// naming the parameter, what the request needs and the limit.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "core/errors.hpp"
#include "core/units.hpp"

namespace freestand::core::limits {

/// Samples of any record, read or generated (10 million: 28 h at 0.01 s, 80 MB of doubles).
inline constexpr double max_samples = 1e7;
/// Lines of a COSMOS V2 file: at least one value per data line, plus headers and comments.
inline constexpr std::size_t max_cosmos_lines = 10'100'000;
/// Highest frequency of a response spectrum or a sine input, Hz. Above a record's Nyquist
/// frequency its pseudo-acceleration is its PGA; sub-stepping to T / 20 there costs without end.
inline constexpr double max_frequency_hz = 1000.0;
/// Lowest frequency of a response spectrum, Hz (a period of 1000 s). Below it the one-sample
/// map's coefficients lose every digit to cancellation, (omega dt)^2 against 1: at 1e-6 Hz the
/// PSA was 480 times the exact omega^2 PGD, and from about 1e-160 Hz omega^2 underflows and the
/// PSA is NaN. At 1e-3 Hz it is within 1% of omega^2 PGD for every step from 1e-6 s to 1 s.
inline constexpr double min_frequency_hz = 1e-3;
/// Frequencies of one response-spectrum request.
inline constexpr double max_frequencies = 1e5;
/// Bytes of one input file (a record, a case, a spectrum) read into memory.
inline constexpr double max_input_bytes = 512.0 * 1024.0 * 1024.0;
/// Time step of a record, s: finer than 1 microsecond or coarser than 1 s is not a strong-motion
/// record (and a 1e300 s step made every measure overflow).
inline constexpr double min_dt_s = 1e-6;
inline constexpr double max_dt_s = 1.0;
/// Largest acceleration of a record or an excitation, m/s^2 (100 g): beyond it the products of
/// the integrators overflow long before anything physical is left to compute.
inline constexpr double max_abs_accel_mps2 = 100.0 * units::g_mps2;
/// Largest design level of a design spectrum, g (target's and generate's --pga, --sds, --sd1,
/// --ag), the upper end of a case's pga_g levels: 'target --design rg1.60 --pga 1e300' printed
/// spectral accelerations of 7.5e298 g with exit 0.
inline constexpr double max_design_level_g = 3.0;
/// Lowest PGA level of a case or a fragility run, g (1 cm/s^2), far below any design level
/// (they start near 0.05 g). The static margin grows as 1 / PGA (docs/methods.md s.2): at
/// 1e-300 g it is 2.5e299, a 300-digit number in a report.
inline constexpr double min_pga_level_g = 1e-3;
/// PGA levels of one case, one override or one fragility run: each level costs a set of
/// histories and a report row (about 70 KB: 1e5 levels exhaust the memory).
inline constexpr double max_pga_levels = 1000.0;
/// Samples of one fragility run, levels x samples per level: each sample is a time-history
/// simulation (a few ms to a second), so 1e6 is already days of CPU.
inline constexpr double max_fragility_samples = 1e6;
/// A block's lengths (half-widths, CG height), m: above 100 m it is not equipment standing on
/// a floor. No lower limit: a CG over an edge (CG to edge -> 0) is a needle that topples at
/// once, and is assessed as one.
inline constexpr double max_length_m = 100.0;
/// A block's mass, kg: from a gram to 100,000 t.
inline constexpr double min_mass_kg = 1e-3;
inline constexpr double max_mass_kg = 1e8;
/// Steps of one fixed-step integration (central difference: duration / dt).
inline constexpr double max_fixed_steps = 1e8;
/// Dormand-Prince steps (accepted and rejected) of one flexible-body run. Their number grows
/// with the mode's frequency (a step is bounded by the explicit method's stability, ~3 /
/// omega); 2e7 is about 20 s of work, over 1000 s of rocking at 1000 Hz. Only the run finds it
/// out, so exceeding it is a NumericalError (exit 4), not an InputError.
inline constexpr double max_adaptive_steps = 2e7;
/// Characters of one line of a TOML case file. toml++ builds the tables of a dotted key
/// (a.b.c...) recursively: 60,000 parts overflowed the stack. A key's parts stand on one line
/// and its table header's on another, so the cap bounds the depth to about this many tables.
inline constexpr std::size_t max_case_line_chars = 4096;

/// An allowed interval of a physical value; bounds inclusive unless stated.
struct Range {
    double lo;
    double hi;
    bool lo_inclusive = true;
    bool hi_inclusive = true;
};

/// True when value lies in range (a NaN never does).
bool within(double value, const Range& range);

/// "[lo, hi]", "(lo, hi]" etc., for messages.
std::string describe(const Range& range);

/// The ranges of the physical values that both a case file and the command line accept, so
/// that every entry point refuses the same values (docs/methods.md s.1 and s.7).
/// Static and kinetic friction, mu_s and mu_k: measured bases span 0.1 to 0.8 (s.7); above 2
/// a base is no longer a friction contact.
inline constexpr Range friction{0.0, 2.0};
/// Restitution on angular velocity, r (s.1).
inline constexpr Range restitution{0.0, 1.0};
/// One PGA level, g: a case's pga_g, dbe_pga_g and fragility_pga_g, assess's and fragility's
/// --pga, a batch list's pga_g.
inline constexpr Range pga_level_g{min_pga_level_g, max_design_level_g};
/// A block's mass, kg.
inline constexpr Range mass_kg{min_mass_kg, max_mass_kg};

/// Throws InputError at where unless value lies in range:
/// "value <value> is out of range; expected <range>".
void require_in(double value, const Range& range, const SourceLocation& where);

/// How many levels START:STOP:STEP holds (both ends included, a STOP a rounding short of a
/// step still counted); step > 0 and stop >= start are the caller's to check.
double pga_range_count(double start_g, double stop_g, double step_g);

/// The count levels start_g + i step_g, each rounded to 12 decimals so that 0.1 + 2 x 0.1 is
/// written 0.3.
std::vector<double> pga_range_levels(double start_g, double step_g, double count);

/// Throws InputError at where unless pga_g holds 1 to max_pga_levels levels, each within
/// pga_level_g, strictly increasing. The count is checked first, before any level is used.
void require_pga_levels(const std::vector<double>& pga_g, const SourceLocation& where);

/// Throws InputError at where unless needed <= limit (a NaN need counts as too large):
/// "<what>: <needed> is above the limit <limit> (README, Limits)", both numbers at 4
/// significant digits or as many more as it takes to tell them apart.
void require_within(double needed, double limit, const SourceLocation& where,
                    std::string_view what);

/// Throws InputError at where unless given >= limit (a NaN counts as too small):
/// "<what>: <given> is below the limit <limit> (README, Limits)".
void require_at_least(double given, double limit, const SourceLocation& where,
                      std::string_view what);

/// Throws InputError at where unless a block's length is positive and at most max_length_m.
void require_length(double length_m, const SourceLocation& where);

/// Throws InputError at where unless every sample is finite and within max_abs_accel_mps2
/// (an excitation's accelerations, after any scaling).
void require_accelerations(const std::vector<double>& series_mps2, const SourceLocation& where);

}  // namespace freestand::core::limits
