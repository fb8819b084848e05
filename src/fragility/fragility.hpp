#pragma once
/// Fragility of a free-standing component (docs/methods.md s.9): the probability of
/// each failure event against PGA, from N samples per level, each drawing a ground motion and
/// the uncertain friction and restitution from its own random stream (seed, level, sample), so
/// that the result does not depend on threads, shards or machines.
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "assess/case.hpp"
#include "assess/run_settings.hpp"
#include "core/parallel.hpp"
#include "core/statistics.hpp"
#include "core/record.hpp"

namespace freestand::fragility {

/// The failure events of docs/methods.md s.9.
enum class Event { overturn, slide, rock, any };
inline constexpr std::array<Event, 4> all_events{Event::overturn, Event::slide, Event::rock,
                                                 Event::any};
/// "overturn", "slide", "rock", "any".
const char* event_name(Event e);

/// The models a sample runs (docs/methods.md s.9, s.10). The default, the rigid planar block in
/// x and in y, is what `freestand fragility` runs; the performance goal (src/goal) asks for the
/// models the case's own levels decide with. Shard files (fragility/serialize.hpp) do not carry
/// the models: a sharded run is always the default's.
struct Models {
    /// Per level (as Config::pga_g) and direction (x, y): the flexible body (rigid base carrying
    /// one elastic mode, assess::flexible_model) instead of the rigid block. Empty: rigid
    /// throughout; else one entry per level.
    std::vector<std::array<bool, 2>> flexible;
    /// A sample whose block rocks in neither direction under its motion
    /// (dynamics::biaxial_rocking_reason) takes its slide from the biaxial model, both
    /// horizontal components at once, instead of the rigid planar runs (a flexible run's slip
    /// still counts: the larger governs, as at a level). Generated sets only.
    bool biaxial_slide = false;
    /// A sample whose block would rock in x or y under its motion (the same rule) runs the 3D
    /// rigid body instead (every component at once, docs/methods.md s.11, with the options of a
    /// simulated level, assess/body3d_level.hpp, and the sample's larger restitution draw as
    /// its r): its slide, tilt over critical and overturn replace the rigid planar runs', and at
    /// a flagged level, where it carries the case's mode, the planar flexible runs' too, as at
    /// a level. Generated sets only.
    bool body3d = false;
};

/// The default models, in words.
inline constexpr const char* planar_models_text =
    "the rigid planar block in x and in y (docs/methods.md s.3)";

/// The models a simulated level of the case runs at each PGA, for samples that should be
/// decided as the case's levels are (docs/methods.md s.9): the flexible body in a direction
/// where its flag is raised and the model can run (assess::flexible_model_decides), else the
/// rigid block; the 3D body for a sample that rocks, biaxial sliding for one that only slides.
struct CaseModels {
    Models models;
    std::string text;                ///< the models, in words
    std::vector<std::string> notes;  ///< where the samples depart from the case's levels
};
CaseModels case_models(const assess::Case& c, const std::vector<double>& pga_g);
/// The models in words (pga_g names the levels of Models::flexible's entries).
std::string describe_models(const Models& m, const std::vector<double>& pga_g);

/// What to run. 1 to 1000 levels strictly increasing in [0.001, 3] g; samples >= 1, at most
/// core::limits::max_fragility_samples over all levels.
struct Config {
    std::vector<double> pga_g;
    int samples = 100;       ///< per level
    std::uint64_t seed = 1;  ///< the run's seed (streams: core::stream_seed(seed, level, sample))
    /// Generated ground motions: a pool of this many three-component sets for the case's target
    /// (matched at 1 g, scaled to each level, SRP 3.7.1 and realism checked); a sample draws one.
    int pool = 20;
    /// A user suite instead: horizontal records, each applied along x and y, no vertical; a
    /// sample draws one and scales it to the level's PGA.
    std::vector<std::string> record_files;
    Models models;
};

/// Throws InputError naming the field (pga_g, samples, pool, records, models) when the config
/// is invalid.
void validate(const Config& config);

/// One sample: the drawn motion and properties and the peak responses over both directions.
struct SampleResult {
    int level = 0;       ///< index into Config::pga_g
    int sample = 0;      ///< 0-based within the level
    std::string motion;  ///< "set 7" (1-based) or the record's file name
    double mu_s = 0.0;
    double restitution_x = 0.0;
    double restitution_y = 0.0;
    double slide_max_m = 0.0;          ///< max over x and y
    double rock_max_over_alpha = 0.0;  ///< max over x and y
    bool overturned = false;           ///< in x or y
};

/// The laws a sample's friction and restitution are drawn from (docs/methods.md s.9): the case's
/// [uncertainty], else uniform over the case's bounds; restitution drawn at one quantile for
/// both directions, over each direction's own bounds (Housner's value to the measured r).
struct Laws {
    core::Distribution mu_s;
    std::optional<core::Distribution> restitution;  ///< none: per-direction bounds
    std::array<std::array<double, 2>, 2> restitution_bounds{};  ///< [x, y][lower, upper]
    double kinetic_ratio = 1.0;  ///< mu_k / mu_s
};

/// What the report states besides the numbers: the case and the laws the samples were drawn
/// from. Everything here is text or numbers from the case, so a merged run reproduces it (and
/// can redraw every sample's motion, friction and restitution to check a shard's).
struct Meta {
    std::string case_name;
    Config config;
    Laws laws;
    double allowable_slide_m = 0.0;
    double required_overturn_fs = 1.5;
    std::string mu_s_law;           ///< e.g. "uniform [0.12, 0.18] (the case's friction bounds)"
    std::string restitution_law;
    std::string motion_source;      ///< what the motions are and how they are drawn
    std::string models;             ///< the models the samples run, in words
};

/// One event at one level.
struct Count {
    int k = 0;
    int n = 0;
    double p = 0.0;                 ///< k / n
    std::array<double, 2> ci{};     ///< Clopper-Pearson 95%
};

struct Level {
    double pga_g = 0.0;
    int n = 0;
    std::array<Count, 4> events;    ///< indexed like all_events
};

/// Lognormal fragility P(a) = Phi(ln(a / theta_m) / beta) fitted by maximum likelihood.
struct Fit {
    double theta_m_g = 0.0;
    double beta = 0.0;
    double pga_1pct_g = 0.0, pga_5pct_g = 0.0, pga_50pct_g = 0.0;
    double log_likelihood = 0.0;
    double chi2 = 0.0;                 ///< Pearson's, over the levels
    int dof = 0;                       ///< levels - 2
    std::optional<double> p_value;     ///< of chi2 with dof (none when dof < 1)
};

/// The fit of one event, or why there is none.
struct EventFit {
    std::optional<Fit> fit;
    std::string note;  ///< "" with a fit; else why not (no failures, every sample failing, ...)
};

struct Result {
    Meta meta;
    std::vector<Level> levels;
    std::array<EventFit, 4> fits;        ///< indexed like all_events
    std::vector<SampleResult> samples;   ///< sorted by (level, sample)
};

/// The laws and source text for a case and config (mu_s_law, restitution_law, motion_source,
/// models: describe_models of config.models).
Meta make_meta(const assess::Case& c, const Config& config);

/// Counts, intervals and fits from complete samples (every (level, sample) exactly once, in any
/// order). Throws std::invalid_argument when samples are missing, repeated or out of range.
Result aggregate(const Meta& meta, std::vector<SampleResult> samples);

/// Draws and simulates samples. prepare() generates the pool or reads the records; run() may
/// then be called from many threads.
class Runner {
  public:
    /// Validates the config; throws InputError for a bad config or a missing record.
    Runner(const assess::Case& c, Config config);
    ~Runner();
    Runner(const Runner&) = delete;
    Runner& operator=(const Runner&) = delete;

    std::size_t total() const;  ///< levels x samples; global index = level * samples + sample
    /// Generates the history pool (on run's threads, through its cache) or reads the records.
    void prepare(const assess::RunSettings& run);
    /// One sample by its global index (prepare() first).
    SampleResult run(std::size_t global_index) const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// Runs the given global indices on `threads` threads (0: all cores); results in index order.
/// progress(done, total) is called from the calling thread about every 0.2 s and at the end.
std::vector<SampleResult> run_samples(const Runner& runner,
                                      const std::vector<std::size_t>& indices, int threads,
                                      const core::ProgressCallback& progress = {});

/// The whole run on one machine: prepare, every sample, aggregate (run.progress reports the
/// steps "history sets" and "samples").
Result run_all(const assess::Case& c, const Config& config, const assess::RunSettings& run = {});

}  // namespace freestand::fragility
