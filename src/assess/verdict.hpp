#pragma once
/// The anchoring decision (METHODS.md s.6) as pure functions of the checks' results, so every
/// branch can be tested on hand-built inputs.
#include <string>
#include <vector>

#include "assess/result.hpp"

namespace freestand::assess {

/// Below this peak slip the response is "no motion" (METHODS.md s.2), m.
inline constexpr double no_motion_slide_m = 1e-3;

/// Whether to simulate a level, and why (issue 6 "model only what the scene needs").
struct SimulationNeed {
    bool run = false;
    std::string reason;
};

/// Policy "auto": rest -> no; slide -> only when the ASCE 4 and energy estimates straddle the
/// allowable (one within, one beyond) or no closed form applies although the block slides;
/// rock and slide-rock -> always (the s.5a estimate is a screen, the simulation the reference).
/// "always" / "never" override. Reads only initiation, sliding and rocking of `closed`.
SimulationNeed simulation_need(const LevelResult& closed, double allowable_slide_m,
                               SimulatePolicy policy);

/// Verdict of one level with the case's own base. Sliding (modes slide, slide-rock, or any
/// simulated slip >= 1 mm) against allowable_slide_m: with a simulation, the larger of its peak
/// and residual slip (max over histories) governs (the reference, METHODS.md s.4); without, the
/// closed forms: the larger governs, except that when both exceed the allowable the smaller
/// decides the failure. Failing gives upgrade_material (material set after the search).
/// Rocking (rock, slide-rock) is decided by the simulation when run (any overturned history,
/// or alpha / theta_max below required_fs, fails), otherwise by the s.5a factor of safety;
/// failing gives anchor. The more severe of the two is returned.
Verdict decide_level(const LevelResult& level, double allowable_slide_m, double required_fs);

/// True for acceptable and acceptable_with_clearance.
bool passes(const Verdict& v);

/// The more severe of two verdicts: higher kind; for equal kinds the larger clearance, then
/// the smaller margin.
const Verdict& more_severe(const Verdict& a, const Verdict& b);

/// Index of the most severe verdict in levels (0 when empty).
std::size_t governing_index(const std::vector<LevelResult>& levels);

/// Overall verdict: the most severe level verdict when all pass; otherwise "upgrade base
/// material to M" with the recommended material's governing verdict, or "anchor" with the
/// governing failing level's margin and model when no material passes.
Verdict overall_verdict(const std::vector<LevelResult>& levels, const Upgrade& upgrade);

/// Sets the material (or anchor) of failing slide levels once the upgrade search is done.
void apply_upgrade(std::vector<LevelResult>& levels, const Upgrade& upgrade);

/// The verdict line: "free-standing acceptable", "acceptable with clearance >= 47 mm",
/// "upgrade base material to steel" or "anchor". The clearance is rounded up to whole mm.
std::string verdict_text(const Verdict& v);

}  // namespace freestand::assess
