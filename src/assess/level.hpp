#pragma once
/// One PGA level in one direction: classification, closed forms, and (when needed) the
/// simulation over the level's histories (docs/methods.md s.6 steps 1-4).
#include <array>
#include <functional>
#include <map>
#include <utility>
#include <optional>
#include <vector>

#include "assess/case.hpp"
#include "assess/histories.hpp"
#include "assess/result.hpp"
#include "dynamics/simulate.hpp"
#include "rocking/demand.hpp"
#include "rocking/equivalent_linear.hpp"
#include "spectra/spectrum.hpp"

namespace freestand::assess {

/// The design demand at one PGA level. Both horizontal directions share the target unless the
/// site gives direction y its own file (h5_y, pga_y_g); SA_VH combines the two directions.
struct LevelDemand {
    double pga_g = 0.0;                   ///< the level's PGA = direction x's, g
    double pga_v_g = 0.0;
    spectra::Spectrum h5;                 ///< 5%-damped horizontal target of direction x
    spectra::Spectrum sa_vh_slide;        ///< SA_VH at the sliding damping (docs/methods.md s.4)
    rocking::DampedSpectra sa_vh_damped;  ///< SA_VH at any damping (docs/methods.md s.5a)
    /// Equivalent-linear rocking by (direction, restitution; -1 for Housner's), computed on
    /// first need. It does not depend on the friction, so material trials with the same
    /// restitution reuse it.
    mutable std::map<std::pair<int, double>, rocking::ElBlockResult> el_cache;
    std::optional<spectra::Spectrum> h5_y;  ///< direction y's own 5% target (target_y_file)
    std::optional<double> pga_y_g;          ///< direction y's PGA from its file, g

    /// 5%-damped horizontal target of direction d.
    const spectra::Spectrum& h5_of(Direction d) const {
        return d == Direction::y && h5_y ? *h5_y : h5;
    }
    /// The case's DeltaD for this level (site.energy_table_displacement_m), m.
    std::optional<double> table_delta_d_m;

    /// Horizontal PGA of direction d, g.
    double pga_of(Direction d) const {
        return d == Direction::y && pga_y_g ? *pga_y_g : pga_g;
    }
    /// The vertical design spectrum at any damping, its ZPA the vertical PGA pga_v_g (RG 1.60's
    /// vertical shape, or the case's vertical file); absent: SA_V = vertical ratio x SA_H.
    std::optional<rocking::DampedSpectra> sa_v_damped;
};

/// The model name LevelResult::model carries for the planar rigid-block simulation.
inline constexpr const char* planar_model_name =
    "rigid planar block, resting, sliding, rocking or slide-rocking (docs/methods.md s.3)";

/// Builds the demand of a level from the site.
LevelDemand level_demand(const Site& site, double pga_g);

/// A target file's spectrum times factor, resampled on f_hz (Spectrum::psa_at: log-log inside,
/// constant displacement below, rigid limit above).
spectra::Spectrum scaled_target(const spectra::Spectrum& file, double factor,
                                const std::vector<double>& f_hz);

/// The flexible-body flag of the component in direction d (blk its block there) at a level's
/// demand (docs/methods.md s.2): shown beside the mode, never changing it.
FlexibleFlag screen_flexible(const Component& comp, const block::Block& blk, Direction d,
                             const LevelDemand& dem);

/// Frequencies the design spectra are tabulated on, Hz.
std::vector<double> design_frequencies();

/// The friction and restitution bounds of direction d (docs/methods.md s.6 step 6, s.7).
DirectionBounds direction_bounds(const Component& comp, Direction d);

/// Evaluates one level and direction of the case (its own base, or the base of a trial case
/// made by with_base_material). Histories are generated through bank only when a simulation
/// runs.
LevelResult evaluate_level(const Case& c, Direction d, const LevelDemand& demand,
                           HistoryBank& bank);

/// The simulator's model of the component in direction d with one bound's contact.
dynamics::BlockModel block_model(const Component& comp, const ContactBound& contact, Direction d);

/// The excitation of history k in direction d at the demand's PGA (horizontal and vertical).
dynamics::Excitation excitation(const HistorySet& set, Direction d, double pga_g);

/// History k's run at one bound (0: the sliding bound; 1: the rocking bound, run only when it
/// differs from the sliding one; 2: the rocking bound at the lower restitution, when that
/// differs): the summary the statistics read. Histories run on several threads at once,
/// so a runner keeps anything else it records in the slot of (k, bound).
using HistoryRunner = std::function<dynamics::Summary(
    std::size_t k, int bound, const dynamics::BlockModel&, const dynamics::Excitation&,
    const dynamics::Options&)>;

/// Number of bound slots a history can run at (HistoryRunner's `bound` is below it).
inline constexpr int bound_slots = 3;

/// Simulates every history at each distinct bound and gathers the statistics of
/// docs/methods.md s.6 steps 3 and 6; rocking_mode picks the governing history's measure.
/// run: the model each history runs (empty: the planar rigid block, dynamics::simulate).
Simulation simulate_level(const Case& c, const DirectionBounds& bounds, Direction d,
                          double pga_g, HistoryBank& bank, bool rocking_mode,
                          const HistoryRunner& run = {});

/// Whether restitution bound a's rocking is worse than b's: more overturned sets, then the larger
/// 84th-percentile theta / alpha (near the overturning threshold the peak is not monotone in r).
bool worse(const RockingRuns& a, const RockingRuns& b);

/// Counts the sets beyond each limit state (docs/methods.md s.6 step 3): slides beyond the
/// allowable; theta / alpha above 1 / FS_required, overturned sets included.
void count_exceedances(Simulation& sim, double allowable_slide_m, double required_fs);

}  // namespace freestand::assess
