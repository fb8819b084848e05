#pragma once
/// The improved tapered cosine wavelet of Al Atik & Abrahamson (2010, Earthquake Spectra 26(3)
/// 601-617, eqs. 14, 16, 17) and the exact response of a damped oscillator to it.
#include <array>
#include <cstddef>
#include <vector>

namespace freestand::motion {

/// Wavelet adjusting the oscillator (f_hz, damping) at its peak time:
/// w(t) = cos(omega' (t - t_peak + dt_shift)) exp(-((t - t_peak + dt_shift) / gamma)^2), with
/// omega' = omega sqrt(1 - zeta^2), gamma = 1.178 f^-0.93 s (f in Hz) and
/// dt_shift = atan(sqrt(1 - zeta^2) / zeta) / omega', so the oscillator's response to it peaks
/// near t_peak. Symmetric about its centre, its integral is gamma sqrt(pi) exp(-(omega' gamma/2)^2)
/// (< 1e-4 gamma for f >= 0.1 Hz), so it adds almost no velocity or displacement drift; the
/// matcher's two baseline rows remove the rest exactly.
struct Wavelet {
    double frequency_hz = 0.0;  ///< oscillator frequency the wavelet carries
    double damping = 0.05;
    double omega_d_radps = 0.0;  ///< omega'
    double gamma_s = 0.0;
    double centre_s = 0.0;  ///< t_peak - dt_shift

    /// Wavelet placed for a peak at t_peak_s.
    static Wavelet at(double frequency_hz, double damping, double t_peak_s);
    /// Wavelet of frequency_hz placed for the peak at t_peak_s of a stiffer oscillator
    /// (oscillator_hz >= frequency_hz): the shift is the oscillator's phase lag at the
    /// wavelet's frequency, atan2(2 zeta r, 1 - r^2) / omega', r = frequency / oscillator
    /// (-> 0 for a rigid oscillator, which follows the wavelet; AA2010's shift at r = 1).
    static Wavelet for_oscillator(double frequency_hz, double oscillator_hz, double damping,
                                  double t_peak_s);
    /// Gaussian acceleration pulse exp(-((t - centre) / gamma)^2) (omega' = 0): a smooth velocity
    /// step used as baseline-correction basis.
    static Wavelet pulse(double centre_s, double gamma_s);
    double value(double t_s) const;
    /// Times beyond which |w| < 1e-7: centre -+ 4 gamma.
    double start_s() const;
    double end_s() const;
};

/// Pseudo-acceleration response y = -omega^2 u at t_s >= 0 of the oscillator (f_hz, damping),
/// at rest at t = 0, to the continuous wavelet cut off before t = 0 (as in a record):
/// y(t) = omega^2 / omega_d * int_{0}^{t} exp(-zeta omega (t - s)) sin(omega_d (t - s)) w(s) ds,
/// in closed form through the Faddeeva function (derivation in the source): the response to
/// the whole wavelet minus the free vibration its part before t = 0 leaves.
double wavelet_response(const Wavelet& w, double f_hz, double damping, double t_s);

/// y and dy/dt at t = 0 of the oscillator (f_hz, damping) driven by the whole wavelet: the free
/// vibration its part before t = 0 leaves, which wavelet_response removes. It depends on the
/// wavelet and the oscillator only, not on t_s.
struct WaveletStart {
    double y = 0.0;
    double ydot = 0.0;
};
WaveletStart wavelet_start(const Wavelet& w, double f_hz, double damping);
/// wavelet_response with wavelet_start(w, f_hz, damping) given (the same bits), for several t_s
/// of one wavelet and oscillator; `start` is read only if the wavelet starts before t = 0.
double wavelet_response(const Wavelet& w, double f_hz, double damping, double t_s,
                        const WaveletStart& start);

/// The oscillator (f_hz, damping) at t_s with the factors of the free vibration that
/// wavelet_response removes, exp(-zeta omega t), cos(omega_d t) and sin(omega_d t): the same
/// for every wavelet.
struct OscillatorAt {
    double f_hz = 0.0;
    double damping = 0.0;
    double t_s = 0.0;
    double decay = 1.0;
    double cos_wd_t = 1.0;
    double sin_wd_t = 0.0;
};
OscillatorAt oscillator_at(double f_hz, double damping, double t_s);
/// wavelet_response(w, o.f_hz, o.damping, o.t_s, start), the same bits, for many wavelets at
/// one oscillator and time.
double wavelet_response(const Wavelet& w, const OscillatorAt& o, const WaveletStart& start);

/// Many closed forms at once (a matcher's pass needs thousands): each costs two Faddeeva
/// evaluations, which are evaluated side by side (faddeeva.hpp). The same bits as one at a time.
/// wavelet_start(*wavelet, f_hz, damping) into *out, for each of r[0..n).
struct StartRequest {
    const Wavelet* wavelet = nullptr;
    double f_hz = 0.0;
    double damping = 0.0;
    WaveletStart* out = nullptr;
};
void wavelet_starts(const StartRequest* r, std::size_t n);
/// wavelet_response(*wavelet, *at, *start) into *out, for each of r[0..n).
struct ResponseRequest {
    const Wavelet* wavelet = nullptr;
    const OscillatorAt* at = nullptr;
    const WaveletStart* start = nullptr;
    double* out = nullptr;
};
void wavelet_responses(const ResponseRequest* r, std::size_t n);

/// The wavelet sampled at i * dt_s over its support inside a record of `samples` samples:
/// values[k] = w((first + k) dt). Computed by exact rotation / Gaussian-ratio recurrences
/// (relative drift ~1e-13 over 10^4 samples) instead of a cos and an exp per sample.
struct SampledWavelet {
    std::size_t first = 0;
    std::vector<double> values;
};
SampledWavelet sample_wavelet(const Wavelet& w, double dt_s, std::size_t samples);
/// The same into `out`, reusing its storage.
void sample_wavelet(const Wavelet& w, double dt_s, std::size_t samples, SampledWavelet& out);
/// The same, also returning sum_k weights_a[first + k] values[k] and the same of weights_b
/// (each `samples` long), summed in order of k as a loop over `out` would: the same bits,
/// without a second pass over the samples.
std::array<double, 2> sample_wavelet(const Wavelet& w, double dt_s, std::size_t samples,
                                     SampledWavelet& out, const std::vector<double>& weights_a,
                                     const std::vector<double>& weights_b);

/// The last form for several wavelets at once, the same bits: *out, *sum_a and *sum_b of each
/// request as sample_wavelet(*wavelet, dt_s, samples, *out, weights_a, weights_b) gives them.
/// Each sampling is a chain of dependent steps; several run side by side.
struct SampleRequest {
    const Wavelet* wavelet = nullptr;
    SampledWavelet* out = nullptr;
    double* sum_a = nullptr;
    double* sum_b = nullptr;
};
void sample_wavelets(const SampleRequest* r, std::size_t n, double dt_s, std::size_t samples,
                     const std::vector<double>& weights_a, const std::vector<double>& weights_b);

/// Adds amplitude * w sampled at i * dt_s to accel (over the wavelet's support inside the record).
void add_wavelet(const Wavelet& w, double amplitude, double dt_s, std::vector<double>& accel);
void add_wavelet(const SampledWavelet& w, double amplitude, std::vector<double>& accel);

}  // namespace freestand::motion
