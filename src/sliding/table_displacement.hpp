#pragma once
/// DeltaD of the energy-conservation sliding estimate (docs/methods.md s.4): the shake table's peak
/// displacement. The thesis read it from test signals band-passed at 0.5-50 Hz; a broadband
/// design history carries most of its displacement below 0.5 Hz, so the history is high-passed
/// at the same corner before its displacement is taken.
#include "core/record.hpp"

namespace freestand::sliding {

/// Order of the Butterworth high-pass, applied forward and backward (zero phase), so the
/// magnitude response is 1 / (1 + (f_c / f)^(2 n)), one half at the corner. Order 2 makes the
/// response go as f^4 below the corner, the low-order acausal filter of strong-motion
/// processing practice (Boore & Bommer 2005; Boore 2005, "On pads and filters").
inline constexpr int highpass_order = 2;

/// Zero-phase high-pass response at f_hz for corner f_c_hz (see highpass_order).
double highpass_gain(double f_hz, double f_c_hz);

/// Peak |displacement| (m) of the record after a zero-phase high-pass at f_c_hz, computed in
/// the frequency domain: D(f) = -A(f) G(f) / (2 pi f)^2 with G the response above (G(0) = 0,
/// so no drift), on the record zero-padded to at least twice its length plus 10 / f_c seconds
/// so that the acausal filter's transients do not wrap around (Boore 2005 on padding). The
/// peak is taken over the whole padded window. Throws InputError (field "energy_highpass_hz")
/// unless f_c_hz is finite and in (0, Nyquist).
double highpass_peak_displacement_m(const core::Record& record, double f_c_hz);

}  // namespace freestand::sliding
