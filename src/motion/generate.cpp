#include <fmt/format.h>

#include <chrono>
#include <cmath>

#include "core/errors.hpp"
#include "core/random.hpp"
#include "core/limits.hpp"
#include "core/units.hpp"
#include "motion/criteria.hpp"
#include "motion/internal.hpp"
#include "spectra/response.hpp"

namespace freestand::motion {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kQuickPasses = 16;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

const Target& target_for(const TargetSet& targets, const std::string& component) {
    if (component == "v") return targets.vertical;
    if (component == "h2" && targets.horizontal_2) return *targets.horizontal_2;
    return targets.horizontal;
}

double correlation(const core::Record& a, const core::Record& b) {
    const std::size_t n = std::min(a.size(), b.size());
    double ma = 0.0, mb = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        ma += a.accel_mps2[i];
        mb += b.accel_mps2[i];
    }
    ma /= static_cast<double>(n);
    mb /= static_cast<double>(n);
    double sab = 0.0, saa = 0.0, sbb = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double x = a.accel_mps2[i] - ma;
        const double y = b.accel_mps2[i] - mb;
        sab += x * y;
        saa += x * x;
        sbb += y * y;
    }
    return saa > 0.0 && sbb > 0.0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

void check_request(const TargetSet& targets, const GenerateOptions& o) {
    if (o.components.empty())
        throw InputError(SourceLocation{"", 0, "components"}, "no component requested");
    for (std::size_t i = 0; i < o.components.size(); ++i) {
        const std::string& c = o.components[i];
        if (c != "h1" && c != "h2" && c != "v")
            throw InputError(SourceLocation{"", 0, "components"},
                             fmt::format("unknown component \"{}\"; expected h1, h2 or v", c));
        for (std::size_t j = 0; j < i; ++j)
            if (o.components[j] == c)
                throw InputError(SourceLocation{"", 0, "components"},
                                 fmt::format("component \"{}\" given twice", c));
        validate_target(target_for(targets, c).psa_5pct, 0.05);
    }
    if (o.seed_records.empty()) {
        require_positive(o.dt_s, SourceLocation{"", 0, "dt_s"});
        require_positive(o.duration_s, SourceLocation{"", 0, "duration_s"});
        if (criteria::dt_too_coarse(o.dt_s))
            throw InputError(
                SourceLocation{"", 0, "dt_s"},
                fmt::format("dt {} s is too coarse: SRP 3.7.1 needs dt <= {} s, and the Nyquist "
                            "frequency {} Hz is below the {} Hz top of the acceptance band",
                            o.dt_s, criteria::max_dt_s, 0.5 / o.dt_s, criteria::band_high_hz));
        if (criteria::too_short(o.duration_s))
            throw InputError(SourceLocation{"", 0, "duration_s"},
                             fmt::format("duration {} s is too short: SRP 3.7.1 needs >= {} s",
                                         o.duration_s, criteria::min_duration_s));
        // Before synthesize allocates duration / dt samples: unchecked, --duration 1e7 would
        // take 24 GB and --dt 1e-7 would run without end (README "Limits").
        core::limits::require_within(o.duration_s / o.dt_s + 1.0, core::limits::max_samples,
                                     SourceLocation{"", 0, "duration_s"},
                                     "the synthetic record's sampling (duration / dt)");
        return;
    }
    if (o.seed_records.size() != o.components.size())
        throw InputError(
            SourceLocation{"", 0, "seed_records"},
            fmt::format("{} seed records for {} components; give one seed record per component",
                        o.seed_records.size(), o.components.size()));
    for (const core::Record& r : o.seed_records) {
        core::validate(r);
        // An all-zero record has no spectrum to scale to the target: the scale factor would be
        // infinite and the error a misleading "sample 0 is not a finite number".
        bool moves = false;
        for (double a : r.accel_mps2) moves = moves || a != 0.0;
        if (!moves)
            throw InputError(SourceLocation{r.source, 0, ""},
                             fmt::format("seed record \"{}\" is zero at all {} samples; a seed "
                                         "record needs motion to match",
                                         r.name, r.accel_mps2.size()));
        const SourceLocation where{r.source, 0, "dt"};
        if (criteria::dt_too_coarse(r.dt_s))
            throw InputError(
                where,
                fmt::format("seed record dt {} s is too coarse: SRP 3.7.1 needs dt <= {} s "
                            "(Nyquist {} Hz below the {} Hz acceptance band)",
                            r.dt_s, criteria::max_dt_s, 0.5 / r.dt_s, criteria::band_high_hz));
        if (criteria::too_short(r.duration_s()))
            throw InputError(SourceLocation{r.source, 0, "duration"},
                             fmt::format("seed record lasts {:.3f} s; SRP 3.7.1 needs >= {} s",
                                         r.duration_s(), criteria::min_duration_s));
    }
}

bool correlated_with_earlier(const std::vector<GeneratedComponent>& done, const core::Record& r) {
    for (const GeneratedComponent& g : done)
        if (std::abs(correlation(g.record, r)) > criteria::max_abs_correlation) return true;
    return false;
}

GeneratedComponent synthetic_component(const Target& target, const GenerateOptions& o,
                                       std::size_t index,
                                       const std::vector<GeneratedComponent>& done,
                                       std::vector<std::string>& notes) {
    const auto start = Clock::now();
    GeneratedComponent best;
    const std::string& name = o.components[index];
    for (int attempt = 0; attempt < o.max_attempts; ++attempt) {
        const std::uint64_t seed =
            core::component_seed(o.seed, index, static_cast<std::uint64_t>(attempt));
        core::Record raw = synthesize(target, o.duration_s, o.dt_s, seed, o.envelope);
        // A fresh seed usually converges in a few passes where a stubborn one needs dozens:
        // cap the passes of the first half of the attempts; hard targets get full ones after.
        MatchOptions mo = o.match;
        if (2 * (attempt + 1) <= o.max_attempts)
            mo.max_iterations = std::min(mo.max_iterations, kQuickPasses);
        MatchResult m = match_in_place(std::move(raw), target, mo);
        GeneratedComponent g;
        g.record = std::move(m.record);
        g.acceptance = std::move(m.acceptance);
        g.method = "synthetic+wavelet";
        g.seed = seed;
        g.attempts = attempt + 1;
        g.iterations = m.iterations;
        const bool correlated = correlated_with_earlier(done, g.record);
        if (g.acceptance.passed && !correlated) {
            g.stop = "passed";
            best = std::move(g);
            break;
        }
        notes.push_back(fmt::format(
            "{}: seed {} rejected ({}); trying the next seed", name, seed,
            correlated ? "|rho| > 0.16 with an earlier component" : g.acceptance.reason));
        if (correlated && g.acceptance.passed) {
            g.acceptance.passed = false;
            g.acceptance.reason = "correlated with an earlier component";
        }
        g.stop = "attempt limit";
        if (attempt == 0 ||
            (!best.acceptance.passed && g.acceptance.min_ratio > best.acceptance.min_ratio))
            best = std::move(g);
    }
    best.attempts = std::max(best.attempts, 1);
    best.record.component = name;
    best.record.name = name;
    best.record.source = fmt::format("freestand generate: synthetic, seed {}", best.seed);
    best.wall_s = seconds_since(start);
    return best;
}

// Matching settings tried in turn on a seed record: every other setting lets the rigid-range
// oscillators use wavelets up to 0.2 cycles per sample (a target above its ZPA at 25-50 Hz, as
// ASCE 7 and EC8 are below T0 / T_B, needs resonant content there while the PGA is held); each
// pair steps gentler and aims higher (more energy, for a PSD just short of the floor, e.g. a
// long record whose D5-75 is large).
MatchOptions seed_attempt_options(MatchOptions base, int attempt) {
    const int step = attempt / 2;
    base.relaxation *= std::pow(0.8, step);
    base.aim += 0.025 * step;
    base.lower += 0.025 * step;
    base.upper = std::max(base.upper, base.lower + 0.06);
    if (attempt % 2 == 1) base.rigid_wavelet_cycles_per_sample = 0.2;
    return base;
}

GeneratedComponent seed_component(const Target& target, const GenerateOptions& o, std::size_t index,
                                  std::vector<std::string>& notes) {
    const auto start = Clock::now();
    const std::string& name = o.components[index];
    const core::Record& seed = o.seed_records[index];
    GeneratedComponent best;
    for (int attempt = 0; attempt < o.max_attempts; ++attempt) {
        MatchResult m = match_record(seed, target, seed_attempt_options(o.match, attempt));
        const std::string reason = m.acceptance.reason;
        const bool better = attempt == 0 || m.acceptance.passed ||
                            m.acceptance.min_ratio > best.acceptance.min_ratio;
        if (better) {
            best.record = std::move(m.record);
            best.acceptance = std::move(m.acceptance);
            best.iterations = m.iterations;
        }
        best.attempts = attempt + 1;
        if (best.acceptance.passed) break;
        notes.push_back(fmt::format("{}: matching {} (setting {}) failed ({}); trying {}", name,
                                    seed.name, attempt + 1, reason,
                                    attempt + 1 < o.max_attempts ? "another setting"
                                                                 : "no more settings"));
    }
    best.record.component = name;
    best.record.name = name;
    best.record.source = fmt::format("freestand generate: wavelet-matched {}", seed.source);
    best.method = fmt::format("wavelet (seed {})", seed.name);
    best.stop = best.acceptance.passed ? "passed" : "attempt limit";
    best.wall_s = seconds_since(start);
    return best;
}

}  // namespace

MatchResult match_record(const core::Record& seed, const Target& target,
                         const MatchOptions& options) {
    core::validate(seed);
    validate_target(target.psa_5pct, 0.05);
    // Scale to the target first (geometric mean of the ratio over the band) so the wavelets only
    // reshape; then match.
    const std::vector<double> f =
        spectra::log_frequencies(criteria::band_low_hz, criteria::band_high_for(seed.dt_s), 20);
    const std::vector<double> psa = spectra::psa_g(seed, 0.05, f, target.g_mps2);
    double log_sum = 0.0;
    for (std::size_t i = 0; i < f.size(); ++i)
        log_sum += std::log(target.psa_5pct.psa_at(f[i]) / psa[i]);
    core::Record scaled = seed;
    const double k = std::exp(log_sum / static_cast<double>(f.size()));
    if (!std::isfinite(k) || k <= 0.0)
        throw InputError(SourceLocation{seed.source, 0, ""},
                         fmt::format("seed record \"{}\" has no usable response in the {}-{} Hz "
                                     "band to scale to the target (scale factor {})",
                                     seed.name, f.front(), f.back(), k));
    for (double& a : scaled.accel_mps2) a *= k;
    return match_in_place(std::move(scaled), target, options);
}

GeneratedSet generate_set(const TargetSet& targets, const GenerateOptions& o) {
    check_request(targets, o);
    GeneratedSet set;
    for (std::size_t i = 0; i < o.components.size(); ++i) {
        const std::string& name = o.components[i];
        const Target& target = target_for(targets, name);
        if (o.seed_records.empty()) {
            set.components.push_back(synthetic_component(target, o, i, set.components, set.notes));
            continue;
        }
        set.components.push_back(seed_component(target, o, i, set.notes));
    }
    set.passed = true;
    for (const GeneratedComponent& g : set.components)
        set.passed = set.passed && g.acceptance.passed;
    for (std::size_t i = 0; i < set.components.size(); ++i)
        for (std::size_t j = i + 1; j < set.components.size(); ++j) {
            const double rho = correlation(set.components[i].record, set.components[j].record);
            set.correlations.push_back(
                {set.components[i].record.component, set.components[j].record.component, rho});
            if (std::abs(rho) > criteria::max_abs_correlation) {
                set.passed = false;
                set.notes.push_back(fmt::format("{}-{}: |rho| = {:.3f} > {}",
                                                set.components[i].record.component,
                                                set.components[j].record.component, std::abs(rho),
                                                criteria::max_abs_correlation));
            }
        }
    return set;
}

}  // namespace freestand::motion
