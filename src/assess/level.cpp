#include "assess/level.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "assess/flexible_level.hpp"
#include "assess/level_runs.hpp"
#include "assess/run_cache.hpp"
#include "assess/verdict.hpp"
#include "core/contract.hpp"
#include "core/measures.hpp"
#include "core/parallel.hpp"
#include "core/statistics.hpp"
#include "core/units.hpp"
#include "rocking/checks.hpp"
#include "rocking/equivalent_linear.hpp"
#include "rocking/flexible.hpp"
#include "sliding/asce.hpp"
#include "sliding/initiation.hpp"
#include "sliding/spectrum_input.hpp"
#include "sliding/table_displacement.hpp"
#include "spectra/design.hpp"

namespace freestand::assess {

namespace {

spectra::Spectrum vector_horizontal_target(double pga_g, double damping, double g_mps2) {
    const spectra::Spectrum h =
        spectra::rg160(pga_g, damping, false, design_frequencies(), g_mps2);
    // Both horizontals follow the same RG 1.60 target: SA_VH = sqrt(1 + 0.16) SA_H.
    return sliding::vector_horizontal({h, h}, damping);
}

}  // namespace

FlexibleFlag screen_flexible(const Component& comp, const block::Block& blk, Direction d,
                             const LevelDemand& dem) {
    FlexibleFlag out;
    const block::Edge e = blk.critical_edge();
    out.uplift_a_g = rocking::uplift_threshold_g(blk, e, dem.pga_v_g);
    // The band of rocking in this direction's plane.
    const std::optional<std::array<double, 2>>& band = comp.plane(d).free_rocking_band_hz;
    if (!comp.fixed_base_frequency_hz && !band) {
        out.reason = "no fixed-base frequency or free-rocking band given: treated as rigid";
        return out;
    }
    rocking::FlexibleInput in;
    in.fixed_base_hz = comp.fixed_base_frequency_hz;
    if (band) {
        in.rock_band_lo_hz = (*band)[0];
        in.rock_band_hi_hz = (*band)[1];
    }
    in.uplift_threshold_g = out.uplift_a_g;
    in.pga_h_g = dem.pga_of(d);
    const rocking::FlexibleScreen s = rocking::flexible_screen(dem.h5_of(d), in);
    out.raised = s.flagged;
    out.band_lo_hz = s.band_lo_hz;
    out.band_hi_hz = s.band_hi_hz;
    out.peak_psa_in_band_g = s.peak_psa_g;
    out.reason = s.reason;
    std::vector<std::string> basis;
    if (comp.fixed_base_frequency_hz)
        basis.push_back(fmt::format("fixed-base {:.2f} Hz", *comp.fixed_base_frequency_hz));
    if (band)
        basis.push_back(fmt::format("free-rocking band {:.2f}-{:.2f} Hz", (*band)[0], (*band)[1]));
    out.basis = fmt::format("{}", fmt::join(basis, "; "));
    return out;
}

namespace {

// DeltaD of the energy method (docs/methods.md s.4): the case's table displacement for the
// level, else the mean of the histories' peak displacements after the zero-phase high-pass,
// which exists only where the histories are used (histories_used). Empty, with the reason, when
// neither applies, so whether a level shows the estimate depends on that level alone.
std::optional<double> energy_delta_d(const Case& c, Direction d, const LevelDemand& dem,
                                     HistoryBank& bank, bool histories_used, Sliding& out) {
    if (dem.table_delta_d_m) {
        out.delta_d_source = "case table (site.energy_table_displacement_m)";
        return dem.table_delta_d_m;
    }
    if (!histories_used) {
        out.delta_d_source = "not computed: informational, and its DeltaD needs the histories, "
                             "which this level did not use";
        return std::nullopt;
    }
    out.highpass_hz = c.site.energy_highpass_hz;
    out.delta_d_source = fmt::format(
        "mean peak displacement of the {} matched {} histories after a zero-phase {:.3g} Hz "
        "high-pass (order-{} Butterworth, forward and backward)",
        bank.sets().size(), d == Direction::x ? "h1" : "h2", c.site.energy_highpass_hz,
        sliding::highpass_order);
    return bank.mean_highpass_displacement_m(d, dem.pga_g);
}

// ASCE 4 and the (informational) energy estimate at the lower friction bound, when the block
// slides there.
Sliding closed_form_sliding(const Case& c, const ContactBound& lower, Direction d, Mode mode,
                            const LevelDemand& dem, HistoryBank& bank, bool histories_used) {
    Sliding out;
    out.mu_s = lower.mu_s;
    out.mu_e = sliding::effective_friction(lower.mu_s, dem.pga_v_g);
    out.c_s_mps2 = 2.0 * out.mu_e * c.site.g_mps2;
    out.c_s_g = out.c_s_mps2 / c.site.g_mps2;
    out.sa_vh_peak_g =
        *std::max_element(dem.sa_vh_slide.psa_g.begin(), dem.sa_vh_slide.psa_g.end());
    if (mode == Mode::rest || mode == Mode::rock) {
        out.reason = mode == Mode::rest
                         ? "at rest at the lower friction bound: the sliding methods do not apply"
                         : "rocks with friction holding at the lower friction bound: no sliding";
        return out;
    }
    if (out.c_s_mps2 <= 0.0) {
        out.reason = "ASCE 4: frictionless base at the lower bound (C_s = 0): the method does "
                     "not apply";
        return out;
    }
    const sliding::Crossing cross =
        sliding::lowest_crossing(dem.sa_vh_slide, out.c_s_g);
    if (!cross.f_hz) {
        out.reason = "ASCE 4: " + cross.reason;
        return out;
    }
    sliding::SlidingInput in;
    in.mu_s = lower.mu_s;
    in.av_g = dem.pga_v_g;
    in.pga_h_g = dem.pga_of(d);
    in.g_mps2 = c.site.g_mps2;
    const std::optional<double> delta_d = energy_delta_d(c, d, dem, bank, histories_used, out);
    if (delta_d) {
        out.delta_d_m = *delta_d;
        in.pgd_m = *delta_d;
    }
    const sliding::SlidingEstimate est = sliding::estimate_sliding(in, *cross.f_hz);
    out.f_es_hz = est.f_es_hz;
    out.slide_asce_m = est.slide_asce_m;
    if (delta_d) out.slide_energy_m = est.slide_energy_m;
    std::vector<std::string> reasons;
    if (!est.slide_asce_m) reasons.push_back("ASCE 4: " + est.slide_asce_reason);
    if (!delta_d) {
        reasons.push_back("energy: " + out.delta_d_source);
    } else if (!est.slide_energy_m) {
        reasons.push_back("energy: " + est.slide_energy_reason);
    }
    out.reason = fmt::format("{}", fmt::join(reasons, "; "));
    return out;
}

rocking::ElBlockResult equivalent_linear(const Case& c, const ContactBound& upper,
                                         const block::Block& blk, Direction d,
                                         const LevelDemand& dem) {
    const std::optional<double> r =
        upper.housner ? std::nullopt : std::optional<double>(upper.restitution);
    const std::pair<int, double> key{d == Direction::x ? 0 : 1, r.value_or(-1.0)};
    if (const auto it = dem.el_cache.find(key); it != dem.el_cache.end()) return it->second;
    rocking::ElOptions opt;
    opt.pga_h_g = dem.pga_of(d);
    opt.pga_v_g = dem.pga_v_g;
    opt.restitution = r;
    opt.fs_required = c.component.required_overturn_fs;
    opt.g_mps2 = c.site.g_mps2;
    rocking::VerticalDemand vertical;
    vertical.ratio = c.site.vertical_ratio;
    vertical.spectra = dem.sa_v_damped;
    rocking::ElBlockResult result =
        rocking::equivalent_linear_rocking(blk, dem.sa_vh_damped, vertical, opt);
    dem.el_cache.emplace(key, result);
    return result;
}

// The s.5a estimate is computed only for the rocking modes: at rest or sliding the verdict does
// not read it, and it dominates the closed-form cost.
Rocking closed_form_rocking(const Case& c, const ContactBound& upper, const block::Block& blk,
                            Direction d, Mode mode, const LevelDemand& dem) {
    Rocking out;
    const block::Edge e = blk.critical_edge();
    out.alpha_rad = blk.alpha_rad(e);
    out.R_m = blk.R_m(e);
    out.p_radps = blk.p_radps(e, c.site.g_mps2);
    out.restitution = upper.restitution;
    out.uplift_a_g = rocking::uplift_threshold_g(blk, e, dem.pga_v_g);
    out.ishiyama_v_mps = rocking::ishiyama_velocity_mps(blk, e, c.site.g_mps2);
    const double A = dem.pga_of(d) / (1.0 - dem.pga_v_g);
    if (mode == Mode::rock || mode == Mode::slide_rock) {
        const rocking::ElBlockResult el = equivalent_linear(c, upper, blk, d, dem);
        const rocking::ElResult& g = el.governing();
        out.gate_passed = g.gate_exceeded;
        out.gate_g = g.gate_g;
        out.theta_rad = g.theta0_rad;
        out.el_reason = g.theta0_reason;
        out.overturn_predicted = g.overturning_predicted;
        out.overturn_fs = g.fs;
        out.spectral_margin = g.spectral_margin;
    }
    if (mode == Mode::rest) out.amplification_estimate = 1.0;
    // Sliding caps the block's acceleration at about mu g (docs/methods.md s.5).
    if (mode == Mode::slide) out.amplification_estimate = std::min(1.0, upper.mu_s / A);
    return out;
}

Initiation classify(const block::Block& blk, double mu_s, const LevelDemand& dem, Direction d) {
    const sliding::PeakInitiation peak =
        sliding::classify_peak(blk, mu_s, dem.pga_of(d), dem.pga_v_g);
    const sliding::Initiation& gi = peak.governing();
    Initiation out;
    out.mode = gi.mode;
    out.a_ratio = gi.A;
    out.mu_s = mu_s;
    out.tan_alpha = gi.tan_alpha;
    out.mu_crit = gi.mu_crit;
    return out;
}

std::string planar_model_reason(const LevelResult& r) {
    std::string out = fmt::format("one direction at a time ({}): the rigid block needs no more",
                                  r.direction == Direction::x ? "x" : "y");
    if (r.flexible.raised) out += "; the flexible-body flag is raised and stays a condition";
    return out;
}

}  // namespace

std::vector<double> design_frequencies() { return spectra::log_frequencies(0.05, 100.0, 100); }

spectra::Spectrum scaled_target(const spectra::Spectrum& file, double factor,
                                 const std::vector<double>& f_hz) {
    spectra::Spectrum s;
    s.damping = file.damping;
    s.label = fmt::format("{} x {:.6g}", file.label, factor);
    s.frequency_hz = f_hz;
    for (double f : f_hz) s.psa_g.push_back(factor * file.psa_at(f));
    return s;
}

namespace {
// User files: the 5% (and 10% if given) horizontal at this level; other dampings through
// rocking::DampedSpectra (log-damping interpolation between the two, EN 1998-1 eta scaling
// outside them).
LevelDemand user_level_demand(const Site& site, const UserTargets& u, double pga_g) {
    const double factor = pga_g / u.zpa_h_g;
    const std::vector<double> f = design_frequencies();
    const spectra::Spectrum h5 = scaled_target(u.h5.spectrum, factor, f);
    std::optional<spectra::Spectrum> y5;
    if (u.y5) y5 = scaled_target(u.y5->spectrum, factor, f);
    // SA_VH combines direction x's and y's targets (docs/methods.md s.4; one file: {h, h}).
    std::vector<spectra::Spectrum> vh{sliding::vector_horizontal({h5, y5 ? *y5 : h5}, 0.05)};
    if (u.h10) {
        const spectra::Spectrum h10 = scaled_target(u.h10->spectrum, factor, f);
        const spectra::Spectrum y10 =
            u.y10 ? scaled_target(u.y10->spectrum, factor, f) : h10;
        vh.push_back(sliding::vector_horizontal({h10, y10}, 0.10));
    }
    rocking::DampedSpectra damped(std::move(vh));
    const rocking::DampedDemand slide = damped.at(site.sliding_damping);
    spectra::Spectrum sa_vh_slide;
    sa_vh_slide.damping = site.sliding_damping;
    sa_vh_slide.label = fmt::format("SA_VH from the target files at {:.3g} damping ({})",
                                    site.sliding_damping, slide.note);
    sa_vh_slide.frequency_hz = f;
    for (double fi : f) sa_vh_slide.psa_g.push_back(slide.psa_g(fi));
    LevelDemand out{pga_g,        site.vertical_ratio * pga_g,
                    h5,           std::move(sa_vh_slide),
                    std::move(damped), {},
                    std::nullopt, std::nullopt,
                    std::nullopt, std::nullopt};
    // The vertical file at the horizontal's scale: its ZPA is then ratio x pga_g.
    if (u.v) out.sa_v_damped.emplace(std::vector{scaled_target(u.v->spectrum, factor, f)});
    if (y5) {
        out.h5_y = std::move(y5);
        // Same factor as x: y's PGA is its file's rigid limit at that scale (equal files: pga_g).
        out.pga_y_g = pga_g * (u.y5->spectrum.psa_g.back() / u.zpa_h_g);
    }
    return out;
}
}  // namespace

namespace {
// The RG 1.60 demand of a level.
LevelDemand rg160_level_demand(const Site& site, double pga_g) {
    std::vector<spectra::Spectrum> damped, vertical;
    damped.reserve(spectra::rg160_dampings.size());
    const double pga_v_g = site.vertical_ratio * pga_g;
    for (double d : spectra::rg160_dampings) {
        damped.push_back(vector_horizontal_target(pga_g, d, site.g_mps2));
        // RG 1.60's vertical spectrum, its ZPA the vertical PGA (docs/methods.md s.8): the
        // vertical demand of the equivalent-linear estimate (s.5a), as of the histories.
        vertical.push_back(spectra::rg160(pga_v_g, d, true, design_frequencies(), site.g_mps2));
    }
    LevelDemand out{pga_g,
                    pga_v_g,
                    spectra::rg160(pga_g, 0.05, false, design_frequencies(), site.g_mps2),
                    vector_horizontal_target(pga_g, site.sliding_damping, site.g_mps2),
                    rocking::DampedSpectra(std::move(damped)),
                    {},
                    std::nullopt,
                    std::nullopt,
                    std::nullopt,
                    std::nullopt};
    out.sa_v_damped.emplace(std::move(vertical));
    return out;
}

// The case's table displacement of the level with this PGA (the table follows site.pga_g).
std::optional<double> table_delta_d(const Site& site, double pga_g) {
    if (!site.energy_table_displacement_m) return std::nullopt;
    const auto it = std::find(site.pga_g.begin(), site.pga_g.end(), pga_g);
    if (it == site.pga_g.end()) return std::nullopt;
    return site.energy_table_displacement_m->at(static_cast<std::size_t>(it - site.pga_g.begin()));
}
}  // namespace

LevelDemand level_demand(const Site& site, double pga_g) {
    LevelDemand out = site.targets ? user_level_demand(site, *site.targets, pga_g)
                                   : rg160_level_demand(site, pga_g);
    out.table_delta_d_m = table_delta_d(site, pga_g);
    return out;
}

DirectionBounds direction_bounds(const Component& comp, Direction d) {
    const BaseContact& base = comp.base;
    const block::Block blk = comp.block(d);
    // A very squat block has a negative Housner value: no rebound.
    const double housner = std::max(0.0, blk.housner_restitution(blk.critical_edge()));
    double r_lo = housner;
    double r_hi = housner;
    bool hi_is_housner = true;
    if (base.restitution_range) {
        r_lo = (*base.restitution_range)[0];
        r_hi = (*base.restitution_range)[1];
        hi_is_housner = false;
    } else if (base.restitution) {
        r_lo = std::min(housner, *base.restitution);
        r_hi = std::max(housner, *base.restitution);
        hi_is_housner = *base.restitution <= housner;
    }
    const double ratio = base.kinetic_ratio();
    DirectionBounds out;
    out.restitution_lower = r_lo;
    out.sliding = ContactBound{base.mu_s_range[0], ratio * base.mu_s_range[0], r_hi,
                               hi_is_housner, "lower friction bound"};
    out.rocking = ContactBound{base.mu_s_range[1], ratio * base.mu_s_range[1], r_hi,
                               hi_is_housner, "upper friction and restitution bounds"};
    if (r_lo != r_hi) {
        out.rocking_lower = ContactBound{base.mu_s_range[1], ratio * base.mu_s_range[1], r_lo,
                                         !hi_is_housner && r_lo == housner && !base.restitution_range,
                                         "upper friction, lower restitution bound"};
    }
    return out;
}

dynamics::BlockModel block_model(const Component& comp, const ContactBound& contact,
                                 Direction d) {
    const block::Block blk = comp.block(d);
    const std::optional<double> r =
        contact.housner ? std::nullopt : std::optional<double>(contact.restitution);
    // Top corners at the body's height (twice the CG height unless the case gives height_m).
    return dynamics::make_block_model(blk, contact.mu_s, contact.mu_k, r, comp.body_height_m());
}

dynamics::Excitation excitation(const HistorySet& set, Direction d, double pga_g) {
    const core::Record& h = d == Direction::x ? set.h1 : set.h2;
    return dynamics::excitation_from_record(h, pga_g, &set.v, pga_g);
}

namespace {

bool same_contact(const ContactBound& a, const ContactBound& b) {
    return a.mu_s == b.mu_s && a.mu_k == b.mu_k && a.restitution == b.restitution &&
           a.housner == b.housner;
}

// A history's summaries at each bound slot (HistoryRunner).
using BoundRuns = std::array<dynamics::Summary, bound_slots>;

// Every history of the bank through `one` (history k at bound slot b, its excitation in
// direction d at pga_g) for the slots `run`, on the run's threads, in history order whatever
// thread ran which. Each (history, slot) is a work item of its own, so the runs balance over
// the threads where N histories alone would leave one idle.
std::vector<BoundRuns> run_histories(
    HistoryBank& bank, Direction d, double pga_g, const std::vector<int>& run,
    const std::function<dynamics::Summary(std::size_t, int, const dynamics::Excitation&)>& one) {
    const auto sets = bank.sets();
    const RunSettings& settings = bank.run();
    std::vector<BoundRuns> runs(sets.size());
    core::ProgressCallback progress;
    if (settings.progress) {
        const std::string step =
            fmt::format("simulations at {:g} g, {}", pga_g, d == Direction::x ? "x" : "y");
        progress = [&settings, step](std::size_t done, std::size_t total) {
            settings.progress(step, done, total);
        };
    }
    core::parallel_for(
        sets.size() * run.size(), settings.threads,
        [&](std::size_t item) {
            const std::size_t k = item / run.size();
            const int slot = run[item % run.size()];
            runs[k][static_cast<std::size_t>(slot)] = one(k, slot, excitation(sets[k], d, pga_g));
        },
        progress);
    return runs;
}

// Rocking statistics of one restitution bound from the runs of slot `slot`.
RockingRuns rocking_runs(const ContactBound& bound, const std::vector<BoundRuns>& runs,
                         std::size_t slot) {
    RockingRuns out;
    out.bound = bound;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> over_alpha, rad;
    for (const BoundRuns& r : runs) {
        const dynamics::Summary& s = r[slot];
        if (s.overturned) ++out.overturned;
        over_alpha.push_back(s.overturned ? nan : s.rock_max_over_alpha);
        rad.push_back(s.overturned ? nan : s.rock_max_rad);
    }
    out.over_alpha = stats_of(over_alpha);
    out.rad = stats_of(rad);
    return out;
}

}  // namespace

bool worse(const RockingRuns& a, const RockingRuns& b) {
    if (a.overturned != b.overturned) return a.overturned > b.overturned;
    return a.over_alpha.p84 > b.over_alpha.p84;
}

Simulation simulate_level(const Case& c, const DirectionBounds& bounds, Direction d,
                          double pga_g, HistoryBank& bank, bool rocking_mode,
                          const HistoryRunner& run) {
    std::array<dynamics::BlockModel, bound_slots> models{
        block_model(c.component, bounds.sliding, d), block_model(c.component, bounds.rocking, d),
        block_model(c.component, bounds.rocking_lower.value_or(bounds.rocking), d)};
    dynamics::Options opt;
    opt.record_series = false;
    opt.g_mps2 = c.site.g_mps2;
    Simulation sim;
    sim.sliding_bound = bounds.sliding;
    sim.bounds_differ = !same_contact(bounds.sliding, bounds.rocking);
    const bool lower_r = bounds.rocking_lower.has_value();
    // Slot 1 repeats slot 0 when the bounds coincide; slot 2 runs only for a second restitution.
    std::vector<int> slots{0};
    if (sim.bounds_differ) slots.push_back(1);
    if (lower_r) slots.push_back(2);
    const auto sets = bank.sets();
    sim.histories = static_cast<int>(sets.size());
    std::array<RunTable<dynamics::Summary>*, bound_slots> kept{};
    if (bank.level_runs() && !run)
        for (int slot : slots)
            kept[static_cast<std::size_t>(slot)] = &bank.level_runs()->rigid(d, slot, sets.size());
    std::vector<BoundRuns> runs = run_histories(
        bank, d, pga_g, slots, [&](std::size_t k, int slot, const dynamics::Excitation& ex) {
            const auto b = static_cast<std::size_t>(slot);
            if (run) return run(k, slot, models[b], ex, opt);
            return remembered(kept[b], k, [&] {
                return rigid_run(bank.run().run_cache, models[b], ex,
                                 bank.excitation_key(k, static_cast<int>(d), pga_g, ex), opt);
            });
        });
    if (!sim.bounds_differ)
        for (BoundRuns& r : runs) r[1] = r[0];
    RockingRuns upper = rocking_runs(bounds.rocking, runs, 1);
    std::size_t rock_slot = 1;
    if (lower_r) {
        RockingRuns lower = rocking_runs(*bounds.rocking_lower, runs, 2);
        if (worse(lower, upper)) {
            std::swap(lower, upper);
            rock_slot = 2;
        }
        sim.rocking_other = std::move(lower);
    }
    sim.rocking_bound = upper.bound;
    sim.rock_over_alpha = std::move(upper.over_alpha);
    sim.rock_rad = std::move(upper.rad);
    std::vector<double> slide, residual, amplification;
    double worst = -1.0;
    for (std::size_t k = 0; k < runs.size(); ++k) {
        const dynamics::Summary& s_slide = runs[k][0];
        const dynamics::Summary& s_rock = runs[k][rock_slot];
        slide.push_back(s_slide.slide_max_m);
        residual.push_back(s_slide.slide_residual_m);
        amplification.push_back(s_rock.amplification);
        bool overturned = s_slide.overturned || runs[k][1].overturned;
        if (lower_r) overturned = overturned || runs[k][2].overturned;
        sim.overturned_sets.push_back(overturned ? 1 : 0);
        if (overturned) ++sim.overturned;
        // Governing history: an overturned one, else the largest rocking (rocking modes) or slip.
        const double score =
            overturned ? 1e9 : (rocking_mode ? s_rock.rock_max_over_alpha : s_slide.slide_max_m);
        if (score > worst) {
            worst = score;
            sim.governing_history = static_cast<int>(k);
        }
    }
    FREESTAND_EXPECT(sim.histories > 0, "a simulated level has histories");
    FREESTAND_EXPECT(sim.overturned <= sim.histories, "overturns are counted once per history");
    sim.slide_m = stats_of(slide);
    sim.slide_residual_m = stats_of(residual);
    sim.amplification = stats_of(amplification);
    sim.overturn_ci = core::clopper_pearson(sim.overturned, sim.histories);
    count_exceedances(sim, c.component.allowable_slide_m, c.component.required_overturn_fs);
    return sim;
}

void count_exceedances(Simulation& sim, double allowable_slide_m, double required_fs) {
    sim.slide_exceed = exceedance(sim.slide_m.values, allowable_slide_m);
    sim.rock_exceed = exceedance(sim.rock_over_alpha.values, 1.0 / required_fs, sim.overturned);
}

LevelResult evaluate_level(const Case& c, Direction d, const LevelDemand& demand,
                           HistoryBank& bank) {
    LevelResult r;
    r.pga_g = demand.pga_g;
    r.pga_v_g = demand.pga_v_g;
    r.direction = d;
    const block::Block blk = c.component.block(d);
    r.bounds = direction_bounds(c.component, d);
    r.initiation = classify(blk, r.bounds.rocking.mu_s, demand, d);
    r.initiation_lower = classify(blk, r.bounds.sliding.mu_s, demand, d);
    r.flexible = screen_flexible(c.component, blk, d, demand);
    r.sliding = closed_form_sliding(c, r.bounds.sliding, d, r.initiation_lower.mode, demand,
                                    bank, false);
    r.rocking = closed_form_rocking(c, r.bounds.rocking, blk, d, r.initiation.mode, demand);
    const double allowable = c.component.allowable_slide_m;
    const double fs = c.component.required_overturn_fs;
    r.screen = screen_level(r, allowable, fs);
    const SimulationNeed need = simulation_need(r.screen, c.options.simulate);
    r.simulation_reason = need.reason;
    const bool flexible = flexible_model_decides(c, r.flexible);
    if (need.run || flexible) {
        const bool rocking_mode =
            r.initiation.mode == Mode::rock || r.initiation.mode == Mode::slide_rock;
        r.simulation = simulate_level(c, r.bounds, d, demand.pga_g, bank, rocking_mode);
        r.model = planar_model_name;
        r.model_reason = planar_model_reason(r);
        // The energy estimate needs the histories' DeltaD: now they exist.
        r.sliding = closed_form_sliding(c, r.bounds.sliding, d, r.initiation_lower.mode,
                                        demand, bank, true);
        if (flexible) simulate_flexible_level(c, r, demand.pga_g, bank, rocking_mode);
    }
    if (r.simulation) r.rocking.pgv_mps = bank.mean_pgv_mps(d, demand.pga_g);
    r.verdict = decide_level(r, allowable, fs);
    r.trail = decision_trail(r, allowable, fs);
    return r;
}

}  // namespace freestand::assess
