#pragma once
/// Settled decisions (docs/methods.md s.6 step 4): the sets of a simulated level are resampled
/// with replacement (a bootstrap from the case seed) and the level's decision is redone on each
/// resample. Fewer than 95% agreeing: the level gets another batch of sets, up to the cap; a
/// level still unsettled at the cap fails, saying so.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "assess/case.hpp"
#include "assess/histories.hpp"
#include "assess/level.hpp"
#include "assess/result.hpp"

namespace freestand::assess {

/// Resamples of the bootstrap (Efron & Tibshirani 1993: 1000-2000 for a percentile or a
/// proportion near 95%).
inline constexpr int bootstrap_resamples = 2000;
/// The share of resamples that must agree with the decision for it to be settled.
inline constexpr double settle_agreement = 0.95;
/// Sets an unsettled level gets per batch.
inline constexpr int settle_batch_sets = 30;
/// The overturn rate a passing level that can uplift must bound. A resample of sets none of
/// which overturned holds no overturn either, so the bootstrap settles "no overturn in N" at any
/// N, however likely an overturn is (at a rate of 2.5%, 0 of 30 happens with probability 0.47).
/// Such a pass is settled only when the Clopper-Pearson 95% upper bound of 0 / N,
/// 1 - 0.025^(1/N), is at most this: N >= 72, so 90 sets in batches of 30 (0 of 120: 3.0%).
inline constexpr double settle_overturn_rate = 0.05;

/// "not settled: P% of B resamples pass at N = n (cap; 95% needed either way)", P the share
/// that passes, from a decision that passed or failed on all sets.
std::string not_settled_text(const Settling& s, bool passed);

/// True when the level's decision rests on its simulation (flexible-body model, or the screen
/// failed and the rigid simulation ran): the decisions the sets can move.
bool decided_by_sets(const LevelResult& level);

/// True when a model the level's decision rests on can uplift, and so overturn: the planar
/// classification at the upper friction bound uplifts, the 3D body ran (the classification of
/// one direction uplifts), or the flexible body uplifted in some set. A flexible body whose base
/// lifted in none of N sets is not held to the overturn bound: an overturn needs an uplift that
/// grows over cycles, so its rate is taken as far below that of any uplift (an assumption,
/// docs/methods.md s.6 step 4).
bool can_overturn(const LevelResult& level);

/// The level's decision (decide_level) redone on the sets at the given indices.
bool passes_on(const LevelResult& level, const std::vector<std::size_t>& sets,
               double allowable_slide_m, double required_fs);

/// The share of bootstrap_resamples resamples of n sets (indices drawn with replacement from
/// stream `seed`) on which `passes_on_sets` gives `decision`.
double bootstrap_agreement(std::size_t n, std::uint64_t seed, bool decision,
                           const std::function<bool(const std::vector<std::size_t>&)>& passes_on_sets);

/// The bootstrap of the level's decision from stream `seed`.
Settling settle(const LevelResult& level, std::uint64_t seed, double allowable_slide_m,
                double required_fs);

/// Both directions of one PGA level (index `level` in the case's list), with biaxial sliding,
/// evaluated on options.histories_per_level sets, then on settle_batch_sets more while a decision
/// the sets can move is unsettled, up to bank.max_sets(); an unsettled decision at the cap fails.
std::vector<LevelResult> evaluate_settled(const Case& c, const LevelDemand& demand,
                                          std::size_t level, HistoryBank& bank);

}  // namespace freestand::assess
