#pragma once
/// Equivalent-linear rocking estimate (docs/methods.md s.5a): a screen that follows the
/// ASCE 43-05 Appendix A.2 approach in the form that section gives; it is not the standard's
/// text. The time-history simulation is the reference (Makris & Konstantinidis 2003).
#include <optional>
#include <string>

#include "block/block.hpp"
#include "block/edge_pair.hpp"
#include "core/units.hpp"
#include "rocking/demand.hpp"

namespace freestand::rocking {

/// How outputs label this estimate.
inline constexpr const char* equivalent_linear_label =
    "equivalent-linear estimate (ASCE 43-05 App. A.2 approach, docs/methods.md s.5a; not the "
    "standard's text; the time-history simulation is the reference)";

/// Housner's free-rocking frequency at amplitude theta0, Hz: f = p / (4 arccosh(1 / (1 -
/// theta0/alpha))) (docs/methods.md s.1). 0 < theta0 < alpha.
double rocking_frequency_hz(double p_radps, double alpha_rad, double theta0_rad);

/// Horizontal CG displacement at rocking angle theta0, m: R (sin(alpha) - sin(alpha - theta0)).
double rocking_displacement_m(double R_m, double alpha_rad, double theta0_rad);

/// Effective damping from the restitution on angular velocity, two impacts per cycle:
/// beta_e = -ln(r) / pi. 0 < r <= 1.
double damping_from_restitution(double r);

/// Vertical demand: a set of vertical spectra, or SA_V = ratio * SA_H(f, beta_e).
struct VerticalDemand {
    std::optional<DampedSpectra> spectra;
    double ratio = 0.0;  ///< used only without spectra; >= 0
};

/// Options of the estimate.
struct ElOptions {
    std::optional<double> pga_h_g;      ///< default: the horizontal demand's zpa_g()
    std::optional<double> pga_v_g;      ///< default: vertical zpa_g(), or ratio * pga_h
    std::optional<double> restitution;  ///< measured r overriding Housner's (docs/methods.md s.7)
    double fs_required = 1.5;           ///< required alpha / theta0
    /// Trial angles alpha k / n, k = 1..n-1, then alpha (1 - core::tol::relative).
    int grid_points = 2000;
    /// Gravity, and the unit g of the spectra and PGAs, m/s^2 (a case's site.g_mps2).
    double g_mps2 = units::g_mps2;
};

/// Result about one edge. Every empty optional has its reason set.
struct ElResult {
    block::Edge edge = block::Edge::right;
    double alpha_rad = 0.0;
    double restitution = 0.0;
    std::optional<double> beta_e;       ///< -ln(r) / pi
    std::string beta_e_reason;
    std::string damping_note;           ///< how the demand at beta_e was obtained
    double pga_h_g = 0.0;
    double pga_v_g = 0.0;
    double gate_g = 0.0;                ///< (1 - 0.4 pga_v) tan(alpha), g
    bool gate_exceeded = false;         ///< pga_h > gate_g: rocking predicted
    std::optional<double> theta0_rad;   ///< 0 below the gate; empty when overturning
    std::string theta0_reason;
    std::optional<double> f_e_hz;       ///< effective frequency at theta0 (theta0 > 0)
    std::optional<double> demand_g;     ///< SA_VH(f_e, beta_e) at theta0
    std::optional<double> fs;           ///< alpha / theta0 (theta0 > 0)
    std::string fs_reason;
    double fs_required = 1.5;
    bool fs_ok = false;
    bool overturning_predicted = false;
    /// Largest scale on the spectra (horizontal and vertical together) that still finds
    /// theta0 < alpha, to relative 1e-6; empty (with reason) when no scale up to 1e6 overturns.
    std::optional<double> spectral_margin;
    std::string spectral_margin_reason;
};

/// Estimate about edge e. horizontal: SA_VH (or one component) at any damping.
/// Steps (docs/methods.md s.5a): gate; beta_e from r; for trial theta0 = alpha k / n upward, the
/// effective frequency f_e with gravity reduced to g (1 - 0.4 SA_V(f_e, beta_e)) (so f_e solves
/// f = f_e,g sqrt(1 - 0.4 SA_V(f)), by bisection), SD, capacity (2 pi f_e)^2 SD against
/// SA_VH(f_e, beta_e); the first grid angle with demand <= capacity is refined by bisection
/// against the previous one. Throws InputError for a restitution outside [0, 1], fs_required
/// <= 0, negative ratio or PGA, grid_points < 10.
ElResult equivalent_linear_rocking(const block::Block& blk, block::Edge e,
                                   const DampedSpectra& horizontal, const VerticalDemand& vertical,
                                   const ElOptions& options);

/// Both edges (one computation for a symmetric block) and the governing one: the smaller
/// spectral margin (an empty margin counts as infinite); ties go to the critical edge.
struct ElBlockResult : block::EdgePair<ElResult> {};

ElBlockResult equivalent_linear_rocking(const block::Block& blk, const DampedSpectra& horizontal,
                                        const VerticalDemand& vertical, const ElOptions& options);

}  // namespace freestand::rocking
