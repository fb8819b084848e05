#pragma once
/// Flexible-body screen (docs/methods.md s.2, flexible-body screen): a body whose fixed-base natural
/// frequency lies in the seismic band can uplift below the static threshold g tan(alpha) when
/// the excitation is strong near its frequencies ("frequency-induced rocking").
#include <optional>
#include <string>

#include "spectra/spectrum.hpp"

namespace freestand::rocking {

/// Bodies with a fixed-base frequency at or above this are rigid for the screen, Hz.
inline constexpr double rigid_frequency_hz = 33.0;

/// Half-width of the band put around a fixed-base frequency: [f / 1.15, 1.15 f], the +-15%
/// frequency uncertainty ASCE 4 covers by peak broadening.
inline constexpr double band_broadening = 1.15;

/// What the screen looks at. At least one of the two must be given.
struct FlexibleInput {
    std::optional<double> fixed_base_hz;      ///< fixed-base natural frequency, Hz (> 0)
    std::optional<double> rock_band_lo_hz;    ///< free-rocking band, Hz (both or neither)
    std::optional<double> rock_band_hi_hz;
    double uplift_threshold_g = 0.0;          ///< static threshold (1 - A_v) tan(alpha), g
    double pga_h_g = 0.0;                     ///< peak horizontal ground acceleration, g
};

/// Outcome. "Strong content" (the flag) means: the peak PSA of the spectrum in the band reaches
/// the static uplift threshold, peak_psa_g >= uplift_threshold_g. Reason: a body responding at
/// its own frequency carries inertial forces of M PSA at its mass, so its base overturning
/// moment reaches the restoring moment M g b once PSA >= g tan(alpha) even while the ground
/// acceleration stays below it. The flag does not depend on pga_h_g: a rigid classification
/// (uplift predicted, or sliding only) never lowers it; pga_h_g only shapes the reason.
struct FlexibleScreen {
    bool applies = false;           ///< false: no band in the seismic range (reason says why)
    double band_lo_hz = 0.0;        ///< lowest frequency screened (of either band)
    double band_hi_hz = 0.0;        ///< highest frequency screened (of either band)
    double peak_psa_g = 0.0;        ///< max of psa_at over the band(s), not the gap between
    double peak_f_hz = 0.0;
    double threshold_g = 0.0;
    bool flagged = false;           ///< strong content in the band: the flexible model must run
    std::string reason;
};

/// Screens spectrum s (use the body's damping, 5% when unknown) over the band: the fixed-base
/// band [f / 1.15, 1.15 f] when f < 33 Hz, the free-rocking band, or their union when both are
/// given (two disjoint bands are screened separately; the gap between them is not).
/// InputError for non-positive frequencies, lo >= hi, one band end only, or no input.
FlexibleScreen flexible_screen(const spectra::Spectrum& s, const FlexibleInput& in);

}  // namespace freestand::rocking
