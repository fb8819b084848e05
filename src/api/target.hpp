#pragma once
/// target: a design spectrum (RG 1.60, ASCE 7, EC8, IS 1893) as a matching target
/// (docs/methods.md s.8), and the design values `generate` shares with it.
#include <optional>
#include <string>
#include <vector>

#include "api/json.hpp"
#include "api/spectrum.hpp"
#include "spectra/spectrum.hpp"

namespace freestand::api {

/// The values a design spectrum is built from; each design takes its own and refuses the
/// others: rg1.60 pga_g; asce7 sds_g, sd1_g, tl_s; ec8 ag_g, type, ground; is1893 pga_g, soil.
struct DesignValues {
    std::optional<double> pga_g;  ///< peak ground acceleration, g, > 0
    std::optional<double> sds_g;  ///< ASCE 7 SDS, g, > 0
    std::optional<double> sd1_g;  ///< ASCE 7 SD1, g, > 0
    std::optional<double> tl_s;   ///< ASCE 7 long-period transition, s, > SD1/SDS
    std::optional<double> ag_g;   ///< EC8 design ground acceleration on rock, g, > 0
    std::optional<std::string> type;    ///< EC8 spectrum type "1" or "2"
    std::optional<std::string> ground;  ///< EC8 ground type "A" to "E"
    std::optional<std::string> soil;    ///< IS 1893 "rock", "medium" or "soft"
};

/// The design names: rg1.60, asce7, ec8, is1893.
const std::vector<std::string>& design_names();

/// InputError naming design_field (the request's field that named the design) for an unknown
/// design, or naming a value the design does not take.
void check_design(const std::string& design_field, const std::string& design,
                  const DesignValues& values);

/// The design spectrum at one damping on frequency_hz (horizontal unless vertical, which only
/// RG 1.60 has); InputError naming the field for a missing, inapplicable or out-of-range value.
spectra::Spectrum design_spectrum(const std::string& design_field, const std::string& design,
                                  const DesignValues& values, double damping, bool vertical,
                                  const std::vector<double>& frequency_hz);

struct TargetRequest {
    std::string design;                  ///< rg1.60, asce7, ec8 or is1893
    DesignValues values;
    std::vector<double> dampings{0.05};  ///< rg1.60 0.005-0.10, ec8 (0, 1), others 0.05 only
    bool vertical = false;               ///< rg1.60's vertical spectrum
    FrequencyGrid grid;
};

struct TargetResult {
    TargetRequest request;
    std::vector<double> frequency_hz;
    std::vector<spectra::Spectrum> spectra;  ///< one per damping, in the request's order
};

/// The design spectra of the checked request; InputError naming the field otherwise.
TargetResult target(const TargetRequest& request);

/// `target --json`.
json to_json(const TargetResult& result);

/// Where a design's formulas come from, for the spectrum file's comments.
const std::string& design_source(const std::string& design);
/// How a design's spectrum scales with its level, for the spectrum file's comments.
const std::string& design_scaling(const std::string& design);

}  // namespace freestand::api
