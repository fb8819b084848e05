#pragma once
/// Simulation runs in a content-addressed cache (core::ContentStore), beside the history sets.
/// A run is a function of its model, its excitation, its options and the build alone, and its
/// key is the SHA-256 of all of them, so a run read back is the run that would be computed, bit
/// for bit: a second assessment of an unchanged case reads its runs instead of simulating them,
/// and every output is the same with or without the cache (docs/methods.md s.12).
#include <optional>
#include <string>
#include <string_view>

#include "core/content_store.hpp"
#include "dynamics/biaxial.hpp"
#include "dynamics/flexible.hpp"
#include "dynamics/simulate.hpp"

namespace freestand::assess {

/// The summary of the planar rigid block's run (dynamics::simulate), from `store` when it
/// holds it, else simulated and stored; simulated alone without a store. opt.record_series
/// must be false (a cached run has no series).
dynamics::Summary rigid_run(const core::ContentStore* store, const dynamics::BlockModel& model,
                            const dynamics::Excitation& ex, const dynamics::Options& opt);

/// As rigid_run, for the flexible body (dynamics::simulate_flexible).
dynamics::FlexibleSummary flexible_run(const core::ContentStore* store,
                                       const dynamics::FlexibleModel& model,
                                       const dynamics::Excitation& ex,
                                       const dynamics::Options& opt);

/// As rigid_run, for the biaxial block's peak |u| (dynamics::simulate_biaxial), m.
double biaxial_peak_run(const core::ContentStore* store, const dynamics::BiaxialModel& model,
                        const dynamics::BiaxialExcitation& ex, const dynamics::Options& opt);

/// The keys (64 hex digits) and the encodings the functions above use.
std::string rigid_run_key(const dynamics::BlockModel& model, const dynamics::Excitation& ex,
                          const dynamics::Options& opt);
std::string flexible_run_key(const dynamics::FlexibleModel& model, const dynamics::Excitation& ex,
                             const dynamics::Options& opt);
std::string biaxial_run_key(const dynamics::BiaxialModel& model,
                            const dynamics::BiaxialExcitation& ex, const dynamics::Options& opt);
std::string encode_summary(const dynamics::Summary& s);
/// None when the bytes are not a whole summary of this format.
std::optional<dynamics::Summary> decode_summary(std::string_view bytes);
std::string encode_flexible_summary(const dynamics::FlexibleSummary& s);
std::optional<dynamics::FlexibleSummary> decode_flexible_summary(std::string_view bytes);

}  // namespace freestand::assess
