#pragma once
/// Spectral demand at an arbitrary damping, for the equivalent-linear rocking estimate
/// (docs/methods.md s.5a: "interpolating the damping on log axes").
#include <functional>
#include <string>
#include <vector>

#include "spectra/spectrum.hpp"

namespace freestand::rocking {

/// PSA of one component (or SA_VH) at one damping, possibly blended from two spectra.
struct DampedDemand {
    spectra::Spectrum lo;        ///< spectrum at (or nearest below) the damping
    spectra::Spectrum hi;        ///< spectrum above it; used when weight_hi > 0
    double weight_hi = 0.0;      ///< t in ln PSA = (1 - t) ln PSA_lo + t ln PSA_hi
    double factor = 1.0;         ///< multiplies the PSA (damping scaling, spectrum scale)
    std::string note;            ///< how the damping was obtained

    /// PSA at f_hz, g: lo^(1 - t) hi^t * factor, each read with Spectrum::psa_at.
    double psa_g(double f_hz) const;
};

/// EN 1998-1 eq. (3.6) damping correction eta = sqrt(10 / (5 + xi)) with xi in percent, not
/// below 0.55. damping in [0, 1).
double ec8_eta(double damping);

/// A horizontal (or vertical) demand available at several dampings: either a set of spectra
/// of the same motion at distinct dampings, or a generator (a design target) producing any.
class DampedSpectra {
public:
    /// Set of spectra at distinct dampings (any order; at least one). InputError otherwise.
    explicit DampedSpectra(std::vector<spectra::Spectrum> set);
    /// Design-target generator: damping -> spectrum at that damping.
    explicit DampedSpectra(std::function<spectra::Spectrum(double damping)> generator,
                           std::string label);

    /// Demand at damping (0, 1). Generator: generator(damping). Set: the spectrum itself at an
    /// available damping; log-log interpolation in damping between the two that bracket it;
    /// outside the available range, the nearest spectrum scaled by ec8_eta(damping) /
    /// ec8_eta(nearest) (noted: the EN 1998-1 factor is meant for the amplified range).
    DampedDemand at(double damping) const;

    /// Rigid-limit PSA (at the highest frequency) of the lowest-damping spectrum, or of the
    /// generator's 5% spectrum, g: the zero-period acceleration standing in for the PGA.
    double zpa_g() const;
    /// The frequency zpa_g() is read at (the spectrum's highest), Hz.
    double zpa_frequency_hz() const;

    std::string label() const;

private:
    std::vector<spectra::Spectrum> set_;  // sorted by damping
    std::function<spectra::Spectrum(double)> generator_;
    std::string label_;
};

}  // namespace freestand::rocking
