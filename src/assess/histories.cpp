#include "assess/histories.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "assess/history_cache.hpp"
#include "assess/run_cache.hpp"
#include "core/errors.hpp"
#include "core/parallel.hpp"
#include "core/random.hpp"
#include "core/measures.hpp"
#include "core/readers.hpp"
#include "motion/criteria.hpp"
#include "assess/level.hpp"
#include "sliding/table_displacement.hpp"
#include "spectra/design.hpp"

namespace freestand::assess {

namespace {

// Target spectra are tabulated over 0.05-100 Hz, covering the acceptance band 0.1-50 Hz.
std::vector<double> target_frequencies() { return spectra::log_frequencies(0.05, 100.0, 100); }

// User files at 1 g: the same factor 1 / zpa_h_g on every file; vertical = ratio x
// horizontal unless a vertical file is given; h2 follows the y file when given. No target PSD (defined for RG 1.60 only).
motion::TargetSet user_unit_targets(const Site& site, const UserTargets& u) {
    const auto f = target_frequencies();
    const double factor = 1.0 / u.zpa_h_g;
    std::optional<spectra::Spectrum> h10;
    if (u.h10) h10 = scaled_target(u.h10->spectrum, factor, f);
    motion::TargetSet t = motion::ratio_targets(fmt::format("target file {}, PGA 1 g", u.h5.given),
                                                scaled_target(u.h5.spectrum, factor, f), h10,
                                                site.vertical_ratio, site.g_mps2);
    if (u.v) {
        t.vertical.psa_5pct = scaled_target(u.v->spectrum, factor, f);
        t.vertical.psa_10pct.reset();
    }
    if (u.y5) {
        // h2 (direction y) is matched to y's file at the same factor as x's.
        motion::Target y = t.horizontal;
        y.psa_5pct = scaled_target(u.y5->spectrum, factor, f);
        y.psa_10pct.reset();
        if (u.y10) y.psa_10pct = scaled_target(u.y10->spectrum, factor, f);
        t.horizontal_2 = std::move(y);
        t.label += fmt::format("; direction y: target file {}", u.y5->given);
    }
    return t;
}

// RG 1.60 at 1 g: the horizontal spectrum, and RG 1.60's own vertical spectrum scaled to the
// site's vertical PGA (docs/methods.md s.8).
motion::TargetSet rg160_unit_targets(const Site& site) {
    const auto f = target_frequencies();
    motion::TargetSet t;
    t.label = fmt::format("RG 1.60 horizontal and vertical, vertical ZPA {:.4f} x PGA, PGA 1 g",
                          site.vertical_ratio);
    t.horizontal.psa_5pct = spectra::rg160(1.0, 0.05, false, f, site.g_mps2);
    t.horizontal.psa_10pct = spectra::rg160(1.0, 0.10, false, f, site.g_mps2);
    t.horizontal.rg160_psd_pga_g = 1.0;  // the RG 1.60 target PSD applies to the horizontals
    t.horizontal.g_mps2 = site.g_mps2;
    t.vertical = motion::rg160_vertical_target(1.0, site.vertical_ratio, f, site.g_mps2);
    return t;
}

motion::TargetSet unit_targets(const Site& site) {
    motion::TargetSet t =
        site.targets ? user_unit_targets(site, *site.targets) : rg160_unit_targets(site);
    motion::set_realism(t, site.realism);
    return t;
}

// A set that fails SRP 3.7.1 or the realism checks is not used: the assessment stops and says
// which history, which component and why (docs/methods.md s.8: a history that cannot meet
// them is rejected with the reason).
void reject_failing(const Case& c, const std::vector<HistorySet>& sets, std::size_t first) {
    const std::array<const char*, 3> names{"h1", "h2", "v"};
    for (std::size_t k = first; k < sets.size(); ++k) {
        if (sets[k].passed) continue;
        std::string why;
        for (std::size_t j = 0; j < sets[k].acceptance.size() && j < names.size(); ++j) {
            if (sets[k].acceptance[j].passed) continue;
            why += fmt::format("{}{}: {}", why.empty() ? "" : "; ", names[j],
                               sets[k].acceptance[j].reason);
        }
        for (const motion::Correlation& r : sets[k].correlations)
            if (std::abs(r.rho) > motion::criteria::max_abs_correlation)
                why += fmt::format("{}{}-{}: |rho| = {:.3f} > {}", why.empty() ? "" : "; ", r.a,
                                   r.b, std::abs(r.rho), motion::criteria::max_abs_correlation);
        if (!c.options.seed_records.empty()) {
            throw InputError(
                SourceLocation{c.file, 0, "options.seed_records"},
                fmt::format("history {} ({}) does not pass SRP 3.7.1 and the realism checks "
                            "once matched: {}. Give other records, or the realism ranges of the "
                            "earthquakes behind them ([site] va_range_mps_per_g, adv2_range, "
                            "da_max_m_per_g)",
                            k + 1, sets[k].method, why));
        }
        throw NumericalError(fmt::format(
            "history {}: no synthetic record passed SRP 3.7.1 and the realism checks within the "
            "generator's attempts ({}); try another [options] seed",
            k + 1, why));
    }
}

// The generation request of set k: its seed from the case seed, and its seed records.
motion::GenerateOptions generate_options(const Case& c, std::size_t k) {
    motion::GenerateOptions go;
    go.seed = HistoryBank::history_seed(c.options.seed, static_cast<int>(k));
    for (std::size_t j = 0; j < 3 && !c.options.seed_records.empty(); ++j) {
        go.seed_records.push_back(
            core::read_record(c.options.seed_records[3 * k + j], c.site.g_mps2));
    }
    return go;
}

HistorySet generate_one(const motion::TargetSet& targets, const motion::GenerateOptions& go) {
    const motion::GeneratedSet g = motion::generate_set(targets, go);
    HistorySet s;
    s.h1 = g.components.at(0).record;
    s.h2 = g.components.at(1).record;
    s.v = g.components.at(2).record;
    for (const auto& comp : g.components) s.acceptance.push_back(comp.acceptance);
    s.correlations = g.correlations;
    s.passed = g.passed;
    s.method = g.components.at(0).method;
    return s;
}

// What one set yields: the set, and whether the cache held it.
struct Obtained {
    HistorySet set;
    bool from_cache = false;
};

Obtained obtain(const Case& c, const motion::TargetSet& targets, std::size_t k,
                const core::ContentStore* cache) {
    const motion::GenerateOptions go = generate_options(c, k);
    Obtained out;
    std::string key;
    if (cache != nullptr) {
        key = history_key(targets, go, c.options.seed, k);
        if (const auto bytes = cache->get(key)) {
            if (auto set = decode_history(*bytes)) {
                out.set = std::move(*set);
                out.from_cache = true;
                return out;
            }
        }
    }
    out.set = generate_one(targets, go);
    // A set that cannot be stored is only regenerated next time (the store keeps the reason).
    if (cache != nullptr) cache->put(key, encode_history(out.set));
    return out;
}

}  // namespace

HistoryBank::HistoryBank(const Case& c, RunSettings run)
    : case_(&c),
      run_(std::move(run)),
      active_(static_cast<std::size_t>(std::max(1, c.options.histories_per_level))) {
    if (run_.run_cache) excitation_keys_ = std::make_shared<ExcitationKeys>();
}

std::uint64_t HistoryBank::history_seed(std::uint64_t case_seed, int k) {
    return core::sequence_seed(case_seed, static_cast<std::uint64_t>(k));
}

std::size_t HistoryBank::max_sets() const {
    const Options& opt = case_->options;
    // Seed records give exactly histories_per_level sets (sets() refuses any other count).
    if (!opt.seed_records.empty()) return static_cast<std::size_t>(opt.histories_per_level);
    return static_cast<std::size_t>(std::max(opt.histories_per_level, opt.max_histories_per_level));
}

void HistoryBank::use(std::size_t n) {
    if (n == 0 || n > max_sets())
        throw std::invalid_argument(fmt::format("HistoryBank::use({}): expected 1 to {}", n, max_sets()));
    active_ = n;
}

std::span<const HistorySet> HistoryBank::sets() {
    const Options& opt = case_->options;
    if (!opt.seed_records.empty() &&
        opt.seed_records.size() != 3 * static_cast<std::size_t>(opt.histories_per_level)) {
        const std::size_t n = static_cast<std::size_t>(opt.histories_per_level);
        throw InputError(SourceLocation{case_->file, 0, "options.seed_records"},
                         fmt::format("expected 3 records (h1, h2, v) per history, {} in all for "
                                     "histories_per_level = {}, got {}",
                                     3 * n, n, opt.seed_records.size()));
    }
    if (sets_.size() < active_) extend(active_);
    return {sets_.data(), active_};
}

// Sets are made by their index alone (seed, k), so a bank extended to n holds the sets a bank
// asked for n at once would hold.
void HistoryBank::extend(std::size_t n) {
    const std::size_t first = sets_.size();
    const motion::TargetSet targets = unit_targets(case_->site);
    // The sets are independent (own seeds): each lands in its own slot whatever the thread
    // that made it (core/fft.hpp serialises FFTW planning).
    std::vector<Obtained> got(n - first);
    core::parallel_for(
        got.size(), run_.threads,
        [&](std::size_t i) { got[i] = obtain(*case_, targets, first + i, run_.cache); },
        run_.progress ? [&](std::size_t done, std::size_t total) {
            run_.progress("history sets", done, total);
        } : core::ProgressCallback{});
    std::size_t generated_now = 0;
    for (Obtained& o : got) {
        (o.from_cache ? cache_hits_ : generated_now) += 1;
        sets_.push_back(std::move(o.set));
    }
    generated_sets_ += generated_now;
    if (run_.cache != nullptr && generated_now > 0) run_.cache->prune();
    reject_failing(*case_, sets_, first);
    measure_sets(first);
}

// The energy method's DeltaD and the PGV of each set at 1 g (both linear in the level).
void HistoryBank::measure_sets(std::size_t first) {
    const std::size_t n = sets_.size();
    unit_hp_disp_x_m_.resize(n, 0.0);
    unit_hp_disp_y_m_.resize(n, 0.0);
    unit_pgv_x_mps_.resize(n, 0.0);
    unit_pgv_y_mps_.resize(n, 0.0);
    const double corner_hz = case_->site.energy_highpass_hz;
    core::parallel_for(n - first, run_.threads, [&](std::size_t i) {
        const std::size_t k = first + i;
        const HistorySet& s = sets_[k];
        unit_hp_disp_x_m_[k] = sliding::highpass_peak_displacement_m(s.h1, corner_hz);
        unit_hp_disp_y_m_[k] = sliding::highpass_peak_displacement_m(s.h2, corner_hz);
        unit_pgv_x_mps_[k] = core::measure(s.h1, case_->site.g_mps2).pgv_mps;
        unit_pgv_y_mps_[k] = core::measure(s.h2, case_->site.g_mps2).pgv_mps;
    });
}

core::Record HistoryBank::scaled(const core::Record& unit, double pga_g) {
    core::Record r = unit;
    for (double& a : r.accel_mps2) a *= pga_g;
    return r;
}

namespace {
// Peak measures are linear in the scale of the record: the mean of the first n sets' values.
double scaled_mean(const std::vector<double>& unit, std::size_t n, double pga_g) {
    double sum = 0.0;
    for (std::size_t k = 0; k < n; ++k) sum += unit[k];
    return pga_g * sum / static_cast<double>(n);
}
}  // namespace

double HistoryBank::mean_highpass_displacement_m(Direction d, double pga_g) {
    const std::size_t n = sets().size();
    return scaled_mean(d == Direction::x ? unit_hp_disp_x_m_ : unit_hp_disp_y_m_, n, pga_g);
}

double HistoryBank::mean_pgv_mps(Direction d, double pga_g) {
    const std::size_t n = sets().size();
    return scaled_mean(d == Direction::x ? unit_pgv_x_mps_ : unit_pgv_y_mps_, n, pga_g);
}

}  // namespace freestand::assess
