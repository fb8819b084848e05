#pragma once
/// Spectrum-compatible histories of a case, generated once on first use and shared by every
/// level, direction and material trial. RG 1.60 with a vertical ratio is linear in the PGA, so
/// the sets are matched at 1 g and scaled: a scaled record matches the scaled target with the
/// same ratios (response spectra are linear in the input). Sets are generated on every core
/// and read from the history cache when it holds them (assess/history_cache.hpp).
#include <cstdint>
#include <string>
#include <vector>

#include "assess/case.hpp"
#include "assess/run_settings.hpp"
#include "core/record.hpp"
#include "motion/motion.hpp"

namespace freestand::assess {

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

    /// The options.histories_per_level sets at 1 g, generating them on first call. Throws
    /// InputError when options.seed_records is not three records (h1, h2, v) per history.
    const std::vector<HistorySet>& sets();
    bool generated() const { return generated_; }

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

    /// Sets read from the cache, and sets generated, by sets().
    std::size_t cache_hits() const { return cache_hits_; }
    std::size_t generated_sets() const { return generated_sets_; }

  private:
    void measure_sets();

    const Case* case_;
    RunSettings run_;
    bool generated_ = false;
    std::size_t cache_hits_ = 0;
    std::size_t generated_sets_ = 0;
    std::vector<HistorySet> sets_;
    std::vector<double> unit_hp_disp_x_m_;
    std::vector<double> unit_hp_disp_y_m_;
    std::vector<double> unit_pgv_x_mps_;
    std::vector<double> unit_pgv_y_mps_;
};

}  // namespace freestand::assess
