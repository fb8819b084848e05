#pragma once
/// Spectrum-compatible histories of a case, generated once on first use and shared by every
/// level, direction and material trial. RG 1.60 with a vertical ratio is linear in the PGA, so
/// the sets are matched at 1 g and scaled: a scaled record matches the scaled target with the
/// same ratios (response spectra are linear in the input). Sets are generated on every core
/// and read from the history cache when it holds them (assess/history_cache.hpp).
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "assess/case.hpp"
#include "assess/run_settings.hpp"
#include "core/record.hpp"
#include "motion/motion.hpp"

namespace freestand::assess {

class ExcitationKeys;
class LevelRuns;

/// One three-component history at the reference PGA of 1 g.
struct HistorySet {
    core::Record h1;                             ///< applied along x
    core::Record h2;                             ///< applied along y
    core::Record v;                              ///< vertical, positive up
    std::vector<motion::Acceptance> acceptance;  ///< h1, h2, v at 1 g (ratios scale-free)
    std::vector<motion::Correlation> correlations;
    bool passed = false;
    std::string method;
};

class HistoryBank {
  public:
    /// Nothing is generated until sets() is first called, then on run.threads threads, each
    /// set read from run.cache when there and written to it when generated; the sets do not
    /// depend on either.
    explicit HistoryBank(const Case& c, RunSettings run = {});

    /// The run's settings: the simulations of the levels use its threads too.
    const RunSettings& run() const { return run_; }

    /// The sets in use at 1 g (the first options.histories_per_level until use() says
    /// otherwise), generating those not yet made. Throws InputError when options.seed_records
    /// is not three records (h1, h2, v) per history.
    std::span<const HistorySet> sets();
    /// Puts the first n sets in use (1 <= n <= max_sets()); they are made on the next sets().
    void use(std::size_t n);
    /// The most sets a level may use: options.max_histories_per_level, or the seed records'.
    std::size_t max_sets() const;
    /// The runs kept for the level being evaluated (assess/level_runs.hpp), or null: a level
    /// that grows its sets (settle.cpp) keeps its runs here while it does.
    LevelRuns* level_runs() const { return level_runs_; }
    void keep_level_runs(LevelRuns* runs) { level_runs_ = runs; }
    /// The run cache's key of set k's excitation ex along axis (0: x, 1: y, 2: both) at pga_g,
    /// computed once per excitation (assess/run_cache.hpp); "" without a run cache.
    template <class Excitation>
    std::string excitation_key(std::size_t k, int axis, double pga_g, const Excitation& ex);
    /// Every set made so far (at least those in use once sets() ran), in index order.
    const std::vector<HistorySet>& made() const { return sets_; }
    bool generated() const { return !sets_.empty(); }

    /// The horizontal record of a direction scaled to pga_g, in m/s^2.
    static core::Record scaled(const core::Record& unit, double pga_g);
    /// Mean peak displacement of the direction's horizontal records at pga_g after the
    /// case's zero-phase high-pass (site.energy_highpass_hz), m: the energy method's DeltaD.
    double mean_highpass_displacement_m(Direction d, double pga_g);
    /// Mean peak ground velocity of the direction's horizontal records at pga_g, m/s.
    double mean_pgv_mps(Direction d, double pga_g);

    /// The seed of history k derived from the case seed (splitmix64, so nearby case seeds give
    /// unrelated streams).
    static std::uint64_t history_seed(std::uint64_t case_seed, int k);

    /// Sets read from the cache, and sets generated, by sets() so far.
    std::size_t cache_hits() const { return cache_hits_; }
    std::size_t generated_sets() const { return generated_sets_; }

  private:
    void extend(std::size_t n);
    void measure_sets(std::size_t first);

    const Case* case_;
    RunSettings run_;
    std::size_t active_;
    LevelRuns* level_runs_ = nullptr;
    std::shared_ptr<ExcitationKeys> excitation_keys_;
    std::size_t cache_hits_ = 0;
    std::size_t generated_sets_ = 0;
    std::vector<HistorySet> sets_;
    std::vector<double> unit_hp_disp_x_m_;
    std::vector<double> unit_hp_disp_y_m_;
    std::vector<double> unit_pgv_x_mps_;
    std::vector<double> unit_pgv_y_mps_;
};

}  // namespace freestand::assess
