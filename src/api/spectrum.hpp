#pragma once
/// spectrum: the linear response spectra (PSA, SD, PSV) of an acceleration record on a frequency
/// grid, with the record's ground-motion measures (docs/methods.md s.8).
#include <vector>

#include "api/json.hpp"
#include "core/measures.hpp"
#include "core/record.hpp"
#include "spectra/response.hpp"

namespace freestand::api {

/// The frequencies a spectrum is computed on: the explicit list when one is given, otherwise
/// log-spaced from fmin_hz to fmax_hz at per_decade points per decade.
struct FrequencyGrid {
    std::vector<double> frequency_hz;  ///< explicit, strictly increasing, > 0; empty: log grid
    double fmin_hz = 0.1;              ///< lowest frequency, Hz, > 0
    double fmax_hz = 100.0;            ///< highest frequency, Hz, > fmin_hz
    double per_decade = 100.0;         ///< points per decade, an integer in [1, 100000]
};

/// The grid's frequencies; InputError naming frequency_hz, fmin_hz, fmax_hz or per_decade.
std::vector<double> frequencies(const FrequencyGrid& grid);

/// The dampings, each in (0, 1) and given once; InputError naming `damping` otherwise.
const std::vector<double>& checked_dampings(const std::vector<double>& dampings);

struct SpectrumRequest {
    core::Record record;
    std::vector<double> dampings{0.05};  ///< fractions of critical, each in (0, 1)
    FrequencyGrid grid;
};

struct SpectrumResult {
    SpectrumRequest request;
    core::GroundMotion measures;
    spectra::ResponseSpectra spectra;
};

/// The record's measures and spectra; InputError naming the field otherwise.
SpectrumResult spectrum(const SpectrumRequest& request);

/// `spectrum --json`: the record's measures and its PSA, SD and PSV per damping.
json to_json(const SpectrumResult& result);

/// Key of a damping in documents and column names: shortest round-trip text, 0.05 -> "0.05".
std::string damping_key(double damping);

/// {"<damping>": [values...], ...}
json by_damping(const std::vector<double>& dampings, const std::vector<std::vector<double>>& values);

}  // namespace freestand::api
