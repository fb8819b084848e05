#pragma once
/// Motion initiation from rest: rest / slide / rock / slide-rock (docs/methods.md s.2).
/// Static boundaries of a rigid block under a step of base acceleration; the rocking checks,
/// the simulator's start-up and the assessment all classify through these functions.
#include <optional>
#include <string>

#include "block/block.hpp"
#include "block/edge_pair.hpp"
#include "block/mode.hpp"

namespace freestand::sliding {

/// Initiating mode of a rigid block at rest: rest, slide, rock or slide-rock (never flight).
using Mode = block::Mode;
/// "rest", "slide", "rock", "slide-rock".
using block::to_string;

/// Which boundary of docs/methods.md s.2 decided the mode.
enum class Criterion {
    below_thresholds,            ///< A <= mu_s and A <= tan(alpha): rest
    friction_below_slenderness,  ///< A > mu_s and mu_s <= tan(alpha): slide
    friction_holds_at_uplift,    ///< A > tan(alpha), mu_s > tan(alpha), mu_s >= mu_crit(A): rock
    friction_fails_at_uplift,    ///< A > tan(alpha) and tan(alpha) < mu_s < mu_crit(A): slide-rock
};

/// The inequality behind the criterion, e.g. "A > tan(alpha) and tan(alpha) < mu_s < mu_crit(A)".
std::string describe(Criterion criterion);

/// Classification about one rocking edge.
struct Initiation {
    block::Edge edge = block::Edge::right;  ///< the edge the block would tip over
    Mode mode = Mode::rest;
    double A = 0.0;          ///< |a_h| / (g + a_v), dimensionless
    double tan_alpha = 0.0;  ///< b / h of this edge
    /// Friction needed at the pivot for pure rocking at uplift, mu_crit(A). Set only when
    /// A > tan(alpha) (uplift is demanded); otherwise empty and mu_crit_reason says why.
    std::optional<double> mu_crit;
    std::string mu_crit_reason;
    Criterion decided_by = Criterion::below_thresholds;
};

/// Horizontal-to-vertical load ratio A = |a_h| / (1 + a_v) for accelerations in g, a_v positive
/// up. Throws InputError (field "a_v_g") when 1 + a_v <= 0: the block is in free flight and the
/// static classification does not apply; and for non-finite input.
double load_ratio(double a_h_g, double a_v_g);

/// Friction ratio |F| / N needed at the pivot of edge e at the instant of uplift
/// (theta = theta' = 0) under load ratio A; for a uniform block it is Shenton's (1996)
/// (A (1 + 4 gamma^2) + 3 gamma) / (4 + gamma^2 + 3 A gamma), gamma = tan(alpha).
/// mu_crit(tan(alpha)) = tan(alpha); increasing in A. Requires A >= 0.
double mu_crit(const block::Block& blk, block::Edge e, double A);

/// Classifies about edge e for a horizontal acceleration magnitude a_h_g >= 0 and a signed
/// vertical a_v_g (g, positive up) with static friction mu_s >= 0. Boundary semantics: rest while
/// A <= mu_s and A <= tan(alpha) (equality is rest); pure rock when mu_s >= mu_crit(A).
/// Throws InputError naming mu_s / a_h_g / a_v_g for out-of-range input.
Initiation classify_edge(const block::Block& blk, block::Edge e, double mu_s, double a_h_g,
                         double a_v_g);

/// Classifies an instantaneous signed base acceleration: a_h_g < 0 (base accelerating left)
/// tips the block over its right edge, a_h_g > 0 over its left edge (docs/methods.md s.3);
/// a_h_g = 0 reports the critical edge (always rest).
Initiation classify_signed(const block::Block& blk, double mu_s, double a_h_g, double a_v_g);

/// Both edges under peak accelerations of unknown sign: horizontal peak_h_g >= 0 in either
/// direction, vertical peak_v_g >= 0 applied downward (the worst case for every mode, since it
/// lowers the effective gravity): A = peak_h / (1 - peak_v).
/// The governing edge is the critical edge (smaller alpha: tips first). Its classification
/// always shows the most motion of the two (rest < slide < rock family), because tan(alpha) is
/// smaller there.
struct PeakInitiation : block::EdgePair<Initiation> {};

/// See PeakInitiation. Throws InputError for peak_h_g < 0, peak_v_g < 0 or peak_v_g >= 1.
PeakInitiation classify_peak(const block::Block& blk, double mu_s, double peak_h_g,
                             double peak_v_g);

}  // namespace freestand::sliding
