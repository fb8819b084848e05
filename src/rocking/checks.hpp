#pragma once
/// Closed-form rocking and overturning checks (docs/methods.md s.5).
#include <string>

#include "block/block.hpp"
#include "core/units.hpp"
#include "rocking/demand.hpp"
#include "sliding/initiation.hpp"
#include "spectra/spectrum.hpp"

namespace freestand::rocking {

/// Peak horizontal acceleration that uplifts edge e, g: tan(alpha) (1 - av_g), with the peak
/// vertical av_g >= 0 taken downward (the worst case; docs/methods.md s.5). 0 <= av_g < 1.
double uplift_threshold_g(const block::Block& blk, block::Edge e, double av_g);

/// Ishiyama (1982) velocity bound, m/s: a block cannot overturn under harmonic excitation whose
/// peak base velocity is below V = 0.4 sqrt(8 g R (1 - cos alpha) / (3 cos alpha)). Derived for
/// uniform blocks; applied with edge e's R and alpha. g_mps2: gravity, m/s^2.
double ishiyama_velocity_mps(const block::Block& blk, block::Edge e,
                             double g_mps2 = units::g_mps2);

/// Energy to lift the CG over edge e, per unit mass, J/kg: E_ot / M = g R (1 - cos alpha).
double overturning_energy_jpkg(const block::Block& blk, block::Edge e,
                               double g_mps2 = units::g_mps2);

/// Housner's (1963) energy estimate against a spectral velocity.
struct HousnerEstimate {
    double sv_mps = 0.0;               ///< spectral velocity used
    double alpha_rad = 0.0;            ///< the block's slenderness about the edge
    /// Slenderness that just survives: sqrt(M R^2 / I_O) S_v / sqrt(g R), rad.
    double alpha_required_rad = 0.0;
    double e_ot_jpkg = 0.0;            ///< g R (1 - cos alpha)
    /// Energy the excitation imparts per unit mass, (1/2) (M R^2 / I_O) S_v^2 (the same
    /// small-angle balance that gives alpha_required).
    double e_in_jpkg = 0.0;
    bool survives = true;              ///< alpha > alpha_required
};

/// Housner estimate about edge e for sv_mps >= 0, under gravity g_mps2, m/s^2.
HousnerEstimate housner_energy(const block::Block& blk, block::Edge e, double sv_mps,
                               double g_mps2 = units::g_mps2);

/// Largest pseudo-velocity PSA g / (2 pi f) over the spectrum's points, m/s (between points the
/// log-log interpolation makes PSV a power law, so the maximum is at a point); the spectrum's
/// unit g is g_mps2, m/s^2.
double peak_pseudo_velocity_mps(const spectra::Spectrum& s, double g_mps2 = units::g_mps2);

/// Same for a demand at one damping, over the points of the spectra it blends.
double peak_pseudo_velocity_mps(const DampedDemand& d, double g_mps2 = units::g_mps2);

/// Warning about accelerations transmitted to the body and what is attached to it, for the
/// initiating mode: rocking amplifies them through impacts (1.3 to 11 measured on rigid
/// specimens), sliding attenuates them to about mu / A. Empty for rest.
std::string amplification_warning(sliding::Mode mode, double mu_s, double A);

}  // namespace freestand::rocking
