#pragma once
/// The ASCE 43-05 performance goal (s.1.3; docs/methods.md s.6 step 5): about 1% probability of
/// unacceptable performance at the design-basis earthquake (DBE) and about 10% at 1.5 x DBE,
/// estimated with the fragility engine (docs/methods.md s.9) at multiples of the DBE.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "assess/case.hpp"
#include "assess/result.hpp"
#include "assess/run_settings.hpp"
#include "fragility/fit.hpp"
#include "fragility/fragility.hpp"

namespace freestand::goal {

/// The targets of ASCE 43-05 s.1.3: P(failure) at the DBE and at 1.5 x DBE.
inline constexpr double target_dbe = 0.01;
inline constexpr double target_150 = 0.10;
/// The levels the engine runs, as multiples of the DBE; those above the engine's 3 g are left
/// out (a note says so, and P at 1.5 x DBE is then read off the fitted curve).
inline constexpr std::array<double, 8> dbe_multiples{0.5, 0.75, 1.0, 1.25, 1.5, 2.0, 2.5, 3.0};
/// Samples per level: the floor of docs/methods.md s.6 step 3 (about 30 sets per level).
inline constexpr int samples_per_level = 30;

/// One failure event of docs/methods.md s.9 against the two targets.
struct LimitState {
    fragility::Event event = fragility::Event::any;
    fragility::Probability at_dbe;  ///< P at the DBE, 95% profile-likelihood interval
    fragility::Probability at_150;  ///< P at 1.5 x DBE, likewise
    fragility::EventFit fit;        ///< theta_m and beta, or why there is no curve
    /// min(target / P) over the two PGAs (capacity over demand, >= 1 meets the goal); none when
    /// both estimates are 0.
    std::optional<double> margin;
    bool at_150_governs = false;  ///< the margin is 1.5 x DBE's (else the DBE's)
    bool passes = true;           ///< neither point estimate exceeds its target
};

struct PerformanceGoal {
    double dbe_pga_g = 0.0;
    /// The configuration it was evaluated for, in words: the case's own base or the
    /// recommended material (the headline's).
    std::string configuration;
    /// The engine's run: its levels (g), samples per level, seed and pool in config, and the
    /// laws the samples drew friction, restitution and motions from.
    fragility::Meta meta;
    std::string models;                      ///< the simulation models the samples ran, in words
    std::vector<fragility::Level> levels;    ///< counts per level and event
    std::array<LimitState, 4> limit_states;  ///< indexed like fragility::all_events
    std::size_t governing = 3;  ///< the limit state with the least margin (ties: the first)
    bool passes = true;         ///< every limit state meets both targets
    /// What the estimate rests on and where it departs from the case's own levels, in words.
    std::vector<std::string> notes;

    const LimitState& governing_state() const { return limit_states.at(governing); }
};

/// The goal of case c (its site.dbe_pga_g; std::invalid_argument without one): the fragility
/// engine at dbe_multiples x DBE (up to 3 g), samples_per_level samples each, seeded by the
/// case's seed and drawing from the case's own history sets (histories_per_level of them,
/// shared with the assessment through run's cache), with the models the case's levels decide
/// with (the flexible body where its flag is raised, biaxial sliding for samples that only
/// slide). Same result at any thread count. Throws InputError for two [[unit]] tables,
/// NumericalError as the engine does.
PerformanceGoal evaluate_goal(const assess::Case& c, const assess::RunSettings& run = {});

/// The case the headline speaks for: the case's own base when it passes or no material does,
/// else the recommended material's case (assess::with_base_material), with its description.
struct HeadlineCase {
    assess::Case c;
    std::string configuration;
};
HeadlineCase headline_case(const assess::AssessmentResult& r);

/// evaluate_goal for the headline's case, its configuration named.
PerformanceGoal evaluate_headline_goal(const assess::AssessmentResult& r,
                                       const assess::RunSettings& run = {});

/// A passing headline becomes the goal's failure when the goal fails (docs/methods.md s.6 step
/// 5: the verdict needs the levels and the goal both): kind anchor, Failure::performance_goal,
/// the governing limit state's margin and its basis in words, Model::fragility_goal, at the
/// governing PGA; the headline's configuration (overall_from_trial) and open conditions stay.
/// A failing headline, or a passing goal, leaves r as it is.
void apply_goal(assess::AssessmentResult& r, const PerformanceGoal& g);

/// "P(any failure at DBE 0.20 g) = 3.1% > 1%": the governing limit state against its target.
std::string goal_basis(const PerformanceGoal& g);

/// A probability in percent to two significant digits ("3.1%", "0.052%"), whole from 10%,
/// "<0.01%" below 0.01% and "0%" for 0.
std::string percent_text(double p);

/// "overturning", "sliding beyond the allowable", "rocking FS below the required", "any
/// failure".
const char* failure_phrase(fragility::Event e);

}  // namespace freestand::goal
