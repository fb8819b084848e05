#pragma once
/// What an assessment found: the pipeline fills it, the report only reads it (issue 6).
/// Absent numbers are std::nullopt with a reason, never a sentinel value.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "assess/case.hpp"

namespace freestand::assess {

/// Initiating mode from rest (METHODS.md s.2).
enum class Mode { rest, slide, rock, slide_rock };
/// "rest", "slide", "rock", "slide-rock".
const char* to_string(Mode m);

/// Which model settled a verdict (issue 6: "each with its margin and the model that decided it").
enum class Model {
    static_initiation,          ///< METHODS.md s.2 static thresholds
    asce4_sliding,              ///< METHODS.md s.4 ASCE 4 equivalent-linear sliding
    energy_sliding,             ///< METHODS.md s.4 energy conservation
    simulation_slide,           ///< METHODS.md s.3 time-history simulation, peak slip
    simulation_residual,        ///< METHODS.md s.3 time-history simulation, residual slip
    equivalent_linear_rocking,  ///< METHODS.md s.5a screen
    simulation_rocking,         ///< METHODS.md s.3 time-history simulation, rocking / overturning
    no_motion,                  ///< METHODS.md s.2 low-motion threshold (peak slip < 1 mm)
};
const char* to_string(Model m);

/// Verdicts in increasing severity (the overall verdict is the most severe).
enum class VerdictKind { acceptable, acceptable_with_clearance, upgrade_material, anchor };
const char* to_string(VerdictKind k);

/// A verdict with its margin (capacity / demand, >= 1 passes) and the model that decided it.
struct Verdict {
    VerdictKind kind = VerdictKind::acceptable;
    std::optional<double> margin;  ///< capacity / demand; absent when unbounded (no demand)
    std::string margin_basis;      ///< what the ratio compares, e.g. "allowable / ASCE 4 slide"
    Model decided_by = Model::static_initiation;
    double clearance_m = 0.0;  ///< clearance needed (acceptable_with_clearance), m
    std::string material;      ///< material to upgrade to (upgrade_material)
};

/// Static classification at the level's peak accelerations (METHODS.md s.2, s.5: vertical
/// taken downward, the worst case).
struct Initiation {
    Mode mode = Mode::rest;
    double a_ratio = 0.0;  ///< A = PGA_h / (1 - PGA_v), both in g
    double mu_s = 0.0;
    double tan_alpha = 0.0;         ///< of the critical edge
    std::optional<double> mu_crit;  ///< Shenton's critical friction at A, when A > tan(alpha)
};

/// Flexible-body screen (issue 6): shown beside the mode, never changes it.
struct FlexibleFlag {
    bool raised = false;
    std::string basis;                ///< e.g. "fixed-base 7.5 Hz; free-rocking band 1.7-4.9 Hz"
    double band_lo_hz = 0.0;          ///< lowest frequency screened (the band may have a gap)
    double band_hi_hz = 0.0;          ///< highest frequency screened
    double peak_psa_in_band_g = 0.0;  ///< 5%-damped target PSA peak in the band
    double uplift_a_g = 0.0;          ///< static uplift threshold g tan(alpha), in g
    std::string reason;               ///< why raised or not, in words
};

/// Closed-form sliding estimates (METHODS.md s.4).
struct Sliding {
    double mu_e = 0.0;
    double c_s_mps2 = 0.0;
    double pgd_m = 0.0;      ///< peak ground displacement used by the energy method
    std::string pgd_source;  ///< where DeltaD came from
    std::optional<double> f_es_hz;
    std::optional<double> slide_asce_m;
    std::optional<double> slide_energy_m;
    std::string reason;  ///< why a value is absent ("" when both present)
};

/// Closed-form rocking and overturning checks (METHODS.md s.5, s.5a).
struct Rocking {
    double alpha_rad = 0.0;
    double R_m = 0.0;
    double p_radps = 0.0;
    double restitution = 0.0;
    double uplift_a_g = 0.0;                ///< A at which uplift starts, g
    double ishiyama_v_mps = 0.0;            ///< velocity bound below which it cannot overturn
    std::optional<double> pgv_mps;          ///< mean PGV of the histories, when they were generated
    bool gate_passed = false;               ///< s.5a gate: PGA > (1 - 0.4 A_v) tan(alpha)
    std::optional<double> theta_rad;        ///< s.5a estimate; absent when gated out or overturning
    bool overturn_predicted = false;        ///< s.5a found no theta below alpha
    std::optional<double> overturn_fs;      ///< alpha / theta; absent when no rocking predicted
    std::optional<double> spectral_margin;  ///< largest spectrum scale with theta < alpha
    std::optional<double> amplification_estimate;  ///< slide: ~mu/A; rest: 1; rock: absent
};

/// Aggregated time-history simulation over the level's histories (METHODS.md s.3).
struct Simulation {
    int histories = 0;
    double slide_max_mean_m = 0.0;
    double slide_max_max_m = 0.0;
    double slide_residual_mean_m = 0.0;  ///< |residual|, mean over histories
    double slide_residual_max_m = 0.0;
    double rock_max_over_alpha_mean = 0.0;  ///< over histories that did not overturn
    double rock_max_over_alpha_max = 0.0;
    double overturned_fraction = 0.0;
    double amplification_mean = 0.0;  ///< top acceleration / PGA
    double amplification_max = 0.0;
    int governing_history = 0;  ///< index of the worst history
};

/// One PGA level in one direction.
struct LevelResult {
    double pga_g = 0.0;
    double pga_v_g = 0.0;
    Direction direction = Direction::x;
    Initiation initiation;
    FlexibleFlag flexible;
    Sliding sliding;
    Rocking rocking;
    std::optional<Simulation> simulation;
    std::string simulation_reason;  ///< why it was run or skipped
    Verdict verdict;
};

/// One material of the upgrade search (METHODS.md s.6 step 5).
struct MaterialTrial {
    std::string material;
    double mu_s = 0.0;
    Verdict verdict;  ///< worst over levels and directions with this material
};

struct Upgrade {
    bool needed = false;                     ///< the case's own base failed somewhere
    std::vector<MaterialTrial> trials;       ///< in METHODS.md s.7 order
    std::optional<std::string> recommended;  ///< weakest material that passes
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
    bool passed = false;
    double min_ratio = 0.0;  ///< 5% computed / target over 0.1-50 Hz
    double max_ratio = 0.0;
    std::string reason;  ///< failed criteria, "" when passed
};

/// The whole assessment.
struct AssessmentResult {
    Case input;
    std::vector<LevelResult> levels;  ///< by PGA, then direction x, y
    Verdict overall;
    std::size_t governing_level = 0;  ///< index into levels of the most severe verdict
    Upgrade upgrade;
    PlotData plots;
    std::vector<std::string> assumptions;  ///< case defaults plus pipeline choices
    std::vector<std::string> limits;       ///< what the models do not cover
    int histories_generated = 0;
    std::vector<HistoryCheck> history_checks;  ///< empty when no histories were generated
    int simulations_run = 0;
};

}  // namespace freestand::assess
