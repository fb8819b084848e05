#pragma once
/// What an assessment found: the pipeline fills it, the report only reads it.
/// Absent numbers are std::nullopt with a reason, never a sentinel value.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "assess/case.hpp"
#include "assess/statistics.hpp"
#include "dynamics/body3d.hpp"
#include "sliding/initiation.hpp"

namespace freestand::assess {

/// Initiating mode from rest (docs/methods.md s.2): the sliding stage's classification, one enum.
using Mode = sliding::Mode;
using sliding::to_string;

/// Which model settled a verdict or a check (docs/methods.md s.6).
enum class Model {
    static_initiation,          ///< docs/methods.md s.2 static thresholds
    asce4_sliding,              ///< docs/methods.md s.4 ASCE 4 equivalent-linear sliding
    equivalent_linear_rocking,  ///< docs/methods.md s.5a screen
    simulation_slide,           ///< docs/methods.md s.3 time-history simulation, peak slip
    simulation_rocking,         ///< docs/methods.md s.3 time-history simulation, rocking / overturning
    simulation_biaxial_slide,   ///< docs/methods.md s.10 biaxial sliding simulation, peak |u|
    simulation_flexible,        ///< docs/methods.md s.10 flexible-body simulation (a raised flag)
    simulation_3d,              ///< docs/methods.md s.11 rigid body in three dimensions
    simulation_3d_flexible,     ///< docs/methods.md s.11 the same carrying one mode per axis
    fragility_goal,             ///< docs/methods.md s.6 step 5: the goal, from the fragility engine
};
const char* to_string(Model m);

/// Verdicts in increasing severity. A level that fails is `anchor` until the base-material
/// search finds a material that passes every level; then it reads `change_material`.
enum class VerdictKind { acceptable, acceptable_with_clearance, change_material, anchor };
const char* to_string(VerdictKind k);

/// What failed at a level (none when it passes).
/// screen_inconclusive: the screen cannot show the level safe and no simulation was allowed.
/// performance_goal: every level passes, but the probability of failure at the DBE or at
/// 1.5 x DBE exceeds the ASCE 43-05 target (a headline only, never a level).
enum class Failure {
    none,
    slides_beyond_allowable,
    rocking_fs_below_required,
    overturns,
    screen_inconclusive,
    not_settled,  ///< the bootstrap of the sets still disagrees at the cap (s.6 step 4)
    performance_goal
};
const char* to_string(Failure f);

/// A verdict with its margin (capacity / demand, >= 1 passes) and the model that decided it.
struct Verdict {
    VerdictKind kind = VerdictKind::acceptable;
    Failure failure = Failure::none;
    /// The demand is negligible (docs/methods.md s.2 low-motion threshold, or a closed form that
    /// finds no motion): the report says "no motion" beside the margin, which is then the
    /// demand ratio or the static margin (docs/methods.md s.6 step 8).
    bool no_motion = false;
    std::optional<double> margin;  ///< capacity / demand
    std::string margin_basis;      ///< what the ratio compares, e.g. "allowable / ASCE 4 slide"
    Model decided_by = Model::static_initiation;
    double clearance_m = 0.0;  ///< sliding demand the clearance must cover, m
    std::string material;      ///< material to change to (change_material)
    std::string mechanism;     ///< why the material change helps, in words
    /// Open conditions the verdict carries (a raised flexible-body flag at a passing level).
    std::vector<std::string> conditions;
};

/// Where a verdict comes from: the level (index into the levels it was taken from) and the
/// level's verdict. Every part of a headline (level, model, margin) comes from this one level.
struct Governing {
    std::size_t level = 0;
    double pga_g = 0.0;
    Direction direction = Direction::x;
    Verdict verdict;
};

/// Static classification at the level's peak accelerations (docs/methods.md s.2, s.5: vertical
/// taken downward, the worst case).
struct Initiation {
    Mode mode = Mode::rest;
    double a_ratio = 0.0;  ///< A = PGA_h / (1 - PGA_v), both in g
    double mu_s = 0.0;
    double tan_alpha = 0.0;         ///< of the critical edge
    std::optional<double> mu_crit;  ///< Shenton's critical friction at A, when A > tan(alpha)
};

/// Flexible-body screen (docs/methods.md s.10): shown beside the mode, never changes it.
struct FlexibleFlag {
    bool raised = false;
    std::string basis;                ///< e.g. "fixed-base 7.5 Hz; free-rocking band 1.7-4.9 Hz"
    double band_lo_hz = 0.0;          ///< lowest frequency screened (the band may have a gap)
    double band_hi_hz = 0.0;          ///< highest frequency screened
    double peak_psa_in_band_g = 0.0;  ///< 5%-damped target PSA peak in the band
    double uplift_a_g = 0.0;          ///< static uplift threshold g tan(alpha), in g
    std::string reason;               ///< why raised or not, in words
};

/// The friction and restitution a check ran with, and which bound each is (docs/methods.md s.6
/// step 6, s.7).
struct ContactBound {
    double mu_s = 0.0;
    double mu_k = 0.0;
    double restitution = 0.0;
    bool housner = false;  ///< r is Housner's of each edge (restitution shows the critical edge's)
    std::string name;      ///< "lower friction bound" or "upper friction and restitution bounds"
};

/// Both bounds of one direction: sliding demands at the lower friction, rocking, overturning
/// and the classification at the upper friction; rocking simulated at both restitution bounds
/// (docs/methods.md s.6 step 6).
struct DirectionBounds {
    ContactBound sliding;
    ContactBound rocking;                      ///< upper friction, upper restitution
    std::optional<ContactBound> rocking_lower;  ///< upper friction, lower restitution (if it differs)
    double restitution_lower = 0.0;
};

/// Closed-form sliding estimates (docs/methods.md s.4) at the lower friction bound.
struct Sliding {
    double mu_s = 0.0;  ///< the friction they used (the lower bound)
    double mu_e = 0.0;
    double c_s_mps2 = 0.0;
    double c_s_g = 0.0;         ///< C_s in the case's unit g (site.g_mps2)
    double sa_vh_peak_g = 0.0;  ///< peak of SA_VH at the sliding damping, g
    /// DeltaD of the energy method (docs/methods.md s.4): the table displacement, m; 0 when the
    /// estimate was not made.
    double delta_d_m = 0.0;
    std::string delta_d_source;          ///< where DeltaD came from, in words
    std::optional<double> highpass_hz;   ///< corner of the zero-phase high-pass, when used
    std::optional<double> f_es_hz;
    std::optional<double> slide_asce_m;
    std::optional<double> slide_energy_m;  ///< informational: never decides nor triggers
    std::string reason;                    ///< why a value is absent ("" when both present)
};

/// Closed-form rocking and overturning checks (docs/methods.md s.5, s.5a) at the upper bounds.
struct Rocking {
    double alpha_rad = 0.0;
    double R_m = 0.0;
    double p_radps = 0.0;
    double restitution = 0.0;
    double uplift_a_g = 0.0;                ///< A at which uplift starts, g
    double ishiyama_v_mps = 0.0;            ///< velocity bound below which it cannot overturn
    std::optional<double> pgv_mps;          ///< mean PGV of the histories, when they were generated
    bool gate_passed = false;               ///< s.5a gate: PGA > (1 - 0.4 A_v) tan(alpha)
    double gate_g = 0.0;                    ///< the gate (1 - 0.4 A_v) tan(alpha), g
    std::optional<double> theta_rad;        ///< s.5a estimate; absent when gated out or overturning
    std::string el_reason;                  ///< why theta_rad is absent, when it is
    bool overturn_predicted = false;        ///< s.5a found no theta below alpha
    std::optional<double> overturn_fs;      ///< alpha / theta; absent when no rocking predicted
    std::optional<double> spectral_margin;  ///< largest spectrum scale with theta < alpha
    std::optional<double> amplification_estimate;  ///< slide: ~mu/A; rest: 1; rock: absent
};

/// One check of the screen (docs/methods.md s.6 step 4).
struct ScreenCheck {
    bool applies = false;  ///< the block moves in this way at the check's bound
    bool passed = true;
    Verdict verdict;       ///< what the check alone concludes (meaningful when it applies)
    std::string text;      ///< the comparison in words, e.g. "ASCE 4 142 mm > allowable 50 mm"
};

/// The screen of a level: static criteria, ASCE 4 sliding, equivalent-linear rocking.
struct Screen {
    ScreenCheck rest;   ///< at rest at the lower friction bound (then it rests at both)
    ScreenCheck slide;  ///< ASCE 4 at the lower friction bound
    ScreenCheck rock;   ///< s.5a estimate at the upper bounds
    bool passed = true;
};

/// Rocking simulated at one restitution bound (docs/methods.md s.6 step 6).
struct RockingRuns {
    ContactBound bound;
    Stats over_alpha;    ///< peak theta / alpha per set (NaN where the set overturned)
    Stats rad;           ///< peak theta per set, rad (NaN where the set overturned)
    int overturned = 0;  ///< sets overturned at this bound
};

/// Aggregated time-history simulation over the level's history sets (docs/methods.md s.3, s.6).
/// Per limit state the 84th percentile of the sets' peaks governs (s.6 step 3).
struct Simulation {
    int histories = 0;
    ContactBound sliding_bound;
    ContactBound rocking_bound;  ///< the restitution bound whose rocking governs
    bool bounds_differ = false;  ///< the rocking runs are not the sliding runs
    Stats slide_m;               ///< peak |slip| at the sliding bound, m
    Stats slide_residual_m;      ///< |slip| at the end at the sliding bound, m
    Stats rock_over_alpha;       ///< peak theta / alpha at the governing rocking bound
    Stats rock_rad;              ///< peak theta at the governing rocking bound, rad
    /// The other restitution bound's rocking, reported beside (absent when the bounds coincide).
    std::optional<RockingRuns> rocking_other;
    std::vector<char> overturned_sets;  ///< per set: overturned at any bound
    int overturned = 0;                 ///< sets overturned at any bound
    std::array<double, 2> overturn_ci{0.0, 0.0};  ///< Clopper-Pearson 95% of overturned / n
    Exceedance slide_exceed;  ///< sets sliding beyond the allowable
    Exceedance rock_exceed;   ///< sets with theta / alpha above 1 / FS_required, or overturned
    Stats amplification;      ///< top acceleration / PGA at the rocking bound
    int governing_history = 0;  ///< index of the worst history (0-based)

    /// The statistic that governs: the 84th percentile of the sets' peaks.
    double governing(const Stats& s) const { return s.p84; }
};

/// Biaxial sliding of a simulated level (docs/methods.md s.10): every history's two horizontal
/// components at once (h1 along x, h2 along y, with the vertical) at the sliding bound. When it
/// ran, its peak |u| replaces the planar peak slip in the sliding verdict; the planar
/// statistics stay in Simulation for comparison.
struct BiaxialSlide {
    bool ran = false;             ///< false: the planar model stays, for `reason`
    std::string reason;           ///< why it ran, or why it does not apply
    Stats slide_m;                ///< peak |u| over the histories, m (when ran)
    double planar_governing_m = 0.0;  ///< the larger governing planar peak slip of x and y, m
    Direction planar_direction = Direction::x;  ///< the direction of that planar peak
    std::optional<double> ratio;  ///< biaxial governing / planar_governing_m (absent if that is 0)
};

/// The flexible-body simulation of a level with a raised flexible-body flag (docs/methods.md
/// s.10): the same histories and bounds as Simulation, the reduced-order model.
struct FlexibleSimulation {
    Simulation sim;              ///< slip, rotation of the base, overturning: as the planar one
    Stats modal_m;               ///< peak |q| (modal displacement relative to the base), m
    Stats modal_accel_g;         ///< peak absolute acceleration of the modal mass, g
    int uplifted = 0;            ///< histories in which the base uplifted (either bound)
    double frequency_hz = 0.0;   ///< the mode it ran with
    double damping = 0.0;
    double mass_fraction = 0.0;
    double height_m = 0.0;
};

/// The rigid body in three dimensions at a simulated level that can uplift (docs/methods.md
/// s.11): every history's three components at once, h1 along x and h2 along y. Its runs are
/// kept as a Simulation (slide: peak |u| of the footprint centre at the sliding bound; rotation:
/// peak tilt and tilt over the critical tilt in the direction it leaned, at the rocking bound),
/// so they decide the level by the same rules as the planar runs; the planar runs stay in
/// LevelResult::simulation, beside it.
struct Body3dLevel {
    bool ran = false;     ///< false: the planar model stays, for `reason`
    std::string reason;   ///< why it ran, or why it does not apply
    Simulation sim;       ///< the 3D runs, as the planar statistics
    Stats twist_rad;      ///< peak |twist| about the vertical at the rocking bound, rad
    /// The body carried the flexible model's mode along each horizontal axis (a raised
    /// flexible-body flag), and the mode's description; modal_m its peak |q| at the rocking
    /// bound, m.
    bool flexible = false;
    std::string mode_text;
    Stats modal_m;
    /// Mean time per set in each contact state at the rocking bound, s (dynamics::ContactState
    /// order: rest, slide, edge, vertex, flight).
    std::array<double, dynamics::contact_state_count> time_in_state_s{};
    double dt_s = 0.0;    ///< the time step
    int unconverged_steps = 0;  ///< over every run: steps whose impulses hit the sweep cap
    /// The step's error, estimated on the governing history at the rocking bound: the same run
    /// at check_dt_s (a sixteenth of dt_s), its peak tilt over critical, overturn and peak |u|
    /// of the footprint centre, m, beside the level's run of that history.
    bool step_checked = false;  ///< the check ran (Options::step_check)
    double check_dt_s = 0.0;
    double check_tilt_over_critical = 0.0;
    bool check_overturned = false;
    double check_slide_m = 0.0;
    double run_tilt_over_critical = 0.0;
    bool run_overturned = false;
    double run_slide_m = 0.0;
    /// Governing 84th percentiles of the planar runs of the level's two directions (the larger),
    /// and 3D over planar (absent when the planar one is 0).
    double planar_rock_over_alpha = 0.0;
    double planar_slide_m = 0.0;
    std::optional<double> rock_ratio;
    std::optional<double> slide_ratio;
};

/// The bootstrap of a simulated level's decision (docs/methods.md s.6 step 4): the sets resampled
/// with replacement, the decision redone on each resample.
struct Settling {
    int n_sets = 0;                 ///< sets the decision rests on
    int resamples = 0;              ///< bootstrap resamples
    double settled_fraction = 1.0;  ///< resamples that agree with the decision
    /// settled_fraction >= settle_agreement, and a pass of a level that can overturn bounds
    /// the overturn rate (overturn_rate_upper <= settle_overturn_rate).
    bool settled = true;
    int rounds = 1;                 ///< batches of sets it took
    /// A passing level that can overturn: the Clopper-Pearson 95% upper bound of its overturn
    /// fraction, 0 of n_sets (absent for a failing level or one that cannot uplift).
    std::optional<double> overturn_rate_upper;
};

/// One PGA level in one direction.
struct LevelResult {
    double pga_g = 0.0;
    double pga_v_g = 0.0;
    Direction direction = Direction::x;
    DirectionBounds bounds;
    Initiation initiation;        ///< at the upper friction bound (classification, rocking)
    Initiation initiation_lower;  ///< at the lower friction bound (sliding)
    FlexibleFlag flexible;
    Sliding sliding;
    Rocking rocking;
    Screen screen;
    std::optional<Simulation> simulation;
    std::string simulation_reason;  ///< why it was run or skipped
    /// The dynamic model the level's simulation used (empty when not simulated) and why that
    /// model suits the scene (docs/methods.md s.10: model only what a scene needs).
    std::string model;
    std::string model_reason;
    /// Biaxial sliding at this level: empty when the level was not simulated.
    std::optional<BiaxialSlide> biaxial;
    /// The flexible-body simulation, run where the flag is raised; it then decides the level
    /// unless the 3D body carries the mode, and `simulation` (the rigid planar one) is reported
    /// beside it.
    std::optional<FlexibleSimulation> flexible_simulation;
    /// The body in three dimensions, where the level can uplift in some direction, carrying the
    /// mode where the flag is raised; it then decides the level (assess::body3d_decides).
    std::optional<Body3dLevel> body3d;
    /// How settled the decision of a simulated level is (docs/methods.md s.6 step 4).
    std::optional<Settling> settling;
    Verdict verdict;
    /// Screen result -> why simulated -> what governed, one line each (the decision trail).
    std::vector<std::string> trail;
};

/// One material of the base-material search (docs/methods.md s.6 step 7): the case reassessed with
/// that material's whole property set, through the same code as a case naming it.
struct MaterialTrial {
    std::string material;
    std::array<double, 2> mu_s_range{0.0, 0.0};
    std::optional<double> restitution;  ///< tabulated r; Housner's where the table has none
    bool passes = false;
    Governing governing;  ///< the trial's governing level and its verdict
};

struct Upgrade {
    bool needed = false;                     ///< the case's own base failed somewhere
    std::vector<MaterialTrial> trials;       ///< in docs/methods.md s.7 order
    std::optional<std::string> recommended;  ///< the passing material with the largest margin
};

/// A plotted curve.
struct Series {
    std::string label;
    std::vector<double> x;
    std::vector<double> y;
};

/// Motion-initiation diagram data for one direction (computed by the pipeline, drawn by the
/// report).
struct InitiationDiagram {
    Direction direction = Direction::x;
    double tan_alpha = 0.0;
    std::vector<double> a_g;                    ///< A samples above tan(alpha)
    std::vector<double> mu_crit;                ///< Shenton's mu_crit(A) at those samples
    std::vector<std::array<double, 2>> points;  ///< (A, mu_s) of each PGA level
};

/// Data behind the report's plots. Empty series mean "not computed" (no histories generated).
struct PlotData {
    std::string governing;              ///< which level/direction/history the histories show
    std::vector<Series> spectra;        ///< 5% target and matched spectra, PSA (g) vs f (Hz)
    std::vector<Series> ground_motion;  ///< acceleration (g) vs time (s)
    std::vector<Series> slip;           ///< slip (m) vs time (s)
    std::vector<Series> rotation;       ///< theta / alpha vs time (s)
    std::vector<InitiationDiagram> initiation;
};

/// SRP 3.7.1 acceptance of one generated component (ratios are scale-free).
struct HistoryCheck {
    int history = 0;        ///< 1-based
    std::string component;  ///< "h1", "h2", "v"
    std::string method;
    /// SRP 3.7.1 and realism checks at the 1 g the set was matched at (ratios are scale-free;
    /// peaks scale with the level).
    motion::Acceptance acceptance;
};

struct JoinedResult;  // assess/joined.hpp

/// The whole assessment.
struct AssessmentResult {
    Case input;
    std::vector<LevelResult> levels;  ///< by PGA, then direction x, y
    /// The case's own base: its governing level among `levels`.
    Governing own;
    /// The headline: the own base's when it passes; else the recommended material's governing
    /// level (index into that trial's levels, not into `levels`), or the own base's failing
    /// level with kind anchor. Level, model and margin always come from one level.
    Governing overall;
    bool overall_from_trial = false;  ///< overall.level indexes the recommended trial's levels
    Upgrade upgrade;
    PlotData plots;
    std::vector<std::string> assumptions;  ///< case defaults plus pipeline choices
    std::vector<std::string> limits;       ///< what the models do not cover
    int histories_generated = 0;
    std::vector<HistoryCheck> history_checks;  ///< empty when no histories were generated
    int simulations_run = 0;
    /// Two units joined by a tunnel (Case::units): each unit's own assessment and the tunnel
    /// check (assess/joined.hpp). levels is then empty; the headline is the pair's.
    std::shared_ptr<const JoinedResult> joined;
};

}  // namespace freestand::assess
