#pragma once
/// Simulation runs in a content-addressed cache (core::ContentStore), beside the history sets.
/// A run is a function of its model, its excitation, its options and the build alone, and its
/// key is the SHA-256 of all of them, so a run read back is the run that would be computed, bit
/// for bit: a second assessment of an unchanged case reads its runs instead of simulating them,
/// and every output is the same with or without the cache (docs/methods.md s.12).
#include <cstddef>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>

#include "assess/histories.hpp"
#include "core/content_store.hpp"
#include "dynamics/biaxial.hpp"
#include "dynamics/body3d.hpp"
#include "dynamics/flexible.hpp"
#include "dynamics/simulate.hpp"

namespace freestand::assess {

/// Raised whenever a change of the simulation engines (dynamics, block) would change a run's
/// summary: the build's identity names the compiler and flags, not the sources, so this is what
/// keeps a cache from serving an old engine's run. A test holds the digest of reference runs
/// and fails until it is raised.
inline constexpr const char* engine_version = "6";

/// The part of a run's key that names its excitation: the SHA-256 of its numbers (its label
/// names it only). Computing it reads every sample, so a bank keeps one per excitation
/// (ExcitationKeys) for the runs that share it.
std::string excitation_key(const dynamics::Excitation& ex);
std::string excitation_key(const dynamics::BiaxialExcitation& ex);

/// The summary of the planar rigid block's run (dynamics::simulate) of the excitation ex, whose
/// excitation_key is ex_key: from `store` when it holds it, else simulated and stored;
/// simulated alone without a store. opt.record_series must be false (a cached run has no
/// series).
dynamics::Summary rigid_run(const core::ContentStore* store, const dynamics::BlockModel& model,
                            const dynamics::Excitation& ex, const std::string& ex_key,
                            const dynamics::Options& opt);

/// As rigid_run, for the flexible body (dynamics::simulate_flexible).
dynamics::FlexibleSummary flexible_run(const core::ContentStore* store,
                                       const dynamics::FlexibleModel& model,
                                       const dynamics::Excitation& ex, const std::string& ex_key,
                                       const dynamics::Options& opt);

/// As rigid_run, for the biaxial block's peak |u| (dynamics::simulate_biaxial), m.
double biaxial_peak_run(const core::ContentStore* store, const dynamics::BiaxialModel& model,
                        const dynamics::BiaxialExcitation& ex, const std::string& ex_key,
                        const dynamics::Options& opt);

/// As rigid_run, for the 3D body (dynamics::simulate_body3d), with or without a mode.
dynamics::Body3dSummary body3d_run(const core::ContentStore* store,
                                   const dynamics::Body3dModel& model,
                                   const dynamics::BiaxialExcitation& ex,
                                   const std::string& ex_key, const dynamics::Body3dOptions& opt);

/// The keys (64 hex digits) and the encodings the functions above use.
std::string rigid_run_key(const dynamics::BlockModel& model, const std::string& ex_key,
                          const dynamics::Options& opt);
std::string flexible_run_key(const dynamics::FlexibleModel& model, const std::string& ex_key,
                             const dynamics::Options& opt);
std::string biaxial_run_key(const dynamics::BiaxialModel& model, const std::string& ex_key,
                            const dynamics::Options& opt);
std::string body3d_run_key(const dynamics::Body3dModel& model, const std::string& ex_key,
                           const dynamics::Body3dOptions& opt);
std::string encode_summary(const dynamics::Summary& s);
/// None when the bytes are not a whole summary of this format.
std::optional<dynamics::Summary> decode_summary(std::string_view bytes);
std::string encode_flexible_summary(const dynamics::FlexibleSummary& s);
std::optional<dynamics::FlexibleSummary> decode_flexible_summary(std::string_view bytes);
std::string encode_body3d_summary(const dynamics::Body3dSummary& s);
std::optional<dynamics::Body3dSummary> decode_body3d_summary(std::string_view bytes);

/// The excitation keys of a bank's sets, each computed once and shared by every run, model
/// and material trial that uses the excitation. Safe to use from several threads.
class ExcitationKeys {
  public:
    /// The key of set k's excitation `ex` along `axis` (0: x, 1: y, 2: both horizontals) at
    /// pga_g; ex must be that excitation.
    template <class Excitation>
    std::string of(std::size_t k, int axis, double pga_g, const Excitation& ex) {
        const Id id{k, axis, pga_g};
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            if (const auto it = keys_.find(id); it != keys_.end()) return it->second;
        }
        std::string key = excitation_key(ex);
        const std::lock_guard<std::mutex> lock(mutex_);
        return keys_.emplace(id, std::move(key)).first->second;
    }

  private:
    using Id = std::tuple<std::size_t, int, double>;
    std::mutex mutex_;
    std::map<Id, std::string> keys_;
};

template <class Excitation>
std::string HistoryBank::excitation_key(std::size_t k, int axis, double pga_g,
                                        const Excitation& ex) {
    return excitation_keys_ ? excitation_keys_->of(k, axis, pga_g, ex) : std::string();
}

}  // namespace freestand::assess
