#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>

#include "assess/flexible_level.hpp"
#include "assess/histories.hpp"
#include "assess/level.hpp"
#include "core/errors.hpp"
#include "core/limits.hpp"
#include "core/random.hpp"
#include "core/readers.hpp"
#include "dynamics/flexible.hpp"
#include "dynamics/simulate.hpp"
#include "fragility/fragility.hpp"
#include "fragility/runner_detail.hpp"

namespace freestand::fragility {

const char* event_name(Event e) {
    switch (e) {
        case Event::overturn:
            return "overturn";
        case Event::slide:
            return "slide";
        case Event::rock:
            return "rock";
        case Event::any:
            return "any";
    }
    return "?";
}

void validate(const Config& c) {
    core::limits::require_pga_levels(c.pga_g, SourceLocation{"", 0, "pga_g"});
    const SourceLocation samples{"", 0, "samples"};
    if (c.samples < 1 || c.samples > 1000000)
        throw InputError(samples, fmt::format("{}; expected 1 to 1000000 per level", c.samples));
    // The whole run, before the samples' list and results are allocated.
    core::limits::require_within(static_cast<double>(c.pga_g.size()) * c.samples,
                                 core::limits::max_fragility_samples, samples,
                                 "the run's samples (levels x samples per level)");
    if (c.record_files.empty() && (c.pool < 1 || c.pool > 1000))
        throw InputError(SourceLocation{"", 0, "pool"},
                         fmt::format("{}; expected 1 to 1000 history sets", c.pool));
    const SourceLocation models{"", 0, "models"};
    if (!c.models.flexible.empty() && c.models.flexible.size() != c.pga_g.size())
        throw InputError(models, fmt::format("{} flexible-body entries for {} levels",
                                             c.models.flexible.size(), c.pga_g.size()));
    if ((c.models.biaxial_slide || c.models.body3d) && !c.record_files.empty())
        throw InputError(models,
                         fmt::format("{} needs generated three-component sets, not a suite of "
                                     "horizontal records",
                                     c.models.body3d ? "the 3D body" : "biaxial sliding"));
}

namespace {

Laws laws_of(const assess::Case& c) {
    Laws l;
    const assess::BaseContact& base = c.component.base;
    l.mu_s = c.uncertainty.mu_s.value_or(
        core::Distribution{core::Distribution::Kind::uniform, base.mu_s_range[0],
                           base.mu_s_range[1], std::nullopt});
    l.restitution = c.uncertainty.restitution;
    for (const assess::Direction d : {assess::Direction::x, assess::Direction::y}) {
        const assess::DirectionBounds b = assess::direction_bounds(c.component, d);
        l.restitution_bounds[d == assess::Direction::x ? 0 : 1] = {b.restitution_lower,
                                                                    b.rocking.restitution};
    }
    l.kinetic_ratio = base.kinetic_ratio();
    return l;
}

}  // namespace

Meta make_meta(const assess::Case& c, const Config& config) {
    validate(config);
    const Laws l = laws_of(c);
    Meta m;
    m.case_name = c.component.name;
    m.config = config;
    m.laws = l;
    m.allowable_slide_m = c.component.allowable_slide_m;
    m.required_overturn_fs = c.component.required_overturn_fs;
    m.models = describe_models(config.models, config.pga_g);
    m.mu_s_law = l.mu_s.describe() + (c.uncertainty.mu_s ? " ([uncertainty] mu_s)"
                                                           : " (the case's friction bounds)");
    if (c.uncertainty.mu_s && c.component.base.kinetic_ratio() != 1.0)
        m.mu_s_law += fmt::format("; mu_k = {:.4g} mu_s", c.component.base.kinetic_ratio());
    if (l.restitution) {
        m.restitution_law = l.restitution->describe() + " ([uncertainty] restitution), both "
                                                        "directions";
    } else {
        m.restitution_law = fmt::format(
            "uniform over each direction's bounds, one quantile for both: x [{:.4g}, {:.4g}], "
            "y [{:.4g}, {:.4g}] (Housner's value to the measured r)",
            l.restitution_bounds[0][0], l.restitution_bounds[0][1], l.restitution_bounds[1][0],
            l.restitution_bounds[1][1]);
    }
    if (config.record_files.empty()) {
        m.motion_source = fmt::format(
            "a pool of {} three-component histories matched at 1 g to the case's target (SRP "
            "3.7.1 and realism checked, docs/methods.md s.8), h1 along x and h2 along y with the "
            "vertical, scaled to each level; each sample draws one set",
            config.pool);
    } else {
        std::string names;
        for (const std::string& f : config.record_files)
            names += (names.empty() ? "" : ", ") + std::filesystem::path(f).filename().string();
        m.motion_source = fmt::format(
            "a suite of {} horizontal records ({}), each applied along x and along y with no "
            "vertical motion and scaled so its PGA is the level's; each sample draws one record",
            config.record_files.size(), names);
    }
    return m;
}

struct Runner::Impl {
    assess::Case c;
    Config config;
    Laws laws;
    std::vector<assess::HistorySet> sets;
    std::vector<core::Record> records;
    std::vector<double> record_pga_g;
    std::vector<std::string> record_names;
    bool prepared = false;
};

Runner::Runner(const assess::Case& c, Config config) : impl_(std::make_unique<Impl>()) {
    if (!c.units.empty())
        throw InputError(SourceLocation{c.file, 0, "unit"},
                         "the fragility analysis takes one component, not two [[unit]] tables");
    validate(config);
    impl_->c = c;
    impl_->config = std::move(config);
    impl_->laws = laws_of(c);
}

Runner::~Runner() = default;

std::size_t Runner::total() const {
    return impl_->config.pga_g.size() * static_cast<std::size_t>(impl_->config.samples);
}

void Runner::prepare(const assess::RunSettings& run) {
    Impl& m = *impl_;
    if (m.config.record_files.empty()) {
        assess::Case pool_case = m.c;
        pool_case.options.histories_per_level = m.config.pool;
        assess::HistoryBank bank(pool_case, run);
        const auto pool = bank.sets();
        m.sets.assign(pool.begin(), pool.end());
    } else {
        for (const std::string& f : m.config.record_files) {
            core::Record r = core::read_record(f, m.c.site.g_mps2);
            double pga = 0.0;
            for (double a : r.accel_mps2) pga = std::max(pga, std::abs(a));
            if (!(pga > 0.0))
                throw InputError(SourceLocation{f, 0, "records"},
                                 "the record has no motion (PGA 0); it cannot be scaled to a level");
            m.record_pga_g.push_back(pga / m.c.site.g_mps2);
            m.record_names.push_back(std::filesystem::path(f).filename().string());
            m.records.push_back(std::move(r));
        }
    }
    m.prepared = true;
}

Draw draw(const Laws& laws, std::uint64_t seed, int level, int sample, std::size_t pool) {
    std::mt19937_64 rng(core::stream_seed(seed, static_cast<std::uint64_t>(level),
                                          static_cast<std::uint64_t>(sample)));
    const double u_motion = core::uniform01(rng());
    const double u_mu = core::uniform01(rng());
    const double u_r = core::uniform01(rng());
    Draw d;
    d.pick = std::min(pool - 1, static_cast<std::size_t>(u_motion * static_cast<double>(pool)));
    d.mu_s = laws.mu_s.at(u_mu);
    for (std::size_t dir = 0; dir < 2; ++dir) {
        const auto& b = laws.restitution_bounds[dir];
        d.restitution[dir] =
            laws.restitution ? laws.restitution->at(u_r) : b[0] + u_r * (b[1] - b[0]);
    }
    return d;
}

namespace {

// The rigid block's run, or the flexible body's base when the level asks for it.
dynamics::Summary simulate_direction(const assess::Component& comp,
                                     const assess::ContactBound& contact, assess::Direction d,
                                     const dynamics::Excitation& ex, const dynamics::Options& opt,
                                     bool flexible) {
    if (!flexible)
        return dynamics::simulate(assess::block_model(comp, contact, d), ex, opt).summary;
    return dynamics::simulate_flexible(assess::flexible_model(comp, contact, d), ex, opt)
        .summary.base;
}

// The worse of a sample's peaks so far and one run's.
void add_peaks(SampleResult& out, double slide_max_m, double rock_max_over_alpha,
               bool overturned) {
    out.slide_max_m = std::max(out.slide_max_m, slide_max_m);
    out.rock_max_over_alpha = std::max(out.rock_max_over_alpha, rock_max_over_alpha);
    out.overturned = out.overturned || overturned;
}

}  // namespace

SampleResult Runner::run(std::size_t global_index) const {
    const Impl& m = *impl_;
    if (!m.prepared) throw std::logic_error("fragility::Runner::run before prepare");
    const auto samples = static_cast<std::size_t>(m.config.samples);
    SampleResult out;
    out.level = static_cast<int>(global_index / samples);
    out.sample = static_cast<int>(global_index % samples);
    const auto level = static_cast<std::size_t>(out.level);
    const double pga_g = m.config.pga_g.at(level);
    const Draw dr = draw(m.laws, m.config.seed, out.level, out.sample,
                         m.sets.empty() ? m.records.size() : m.sets.size());
    out.motion = m.sets.empty() ? m.record_names[dr.pick] : fmt::format("set {}", dr.pick + 1);
    out.mu_s = dr.mu_s;
    out.restitution_x = dr.restitution[0];
    out.restitution_y = dr.restitution[1];
    const Models& models = m.config.models;
    dynamics::Options opt;
    opt.record_series = false;
    opt.g_mps2 = m.c.site.g_mps2;
    const double mu_k = m.laws.kinetic_ratio * out.mu_s;
    const auto where = [&](const std::string& direction, const NumericalError& e) {
        // Name the sample so that it can be rerun alone (its draws depend on these only).
        return NumericalError(fmt::format(
            "level {} (PGA {:g} g), sample {} ({}, mu_s {:.6g}, restitution x {:.6g}, y {:.6g}, "
            "{}): {}",
            out.level + 1, pga_g, out.sample + 1, out.motion, out.mu_s, out.restitution_x,
            out.restitution_y, direction, e.what()));
    };
    std::optional<WholeBody> whole;
    const bool flagged = !models.flexible.empty() &&
                         (models.flexible[level][0] || models.flexible[level][1]);
    if (!m.sets.empty() && (models.biaxial_slide || models.body3d)) {
        try {
            // One restitution for the body: the larger draw, the more energetic.
            whole = whole_body_sample(m.c, m.sets[dr.pick], pga_g, out.mu_s, mu_k,
                                      std::max(dr.restitution[0], dr.restitution[1]), models,
                                      flagged);
        } catch (const NumericalError& e) {
            throw where("the whole body", e);
        }
    }
    const bool body3d = whole && whole->model == WholeBody::Model::body3d;
    double flexible_slide_m = 0.0;
    for (const assess::Direction d : {assess::Direction::x, assess::Direction::y}) {
        const std::size_t dir = d == assess::Direction::x ? 0 : 1;
        const bool flexible_here = !models.flexible.empty() && models.flexible[level][dir];
        // The 3D body replaces the rigid planar runs, and at a flagged level, where it carries
        // the mode, the planar flexible ones too.
        if (body3d && (flagged || !flexible_here)) continue;
        const assess::ContactBound contact{out.mu_s, mu_k, dr.restitution[dir], false, ""};
        const dynamics::Excitation ex =
            m.sets.empty() ? dynamics::excitation_from_record(m.records[dr.pick],
                                                              pga_g / m.record_pga_g[dr.pick])
                           : assess::excitation(m.sets[dr.pick], d, pga_g);
        dynamics::Summary s;
        try {
            s = simulate_direction(m.c.component, contact, d, ex, opt, flexible_here);
        } catch (const NumericalError& e) {
            throw where(fmt::format("direction {}", assess::to_string(d)), e);
        }
        add_peaks(out, s.slide_max_m, s.rock_max_over_alpha, s.overturned);
        if (flexible_here) flexible_slide_m = std::max(flexible_slide_m, s.slide_max_m);
    }
    if (body3d) {
        add_peaks(out, whole->slide_max_m, whole->rock_max_over_alpha, whole->overturned);
    } else if (whole) {
        // Biaxial sliding replaces the rigid blocks' slide; a flexible run's slip still counts.
        out.slide_max_m = std::max(flexible_slide_m, whole->slide_max_m);
    }
    return out;
}

std::vector<SampleResult> run_samples(const Runner& runner, const std::vector<std::size_t>& indices,
                                      int threads, const core::ProgressCallback& progress) {
    std::vector<SampleResult> out(indices.size());
    core::parallel_for(
        indices.size(), threads, [&](std::size_t i) { out[i] = runner.run(indices[i]); },
        progress);
    return out;
}

Result run_all(const assess::Case& c, const Config& config, const assess::RunSettings& run) {
    Runner runner(c, config);
    runner.prepare(run);
    std::vector<std::size_t> all(runner.total());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    auto samples = run_samples(runner, all, run.threads, [&](std::size_t done, std::size_t total) {
        if (run.progress) run.progress("samples", done, total);
    });
    return aggregate(make_meta(c, config), std::move(samples));
}

}  // namespace freestand::fragility
