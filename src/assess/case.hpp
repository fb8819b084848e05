#pragma once
/// An assessment case: the component, the site and the run options, read from a TOML file
/// (README "Case files"). Values are SI and validated when read; every problem is an
/// InputError naming file:line:key and the allowed range.
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "block/block.hpp"
#include "core/statistics.hpp"
#include "core/units.hpp"
#include "motion/motion.hpp"
#include "spectra/spectrum.hpp"

namespace freestand::assess {

/// Horizontal direction of the component; each is assessed as a planar problem.
enum class Direction { x, y };
inline const char* to_string(Direction d) { return d == Direction::x ? "x" : "y"; }

/// Geometry and rocking properties of the component in the vertical plane of one horizontal
/// direction.
struct PlanarGeometry {
    double b_left_m = 0.0;         ///< CG to the left rocking edge (or leg), m
    double b_right_m = 0.0;        ///< CG to the right rocking edge (or leg), m
    double inertia_cg_kgm2 = 0.0;  ///< I_c about the CG, out of this plane, kg m^2
    std::string inertia_source;    ///< how I_c was obtained, for the report
    /// Measured free-rocking frequencies of rocking in this plane, [lo, hi] Hz (the
    /// flexible-body screen's band, docs/methods.md s.2).
    std::optional<std::array<double, 2>> free_rocking_band_hz;
};

/// Base friction and restitution, with where each value came from, and their bounds
/// (docs/methods.md s.7: single measurements, so checks use bounds, not best estimates).
struct BaseContact {
    std::string material;               ///< docs/methods.md s.7 name, or "" for explicit values
    double mu_s = 0.0;                  ///< static friction coefficient (nominal)
    double mu_k = 0.0;                  ///< kinetic friction coefficient (nominal)
    std::optional<double> restitution;  ///< measured, on angular velocity; Housner's when absent
    /// Where the values came from: "material table (docs/methods.md s.7; Saraswat 2017)" or
    /// "case file".
    std::string source;
    /// [lower, upper] static friction; the default is 0.8 and 1.2 x mu_s (docs/methods.md s.7).
    std::array<double, 2> mu_s_range{0.0, 0.0};
    std::string mu_s_range_source;
    /// [lower, upper] restitution given by the case; absent: from Housner's value of each
    /// direction to the measured r (both Housner's when none is measured).
    std::optional<std::array<double, 2>> restitution_range;

    /// mu_k / mu_s, applied to both friction bounds (1 when mu_s = 0).
    double kinetic_ratio() const { return mu_s > 0.0 ? mu_k / mu_s : 1.0; }
};

/// Default friction bounds of docs/methods.md s.7: 0.8 and 1.2 times the single measurement.
std::array<double, 2> default_mu_s_range(double mu_s);

/// The free-standing component ([component]; docs/methods.md s.1).
struct Component {
    std::string name;
    std::string description;
    double mass_kg = 0.0;
    double cg_height_m = 0.0;
    /// Height of the body's top above the base, m; absent: twice the CG height (a body with its
    /// CG at mid-height). Sets the top point of the simulation's top acceleration, the default
    /// inertia and the default modal height.
    std::optional<double> height_m;
    PlanarGeometry x;            ///< rocking in the x-z plane
    PlanarGeometry y;            ///< rocking in the y-z plane
    bool uniform_block = false;  ///< given as width/depth/height of a uniform block
    std::string footprint;       ///< legs or footprint description (free text)
    std::optional<double> fixed_base_frequency_hz;
    /// The flexible body's mode (docs/methods.md s.10), used when a flexible-body flag is raised;
    /// absent: dynamics::default_modal_damping and a uniform cantilever's first mode.
    std::optional<double> modal_damping;
    std::optional<double> modal_mass_fraction;  ///< m_s / M
    std::optional<double> modal_height_m;       ///< h_s above the base, m
    BaseContact base;
    double allowable_slide_m = 0.0;     ///< absolute slide allowed: clearance to walls, neighbours
    /// Relative displacement allowed between joined units (slack of a transfer tunnel), m.
    std::optional<double> allowable_relative_m;
    double required_overturn_fs = 1.5;  ///< required alpha / theta_max (docs/methods.md s.5a)

    const PlanarGeometry& plane(Direction d) const { return d == Direction::x ? x : y; }
    /// height_m, else twice the CG height, m.
    double body_height_m() const { return height_m.value_or(2.0 * cg_height_m); }
    /// The planar rigid block of one direction.
    block::Block block(Direction d) const;
};

/// A user target spectrum file ([site] target_*_file), read when the case is parsed.
struct TargetFile {
    std::string given;           ///< path as written in the case file
    spectra::Spectrum spectrum;  ///< as read (PSA in g at the file's own scale)
};

/// User target files replacing the design spectrum. target_h_file (h5, h10) is direction x, and
/// y too unless target_y_file (y5, y10) is given; history h1 is matched to x's target, h2 to
/// y's. Each file is scaled at a level by pga_g / zpa_h_g, zpa_h_g being the x 5% file's
/// rigid-limit PSA (at its highest frequency); the 10%, y and vertical files take the same
/// factor, so direction y's PGA is pga_g x (y file's rigid limit / zpa_h_g).
struct UserTargets {
    TargetFile h5;                  ///< horizontal, 5% damped
    std::optional<TargetFile> h10;  ///< horizontal, 10% damped
    std::optional<TargetFile> v;    ///< vertical, 5% damped
    std::optional<TargetFile> y5;   ///< horizontal of direction y, 5% damped
    std::optional<TargetFile> y10;  ///< horizontal of direction y, 10% damped (with h10 and y5)
    double zpa_h_g = 1.0;           ///< PSA of h5 at its highest frequency, g
};

/// The site's design motion ([site]; docs/methods.md s.8).
struct Site {
    std::string design = "rg1.60";      ///< "rg1.60", or "user target files" when targets is set
    std::optional<UserTargets> targets; ///< user target files instead of RG 1.60
    std::vector<double> pga_g;          ///< horizontal PGA levels, g, strictly increasing
    /// Vertical PGA / horizontal PGA: the case's, else RG 1.60's vertical ZPA ratio (1) for
    /// design = "rg1.60" and 2/3 for target files (the vertical file's ratio when given). With
    /// RG 1.60 the vertical histories match its vertical spectrum scaled to this ZPA.
    double vertical_ratio = 2.0 / 3.0;
    double sliding_damping = 0.10;      ///< damping of the spectrum the sliding method reads
    /// Gravity of every computation of the case, and the size of its unit g (PGA levels,
    /// spectra and records in g), m/s^2, in [9.78, 9.84] (docs/methods.md, Conventions).
    double g_mps2 = units::g_mps2;
    /// Corner of the zero-phase high-pass that turns a history's displacement into the energy
    /// method's DeltaD (docs/methods.md s.4: the thesis's test band started at 0.5 Hz), Hz.
    double energy_highpass_hz = 0.5;
    /// PGA of the design-basis earthquake, g ([site] dbe_pga_g, in [0.001, 3]): given, the ASCE
    /// 43-05 s.1.3 performance goal is checked at it and at 1.5 x DBE (docs/methods.md s.6
    /// step 5, src/goal/).
    std::optional<double> dbe_pga_g;
    /// DeltaD per PGA level given by the case (table displacements), m; replaces the high-pass.
    std::optional<std::vector<double>> energy_table_displacement_m;
    /// Realism ranges every generated history must meet (docs/methods.md s.8): RG 1.60's by
    /// default for design = "rg1.60"; for target files PGA / ZPA and D5-75 only, V/A, AD/V^2
    /// and D/A where the case sets va_range_mps_per_g, adv2_range, da_max_m_per_g.
    motion::RealismLimits realism;
};

/// When to run the time-history simulation ([options] simulate; docs/methods.md s.6).
enum class SimulatePolicy { automatic, always, never };
const char* to_string(SimulatePolicy p);

/// Uncertain properties of a fragility analysis ([uncertainty], docs/methods.md s.9). Absent: the
/// friction is uniform over the case's bounds and the restitution uniform over each direction's
/// bounds (Housner's value to the measured r), drawn at one quantile for both directions.
struct Uncertainty {
    std::optional<core::Distribution> mu_s;         ///< static friction (mu_k keeps its ratio)
    std::optional<core::Distribution> restitution;  ///< one value for both directions
};

/// The fragility section of an assessment ([options] fragility = true).
struct FragilitySection {
    bool enabled = false;
    std::vector<double> pga_g;  ///< levels, g (default 0.1 to 1.0 by 0.1)
    int samples = 100;          ///< per level
};

/// Run options ([options]; README "Case files").
struct Options {
    /// Sets per simulated level, and the batch an unsettled level grows by (docs/methods.md s.6
    /// steps 3-4: percentiles of about 30 sets, ASCE 4-16 and ASCE 43-05 practice).
    int histories_per_level = 30;
    int max_histories_per_level = 120;  ///< the cap an unsettled level grows to
    std::uint64_t seed = 1;
    std::vector<std::filesystem::path> seed_records;  ///< resolved against the case's folder
    SimulatePolicy simulate = SimulatePolicy::automatic;
    FragilitySection fragility;
    /// false skips the base-material search of a failing case (no case key: `validate` reads
    /// the own base's levels only and sets it).
    bool search_materials = true;
    /// false skips the 3D body's step check (Body3dLevel::step_checked; no case key: it only
    /// reports, and the tests that compare verdicts across policies set it).
    bool step_check = true;
};

/// The transfer tunnel joining two units ([tunnel], docs/methods.md s.10).
struct Tunnel {
    double height_m = 0.0;              ///< tunnel height above the base, m
    double allowable_relative_m = 0.0;  ///< its slack: relative displacement allowed, m
};

/// A parsed case plus what the report must echo.
struct Case {
    std::string file;  ///< path as given
    /// The component; unused (default) when the case describes two units.
    Component component;
    /// Two free-standing units joined by a tunnel ([[unit]] tables, each with the keys of
    /// [component]; exclusive with [component]); empty for a one-component case.
    std::vector<Component> units;
    std::optional<Tunnel> tunnel;  ///< with units
    Site site;
    Options options;
    Uncertainty uncertainty;
    std::vector<std::string> assumptions;  ///< defaults the parser applied, in words
};

/// The case with its base replaced by material m's whole property set (friction bounds, mu_k =
/// mu_s, tabulated restitution), exactly as a case file naming only `base_material = m` reads;
/// unchanged when m is the case's own material, whose bounds the case may have given.
Case with_base_material(Case c, const std::string& material);

/// Why a set of levels cannot be assessed (a level whose vertical PGA, pga_g x vertical_ratio,
/// reaches 1 g), or nothing.
std::optional<std::string> weightless_level(const std::vector<double>& pga_g,
                                            double vertical_ratio);

/// Parses a case file. Throws IoError if it cannot be read, InputError on any bad content
/// (syntax, unknown key, missing key, wrong type, out-of-range value), naming file:line:key.
Case read_case(const std::filesystem::path& path);

/// Parses case text; file_label is used in messages and to resolve relative paths.
Case parse_case(const std::string& text, const std::string& file_label);

struct CaseOverrides;

/// As parse_case, with overrides (assess/overrides.hpp) written into the document before it is
/// read: the case reads exactly as a file carrying those values would. A value the overrides
/// set has no line in the file, so its errors name file and key only.
Case parse_case(const std::string& text, const std::string& file_label,
                const CaseOverrides& overrides);

}  // namespace freestand::assess
