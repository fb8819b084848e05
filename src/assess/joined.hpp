#pragma once
/// Two free-standing units joined by a transfer tunnel (docs/methods.md s.10): each unit is
/// assessed as a component, and at every level both are simulated under the same histories
/// for their relative displacement at the tunnel's height, checked against its slack.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "assess/case.hpp"
#include "assess/histories.hpp"
#include "assess/result.hpp"

namespace freestand::assess {

/// The model name of the tunnel check.
inline constexpr const char* pair_model_name =
    "two rigid planar blocks under the same base motion (docs/methods.md s.10)";

/// The tunnel check in one direction at one level, over the level's histories.
struct TunnelDirection {
    Direction direction = Direction::x;
    /// Per history, the larger relative peak of the two opposite-friction pairings (unit 1 at
    /// its lower friction bound and unit 2 at its upper, and the reverse), m; NaN in `values`
    /// where a unit overturned, the statistics over the other sets.
    Stats relative_m;
    /// Both units at their own lower friction bound (a common floor), m: for comparison.
    Stats relative_common_m;
    int overturned = 0;  ///< histories in which a unit overturned (the tunnel is then lost)
    int governing_history = 0;  ///< 0-based, the largest relative peak
};

/// The tunnel check of one PGA level.
struct TunnelLevel {
    double pga_g = 0.0;
    int histories = 0;
    std::array<TunnelDirection, 2> directions;  ///< x, y
    std::size_t governing_direction = 0;        ///< index into directions
    double demand_m = 0.0;  ///< governing statistic of the governing direction, m
    std::optional<double> margin;  ///< allowable / demand; absent when no relative motion
    bool passes = true;
    std::string model = pair_model_name;
    std::string model_reason;
    std::string text;  ///< the comparison in words
    /// The bootstrap of the tunnel's decision over the sets (docs/methods.md s.6 step 4).
    Settling settling;
};

/// A two-unit case's result (AssessmentResult::joined).
struct JoinedResult {
    Tunnel tunnel;
    std::array<AssessmentResult, 2> units;  ///< each unit assessed as a component
    std::vector<TunnelLevel> levels;
    std::size_t governing_level = 0;  ///< the tunnel's worst level
    bool tunnel_passes = true;
    bool passes = true;    ///< both units and the tunnel pass
    std::string verdict;   ///< the pair's headline: the worst of the units and the tunnel
    std::string remedy;    ///< what to do when the tunnel fails (brace the units), else ""
    std::string bounds;    ///< which friction and restitution the tunnel check ran with, why
};

/// The tunnel check of level `level` of the case's PGA list: both units under every set of the
/// bank, in each direction (docs/methods.md s.10; sampling at the input steps,
/// dynamics::simulate_pair), on options.histories_per_level sets, grown by batches while the
/// decision is unsettled (docs/methods.md s.6 step 4); unsettled at the cap, it fails.
TunnelLevel tunnel_level(const Case& c, std::size_t level, HistoryBank& bank);

/// Assesses a two-unit case (c.units, c.tunnel): each unit as a one-component case with the
/// same site and options, then the tunnel check at every level; the headline is the worst of
/// the units and the tunnel.
AssessmentResult assess_joined(const Case& c, const RunSettings& run = {});

/// The case of unit i alone: the same site, options and uncertainty.
Case unit_case(const Case& c, std::size_t i);

}  // namespace freestand::assess
