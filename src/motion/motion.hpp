#pragma once
/// Spectrum-compatible acceleration histories (docs/methods.md s.8): synthetic records from a target
/// spectrum, time-domain wavelet matching of seed records, baseline correction, and the
/// SRP 3.7.1 acceptance report. Everything is deterministic for the same inputs and seed.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/record.hpp"
#include "core/units.hpp"
#include "spectra/spectrum.hpp"

namespace freestand::motion {

/// A closed range [min, max].
struct Range {
    double min = 0.0;
    double max = 0.0;
};

/// Ranges a history must fall in to be consistent with the earthquakes behind its target
/// (SRP 3.7.1 asks for realistic velocity, displacement and duration; NUREG/CR-6728 tabulates
/// V/A and AD/V^2 by magnitude and distance; docs/methods.md s.8 "Realism"). PGA / ZPA and
/// D5-75 apply to every target. V/A, AD/V^2 and D/A depend on the earthquakes behind a target:
/// each is checked only when its range is set (rg160_realism() sets all three from the
/// RG 1.60 basis, V/A 1.22 m/s/g and D/A 0.91 m/g of Newmark, Blume & Kapur 1973); unset, the
/// ratio is reported and not checked.
struct RealismLimits {
    Range pga_over_zpa{1.0, 1.1};  ///< PGA / the target's zero-period acceleration
    double d5_75_min_s = 6.0;      ///< 5-75% Arias duration
    std::optional<Range> va_mps_per_g;     ///< PGV / PGA, m/s per g
    std::optional<Range> adv2;             ///< PGA PGD / PGV^2 (PGA in m/s^2)
    std::optional<double> da_max_m_per_g;  ///< PGD / PGA, m per g
};

/// The RG 1.60 defaults: V/A 0.8-2.0 m/s/g, AD/V^2 2-8, D/A at most 1.3 m/g.
RealismLimits rg160_realism();

/// Throws InputError naming the field (pga_over_zpa_range, d5_75_min_s, va_range_mps_per_g,
/// adv2_range, da_max_m_per_g) unless every limit is finite and positive and each min < max.
void validate_realism(const RealismLimits& limits);

/// What one component must match.
struct Target {
    spectra::Spectrum psa_5pct;                  ///< acceptance target; damping must be 0.05
    std::optional<spectra::Spectrum> psa_10pct;  ///< 10%-damped target, reported only
    /// When set, the PSD is checked against the RG 1.60 horizontal target PSD
    /// (spectra::rg160_target_psd) at this PGA; unset for targets without a defined PSD.
    std::optional<double> rg160_psd_pga_g;
    RealismLimits realism;
    /// V/A, AD/V^2 and D/A are checked on horizontal components only (the NUREG/CR-6728 ratios
    /// describe horizontal motion); PGA / ZPA and D5-75 on every component.
    bool horizontal = true;
    /// Size of the unit g of the spectra (and of the records' PGA), and gravity of the Arias
    /// intensity, m/s^2: a case's site.g_mps2 (docs/methods.md, Conventions).
    double g_mps2 = units::g_mps2;
};

/// Zero-period acceleration of a target, g: its PSA at the highest tabulated frequency (RG 1.60:
/// the PGA, PSA being flat above 33 Hz).
double zero_period_g(const spectra::Spectrum& psa_5pct);

/// Horizontal and vertical targets of one design.
struct TargetSet {
    std::string label;  ///< e.g. "RG 1.60, PGA 0.3 g"
    Target horizontal;
    Target vertical;
    /// Target of component "h2" when the two horizontal directions differ; unset: h2 matches
    /// horizontal like h1.
    std::optional<Target> horizontal_2;
};

/// RG 1.60 horizontal and vertical (5% and 10%), with the RG 1.60 target PSD on horizontals.
/// The vertical is rg160_vertical_target at vertical_zpa_ratio (1: RG 1.60's own vertical).
/// g_mps2: the unit g of every target, m/s^2.
TargetSet rg160_targets(double pga_g, double vertical_zpa_ratio = 1.0,
                        double g_mps2 = units::g_mps2);

/// RG 1.60's vertical target (5% and 10%, tabulated on frequency_hz) at the horizontal PGA
/// pga_g, scaled so its zero-period acceleration is zpa_ratio x pga_g. RG 1.60's own vertical
/// spectrum (zpa_ratio = spectra::rg160_vertical_zpa_ratio, 1) is 2/3 of the horizontal below
/// 0.25 Hz and equal to it above 3.5 Hz, its ZPA the horizontal PGA (docs/methods.md s.8).
/// A vertical component: no target PSD, realism limited to PGA / ZPA and D5-75. InputError
/// (field "vertical_ratio") unless zpa_ratio is in (0, 2]. g_mps2: the unit g, m/s^2.
Target rg160_vertical_target(double pga_g, double zpa_ratio,
                             const std::vector<double>& frequency_hz,
                             double g_mps2 = units::g_mps2);

/// Sets the realism limits of every target of the set (validated).
void set_realism(TargetSet& targets, const RealismLimits& limits);

/// Targets from a horizontal 5% spectrum (and optionally 10%); the vertical is
/// vertical_ratio times the horizontal (2/3 is common). No target PSD. g_mps2: the unit g of
/// the spectra, m/s^2.
TargetSet ratio_targets(std::string label, const spectra::Spectrum& horizontal_5pct,
                        const std::optional<spectra::Spectrum>& horizontal_10pct,
                        double vertical_ratio, double g_mps2 = units::g_mps2);

/// Throws InputError (field = the spectrum's label) unless the spectrum has >= 2 points,
/// strictly increasing finite positive frequencies, finite positive PSA, and the damping
/// expected (within core::tol::damping_equal).
void validate_target(const spectra::Spectrum& spectrum, double expected_damping);

/// Strong-motion envelope of the synthetic method: (t / rise)^2 while rising, 1 in the strong
/// part, then exp(-c (t - rise - strong)) decaying to end_level at the record's end.
struct Envelope {
    double rise_s = 2.0;
    double strong_s = 10.0;
    double end_level = 0.05;  ///< envelope value at the last sample, in (0, 1]
};

/// Envelope value at t for a record of total duration duration_s.
double envelope_at(const Envelope& envelope, double t_s, double duration_s);

/// Controls of the wavelet matching loop. A matching frequency whose ratio (computed / target)
/// lies in [lower, upper] is held where it is; one outside is pulled to aim.
struct MatchOptions {
    double aim = 1.05;    ///< ratio aimed at, so dips between matching points stay >= 1
    double lower = 1.02;  ///< in-loop band: ratios at the matching frequencies
    double upper = 1.18;
    double relaxation = 1.0;    ///< fraction of the linearised correction applied per pass
    int max_iterations = 40;    ///< matching passes
    int match_per_decade = 30;  ///< matching frequencies per decade (checks are at 100)
    /// Shortest wavelet, in cycles per sample, for oscillators above 25 Hz (0.1 elsewhere:
    /// coarser wavelets are poorly represented by their samples). A target rising above its
    /// zero-period value at 25-50 Hz (ASCE 7, EC8 below T_B) needs resonant content there.
    double rigid_wavelet_cycles_per_sample = 0.1;
};

/// Everything the generator needs besides the targets.
struct GenerateOptions {
    std::vector<std::string> components{"h1", "h2", "v"};  ///< "h1"/"h2" horizontal, "v" vertical
    double duration_s = 20.0;  ///< synthetic records only (>= 20 s, SRP 3.7.1)
    double dt_s = 0.005;       ///< synthetic records only (<= 0.01 s, SRP 3.7.1)
    std::uint64_t seed = 1;    ///< base seed; each component and attempt derives its own
    /// Seed records, one per component in order; empty selects the synthetic method.
    std::vector<core::Record> seed_records;
    Envelope envelope;
    MatchOptions match;
    /// Tries per component: synthetic, a new seed each (the first half stop after 12 passes);
    /// seed record, gentler steps and a higher aim each.
    int max_attempts = 6;
};

/// SRP 3.7.1 Option 1 Approach 2 acceptance of one record against its target, and the
/// realism checks of its RealismLimits.
struct Acceptance {
    bool passed = false;           ///< srp_passed && realism_passed
    bool srp_passed = false;       ///< every SRP 3.7.1 criterion
    bool realism_passed = false;   ///< every realism range
    std::string reason;            ///< "" when passed, else every failed criterion, "; "-joined
    std::size_t check_points = 0;  ///< 5% ratio points, >= 100 per decade over 0.1-50 Hz
    double min_ratio = 0.0;        ///< computed / target over the check band
    double max_ratio = 0.0;
    double mean_ratio = 0.0;
    int max_adjacent_below = 0;             ///< longest run of adjacent points below 1.0 (<= 9)
    double max_ratio_cap_band = 0.0;        ///< max ratio over 0.2-25 Hz (<= 1.3)
    std::optional<double> psd_min_ratio;    ///< min of averaged PSD / target PSD, 0.3-24 Hz
    std::optional<double> ratio_10pct_min;  ///< 10% ratio, informational
    std::optional<double> ratio_10pct_max;
    double pga_g = 0.0, pgv_mps = 0.0, pgd_m = 0.0;
    double d5_75_s = 0.0, d5_95_s = 0.0, duration_s = 0.0, dt_s = 0.0;
    double final_velocity_mps = 0.0, final_displacement_m = 0.0;
    double arias_mps = 0.0;          ///< Arias intensity
    double zpa_g = 0.0;              ///< the target's zero-period acceleration
    double pga_over_zpa = 0.0;       ///< PGA / ZPA
    double va_mps_per_g = 0.0;       ///< PGV / PGA
    double adv2 = 0.0;               ///< PGA PGD / PGV^2, PGA in m/s^2
    double da_m_per_g = 0.0;         ///< PGD / PGA
    RealismLimits realism;           ///< the ranges checked
    bool horizontal = true;          ///< V/A, AD/V^2, D/A apply (when their ranges are set)
};

/// Computes the acceptance report with spectra::psa_g at 100 points per decade 0.1-50 Hz.
/// The PSD S(f) = |X(f)|^2 / (pi T_D), X = dt FFT(a), T_D = D5-75, averaged over +-20% in
/// frequency, is one-sided per rad/s, the convention of the RG 1.60 target PSD.
Acceptance check_acceptance(const core::Record& record, const Target& target);

/// One generated or matched component.
struct GeneratedComponent {
    core::Record record;  ///< component label set; acceleration in m/s^2
    Acceptance acceptance;
    std::string method;      ///< "synthetic+wavelet" or "wavelet (seed <name>)"
    std::uint64_t seed = 0;  ///< RNG seed actually used (synthetic), else 0
    int attempts = 0;        ///< seeds tried
    int iterations = 0;      ///< matching passes of the kept attempt
    double wall_s = 0.0;     ///< wall time of this component (the only non-deterministic output)
    std::string stop;        ///< "passed", "iteration limit", "attempt limit", ...
};

/// Zero-lag Pearson correlation of two components over their common samples.
struct Correlation {
    std::string a, b;
    double rho = 0.0;
};

struct GeneratedSet {
    std::vector<GeneratedComponent> components;
    std::vector<Correlation> correlations;  ///< every pair, in component order
    bool passed = false;                    ///< every component passed and every |rho| <= 0.16
    std::vector<std::string> notes;         ///< regenerations and other decisions taken
};

/// Generates (or matches) every requested component against targets.horizontal / vertical.
/// Throws InputError on bad targets or requests (dt > 0.01 s, duration < 20 s, seed record count
/// different from the component count, unknown component names).
GeneratedSet generate_set(const TargetSet& targets, const GenerateOptions& options);

/// Result of matching one record.
struct MatchResult {
    core::Record record;
    int iterations = 0;      ///< passes made before the returned record
    bool converged = false;  ///< every matching frequency got inside [lower, upper]
    Acceptance acceptance;   ///< full check of the returned record
};
/// Wavelet-matches one seed record to a target: scaled to the target's geometric-mean level
/// first, then wavelet passes with the baseline constraints until the full acceptance check
/// passes or options.max_iterations is reached (the iterate closest to the band is returned).
MatchResult match_record(const core::Record& seed, const Target& target,
                         const MatchOptions& options);

/// Synthetic stationary random-phase process x envelope, iterated in the frequency domain on
/// the target/computed PSA ratio (SIMQKE); not yet matched.
core::Record synthesize(const Target& target, double duration_s, double dt_s, std::uint64_t seed,
                        const Envelope& envelope);

}  // namespace freestand::motion
