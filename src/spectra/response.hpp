#pragma once
/// Linear SDOF response spectra by the Nigam-Jennings exact recurrence (docs/methods.md s.8).
#include <memory>
#include <vector>

#include "core/record.hpp"
#include "core/units.hpp"
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
/// samples; each oscillator sub-steps so its step is <= T/20. The oscillators start at rest at
/// the first sample and peaks are taken over the record's duration (no free-vibration tail).
/// Dampings in [0, 1), frequencies finite and > 0 (any order); throws InputError otherwise.
ResponseSpectra response_spectra(const core::Record& record, const std::vector<double>& dampings,
                                 const std::vector<double>& frequency_hz);

/// Integration controls of the response computation.
struct ResponseOptions {
    /// Each oscillator sub-steps so its step is <= T / min_steps_per_period (docs/methods.md s.8:
    /// T/20, else peaks between samples are missed). 0 turns sub-stepping off: one step per
    /// sample, exact at the samples but blind between them (for benchmarks and tests only).
    int min_steps_per_period = 20;
    /// Advance up to this many oscillators per vector register: eight per 512-bit register
    /// where the CPU has AVX-512, four per 256-bit one where it has AVX, else two per 128-bit
    /// one (>= 2). Each oscillator's arithmetic is the same IEEE operations in the same order
    /// at any width, so the results are the same bits; fewer is for the tests that check so.
    int max_lanes = 8;
};

/// As above with explicit integration controls (benchmarks, convergence tests), PSA in the unit
/// g of size g_mps2, m/s^2 (a case's site.g_mps2).
ResponseSpectra response_spectra(const core::Record& record, const std::vector<double>& dampings,
                                 const std::vector<double>& frequency_hz,
                                 const ResponseOptions& options, double g_mps2 = units::g_mps2);

/// Peak relative displacement of one oscillator and when it happens: what time-domain spectral
/// matching (RspMatch-style wavelet adjustment) needs.
struct OscillatorPeak {
    double sd_m = 0.0;    ///< signed relative displacement at the peak of |u|, m
    double time_s = 0.0;  ///< time of that peak (a sub-step point), s from the first sample
};

/// Signed peak displacement and its time for each frequency at one damping (same sub-stepping
/// as response_spectra). PSA = omega^2 |sd_m| / g.
std::vector<OscillatorPeak> peak_responses(const core::Record& record, double damping,
                                           const std::vector<double>& frequency_hz);

/// PSA only, one damping, in the unit g of size g_mps2, m/s^2: the hot path for matching loops.
std::vector<double> psa_g(const core::Record& record, double damping,
                          const std::vector<double>& frequency_hz,
                          double g_mps2 = units::g_mps2);

/// Oscillators of one damping at fixed frequencies for records sampled at dt_s, set up once
/// (their exact one-sample maps, packed for the vector loops): for loops that take many spectra
/// of records of one time step. Each call gives the same bits as the free functions above.
/// Immutable after construction: one set may serve several threads at once.
class OscillatorSet {
  public:
    /// Throws InputError as response_spectra does for a bad damping or frequency, and for a
    /// dt_s that is not a finite number > 0.
    OscillatorSet(double damping, const std::vector<double>& frequency_hz, double dt_s,
                  const ResponseOptions& options = {});

    const std::vector<double>& frequency_hz() const;
    double damping() const;
    double dt_s() const;

    /// The record must be sampled at dt_s (InputError otherwise), as validate() accepts, with at
    /// least 2 samples. Peak relative displacement |u|, m, at each frequency.
    std::vector<double> sd_m(const core::Record& record) const;
    /// PSA = omega^2 SD / g at each frequency, in the unit g of size g_mps2, m/s^2.
    std::vector<double> psa_g(const core::Record& record, double g_mps2 = units::g_mps2) const;
    /// Signed peak displacement and its time at each frequency.
    std::vector<OscillatorPeak> peak_responses(const core::Record& record) const;

  private:
    struct Prepared;
    std::shared_ptr<const Prepared> prepared_;
};

}  // namespace freestand::spectra
