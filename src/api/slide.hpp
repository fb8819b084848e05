#pragma once
/// slide: closed-form sliding estimates, ASCE 4 equivalent-linear and energy conservation
/// (docs/methods.md s.4).
#include <filesystem>
#include <optional>
#include <vector>

#include "api/json.hpp"
#include "sliding/asce.hpp"

namespace freestand::api {

/// An InputError names the field (mu_s, av_g, pgd_m, pga_h_g, fes_hz), as classify's does.
struct SlideRequest {
    double mu_s = 0.0;             ///< static friction coefficient, in [0, 2]
    double av_g = 0.0;             ///< peak vertical acceleration, g, in [0, 2.5)
    std::optional<double> pgd_m;   ///< peak ground displacement, m, >= 0 (energy method)
    std::optional<double> pga_h_g; ///< peak horizontal acceleration, g, >= 0
    /// f_es: given (Hz, > 0), or found on 10%-damped horizontal spectrum files (one or two
    /// components): exactly one of the two.
    std::optional<double> fes_hz;
    std::vector<std::filesystem::path> spectrum10_files;
};

struct SlideResult {
    SlideRequest request;
    sliding::SlidingEstimate estimate;
};

/// The checked request's estimates; InputError naming the field otherwise, IoError for a
/// spectrum file that cannot be read.
SlideResult slide(const SlideRequest& request);

/// `slide --json`.
json to_json(const SlideResult& result);

}  // namespace freestand::api
