#pragma once
/// Linear SDOF response spectra by the Nigam-Jennings exact recurrence (METHODS.md s.8).
#include <vector>

#include "core/record.hpp"
#include "spectra/spectrum.hpp"

namespace freestand::spectra {

/// Peak responses of oscillators at each frequency and damping.
/// Indexing: psa_g[d][i] for dampings[d], frequency_hz[i].
struct ResponseSpectra {
    std::vector<double> frequency_hz;
    std::vector<double> dampings;
    std::vector<std::vector<double>> psa_g;    ///< pseudo-acceleration omega^2 SD, g
    std::vector<std::vector<double>> sd_m;     ///< peak relative displacement, m
    std::vector<std::vector<double>> psv_mps;  ///< pseudo-velocity omega SD, m/s

    /// One damping's PSA as a Spectrum.
    Spectrum spectrum(std::size_t damping_index) const;
};

/// Computes all oscillators in one pass over the record. Input is piecewise linear between
/// samples; each oscillator sub-steps so its step is <= T/20.
ResponseSpectra response_spectra(const core::Record& record, const std::vector<double>& dampings,
                                 const std::vector<double>& frequency_hz);

/// PSA only, one damping: the hot path for matching loops.
std::vector<double> psa_g(const core::Record& record, double damping,
                          const std::vector<double>& frequency_hz);

}  // namespace freestand::spectra
