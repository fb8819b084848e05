#include "sliding/table_displacement.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/errors.hpp"
#include "core/fft.hpp"

namespace freestand::sliding {

double highpass_gain(double f_hz, double f_c_hz) {
    if (f_hz <= 0.0) return 0.0;
    return 1.0 / (1.0 + std::pow(f_c_hz / f_hz, 2 * highpass_order));
}

double highpass_peak_displacement_m(const core::Record& record, double f_c_hz) {
    const double nyquist_hz = 0.5 / record.dt_s;
    if (!std::isfinite(f_c_hz) || f_c_hz <= 0.0 || f_c_hz >= nyquist_hz) {
        throw InputError(SourceLocation{"", 0, "energy_highpass_hz"},
                         "expected a corner frequency in (0, Nyquist = " +
                             std::to_string(nyquist_hz) + ") Hz");
    }
    const std::size_t n = record.accel_mps2.size();
    const auto pad = static_cast<std::size_t>(std::ceil(10.0 / f_c_hz / record.dt_s));
    core::RealFft fft(core::fft_size(2 * n + pad));
    std::vector<std::complex<double>> spectrum = fft.forward(record.accel_mps2);
    const double df_hz = 1.0 / (static_cast<double>(fft.size()) * record.dt_s);
    for (std::size_t k = 0; k < spectrum.size(); ++k) {
        const double f_hz = df_hz * static_cast<double>(k);
        const double w = 2.0 * std::numbers::pi * f_hz;
        spectrum[k] = k == 0 ? 0.0 : -spectrum[k] * highpass_gain(f_hz, f_c_hz) / (w * w);
    }
    const std::vector<double> d = fft.inverse(spectrum);
    double peak = 0.0;
    for (double v : d) peak = std::max(peak, std::abs(v));
    return peak / static_cast<double>(fft.size());
}

}  // namespace freestand::sliding
