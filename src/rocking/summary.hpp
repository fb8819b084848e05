#pragma once
/// All closed-form rocking checks of a block for one direction (docs/methods.md s.2, s.5, s.5a):
/// what `freestand rock` prints and what the assessment reads before deciding to simulate.
#include <optional>
#include <string>

#include "block/block.hpp"
#include "block/edge_pair.hpp"
#include "rocking/checks.hpp"
#include "rocking/demand.hpp"
#include "rocking/equivalent_linear.hpp"
#include "rocking/flexible.hpp"
#include "sliding/initiation.hpp"

namespace freestand::rocking {

/// Inputs; everything optional except the block. Missing inputs leave the checks that need
/// them empty, with a reason.
struct RockingInput {
    std::optional<DampedSpectra> horizontal;  ///< SA_VH (or one component) at any damping
    VerticalDemand vertical;                  ///< vertical spectra or SA_V / SA_H ratio
    std::optional<double> pga_h_g;            ///< default: the horizontal spectra's ZPA
    /// Peak vertical, g, applied downward; default: vertical ZPA, else ratio * PGA_h, else 0.
    std::optional<double> pga_v_g;
    std::optional<double> pgv_mps;            ///< peak ground velocity (Ishiyama check)
    std::optional<double> mu_s;               ///< static friction (initiating mode)
    std::optional<double> restitution;        ///< measured r, overrides Housner's
    double fs_required = 1.5;
    std::optional<double> fixed_base_hz;      ///< flexible-body screen
    std::optional<double> rock_band_lo_hz;
    std::optional<double> rock_band_hi_hz;
};

/// Geometry-only checks about one edge, plus the spectral ones when a spectrum was given.
struct EdgeChecks {
    block::Edge edge = block::Edge::right;
    double alpha_rad = 0.0;
    double tan_alpha = 0.0;
    double R_m = 0.0;
    double p_radps = 0.0;
    double inertia_edge_kgm2 = 0.0;
    double restitution = 0.0;       ///< the one used: measured if given, else Housner's
    double uplift_a_g = 0.0;        ///< tan(alpha) (1 - A_v)
    double ishiyama_v_mps = 0.0;
    double e_ot_jpkg = 0.0;
    std::optional<HousnerEstimate> housner;  ///< with S_v = peak 5%-damped PSV
    std::optional<ElResult> el;
};

/// Both edges; the governing one is the equivalent-linear governing edge when a spectrum was
/// given, else the critical edge.
struct RockingChecks : block::EdgePair<EdgeChecks> {
    std::optional<double> pga_h_g;
    std::string pga_h_source;        ///< "given", "spectrum ZPA", or a caution when the
                                     ///< spectrum stops below 33 Hz
    double pga_v_g = 0.0;
    std::string pga_v_source;
    std::optional<double> housner_sv_mps;
    std::string spectral_reason;     ///< why housner / el are empty
    std::optional<bool> pgv_below_ishiyama;  ///< PGV below the smaller edge bound
    std::string pgv_reason;
    std::optional<sliding::PeakInitiation> initiation;
    std::string initiation_reason;
    std::string amplification_warning;
    std::optional<FlexibleScreen> flexible;
    std::string flexible_reason;
};

/// Runs every check the inputs allow. InputError for out-of-range values (naming the field).
RockingChecks rocking_checks(const block::Block& blk, const RockingInput& in);

}  // namespace freestand::rocking
