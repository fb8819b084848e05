#pragma once
/// The anchoring decision (docs/methods.md s.6) as pure functions of the checks' results, so every
/// branch can be tested on hand-built inputs.
///
/// Policy: the screen (static criteria, ASCE 4 sliding at the lower friction bound, the
/// equivalent-linear rocking estimate at the upper bounds) decides a level that passes it. A
/// level that fails the screen needs the time-history simulation, which then governs it, pass
/// or fail; only `simulate = "never"` lets the screen decide a failure. The energy-conservation
/// estimate is informational: it neither decides nor triggers anything.
#include <string>
#include <string_view>
#include <vector>

#include "assess/result.hpp"

namespace freestand::assess {

/// Below both thresholds the response is "no motion" (docs/methods.md s.2).
inline constexpr double no_motion_slide_m = 1e-3;
inline constexpr double no_motion_rock_rad = 0.003;

/// The screen of one level from its initiation (both bounds), sliding and rocking results.
Screen screen_level(const LevelResult& closed, double allowable_slide_m, double required_fs);

/// Whether to simulate a level, and why. "auto" simulates wherever the closed forms leave the
/// verdict open, so "auto" and "always" give the same verdict.
struct SimulationNeed {
    bool run = false;
    std::string reason;
};

/// "never": no. "always": yes. "auto": exactly when the screen failed.
SimulationNeed simulation_need(const Screen& screen, SimulatePolicy policy);

/// The simulation's verdict: sliding at the sliding bound (governing statistic of the peak slip
/// against the allowable), rocking at the rocking bound (any overturn fails; the governing
/// statistic of theta_max / alpha against 1 / FS_required); the more severe of the two. When
/// biaxial sliding ran (biaxial->ran), its peak |u| is the sliding demand (docs/methods.md s.10).
Verdict simulation_verdict(const Simulation& sim, double allowable_slide_m, double required_fs,
                           const BiaxialSlide* biaxial = nullptr);

/// The level's verdict: the screen's when it passed (a simulation run then is reported beside
/// it), the simulation's when the screen failed and it ran, else the screen's failure.
/// Carries the flexible-body open condition when the flag is raised at a passing level.
Verdict decide_level(const LevelResult& level, double allowable_slide_m, double required_fs);

/// Whether the 3D body decides the level (docs/methods.md s.11): it ran, and either no
/// flexible body ran or the 3D body carried its mode (a rigid 3D body beside a flexible one
/// shares the decision: the worse of the two governs).
bool body3d_decides(const LevelResult& level);

/// Screen result -> why simulated -> what governed, one line each.
std::vector<std::string> decision_trail(const LevelResult& level, double allowable_slide_m,
                                        double required_fs);

/// The level's verdict and trail made again from what it now holds (after a later model joined
/// it), with the component's allowable slide and required factor of safety.
void redecide_level(LevelResult& level, const Component& component);

/// True for acceptable and acceptable_with_clearance.
bool passes(const Verdict& v);

/// True when a is strictly more severe than b: a failure over a pass; among passes a level that
/// moves over one with no motion; then the smaller margin (a "no motion" verdict carries its
/// static or demand margin; one without any is the least severe); then the larger clearance.
bool more_severe(const Verdict& a, const Verdict& b);

/// The most severe level (the first on ties) with its verdict. levels must not be empty.
Governing governing_of(const std::vector<LevelResult>& levels);

/// Largest clearance any level needs, m (0 when none slides measurably).
double clearance_needed_m(const std::vector<LevelResult>& levels);

/// Open conditions of every level (flexible-body flag at passing levels), merged in order.
std::vector<std::string> open_conditions(const std::vector<LevelResult>& levels);

/// The verdict line: "free-standing acceptable", "acceptable with clearance >= 47 mm",
/// "change base material to steel (higher friction: ...)" or "anchor". The clearance is rounded
/// up to whole mm.
std::string verdict_text(const Verdict& v);

/// True when text is a verdict line verdict_text can write for a verdict of this kind (the
/// clearance, the material and the mechanism free): how a summary row read back is checked.
bool verdict_text_fits(VerdictKind kind, std::string_view text);

/// "1.15", or "4.02 (no motion)" when the demand is negligible.
std::string margin_text(const Verdict& v);

}  // namespace freestand::assess
