#include "api/spectrum.hpp"

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/limits.hpp"
#include "spectra/spectrum.hpp"

namespace freestand::api {

namespace spectrum_detail {

std::vector<double> explicit_frequencies(const std::vector<double>& f) {
    const SourceLocation where{"", 0, "frequency_hz"};
    for (std::size_t i = 0; i < f.size(); ++i) {
        require_positive(f[i], where);
        if (i > 0 && !(f[i] > f[i - 1]))
            throw InputError(where, fmt::format("{} Hz follows {} Hz; expected strictly "
                                                "increasing values",
                                                f[i], f[i - 1]));
    }
    return f;
}

}  // namespace spectrum_detail

std::vector<double> frequencies(const FrequencyGrid& grid) {
    if (!grid.frequency_hz.empty()) return spectrum_detail::explicit_frequencies(grid.frequency_hz);
    const SourceLocation at_fmin{"", 0, "fmin_hz"};
    const SourceLocation at_fmax{"", 0, "fmax_hz"};
    require_positive(grid.fmin_hz, at_fmin);
    require_positive(grid.fmax_hz, at_fmax);
    // The grid's ends are checked as the fields they came from, not as its frequencies.
    core::limits::require_at_least(grid.fmin_hz, core::limits::min_frequency_hz, at_fmin,
                                   "a response-spectrum frequency (Hz)");
    core::limits::require_within(grid.fmax_hz, core::limits::max_frequency_hz, at_fmax,
                                 "a response-spectrum frequency (Hz)");
    if (!(grid.fmax_hz > grid.fmin_hz))
        throw InputError(at_fmax, fmt::format("{} Hz; expected more than the lowest frequency "
                                              "{} Hz",
                                              grid.fmax_hz, grid.fmin_hz));
    const double per = grid.per_decade;
    if (!(per >= 1.0 && per <= 100000.0 && per == static_cast<double>(static_cast<int>(per))))
        throw InputError(SourceLocation{"", 0, "per_decade"},
                         fmt::format("{}; expected an integer in [1, 100000]", per));
    return spectra::log_frequencies(grid.fmin_hz, grid.fmax_hz, static_cast<int>(per));
}

const std::vector<double>& checked_dampings(const std::vector<double>& dampings) {
    const SourceLocation where{"", 0, "damping"};
    if (dampings.empty()) throw InputError(where, "no damping given; expected at least one");
    for (std::size_t i = 0; i < dampings.size(); ++i) {
        require_in_range(dampings[i], 0.0, 1.0, where, false, false);
        for (std::size_t j = 0; j < i; ++j)
            if (dampings[j] == dampings[i])
                throw InputError(where, fmt::format("{} given twice; expected distinct values",
                                                    dampings[i]));
    }
    return dampings;
}

SpectrumResult spectrum(const SpectrumRequest& request) {
    const std::vector<double>& dampings = checked_dampings(request.dampings);
    const std::vector<double> f = frequencies(request.grid);
    spectra::ResponseSpectra rs = spectra::response_spectra(request.record, dampings, f);
    return {request, core::measure(request.record), std::move(rs)};
}

std::string damping_key(double damping) { return fmt::format("{}", damping); }

json by_damping(const std::vector<double>& dampings,
                const std::vector<std::vector<double>>& values) {
    json j = json::object();
    for (std::size_t d = 0; d < dampings.size(); ++d) j[damping_key(dampings[d])] = values[d];
    return j;
}

json to_json(const SpectrumResult& result) {
    const core::Record& record = result.request.record;
    const core::GroundMotion& gm = result.measures;
    const spectra::ResponseSpectra& rs = result.spectra;
    json j;
    j["record"] = record.name;
    j["source"] = record.source;
    j["component"] = record.component;
    j["dt_s"] = record.dt_s;
    j["npts"] = record.size();
    j["pga_g"] = gm.pga_g;
    j["pgv_mps"] = gm.pgv_mps;
    j["pgd_m"] = gm.pgd_m;
    j["arias_mps"] = gm.arias_mps;
    j["d5_75_s"] = gm.d5_75_s;
    j["d5_95_s"] = gm.d5_95_s;
    j["frequencies_hz"] = rs.frequency_hz;
    j["psa_g"] = by_damping(rs.dampings, rs.psa_g);
    j["sd_m"] = by_damping(rs.dampings, rs.sd_m);
    j["psv_mps"] = by_damping(rs.dampings, rs.psv_mps);
    return j;
}

}  // namespace freestand::api
