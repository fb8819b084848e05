#pragma once
/// rock: closed-form rocking and overturning checks of a block (docs/methods.md s.5, s.5a).
#include <array>
#include <filesystem>
#include <optional>
#include <vector>

#include "api/json.hpp"
#include "rocking/summary.hpp"
#include "sliding/block_spec.hpp"

namespace freestand::api {

/// An InputError names the field (box.half_width_m, pga_h_g, av_g, pgv_mps, v_ratio, mu_s,
/// restitution, fs_required, fixed_base_hz, rock_band_hz), as classify's does.
struct RockRequest {
    sliding::BoxSpec box;
    /// Horizontal spectrum files, one per damping (SA_VH or one component); none: no spectral
    /// checks.
    std::vector<std::filesystem::path> spectrum_files;
    std::vector<std::filesystem::path> spectrum_v_files;  ///< vertical, one per damping
    std::optional<double> v_ratio;        ///< SA_V / SA_H without vertical spectra, >= 0
    std::optional<double> pga_h_g;        ///< g, >= 0; default the spectrum's ZPA
    std::optional<double> av_g;           ///< peak vertical, g, in [0, 1), taken downward
    std::optional<double> pgv_mps;        ///< m/s, >= 0 (Ishiyama check)
    std::optional<double> mu_s;           ///< in [0, 2] (initiating mode)
    std::optional<double> restitution;    ///< in [0, 1]; default Housner's
    double fs_required = 1.5;             ///< required alpha / theta0, >= 1
    std::optional<double> fixed_base_hz;  ///< > 0 (flexible-body screen)
    std::optional<std::array<double, 2>> rock_band_hz;  ///< free-rocking band LO, HI, 0 < LO < HI
};

struct RockResult {
    rocking::RockingInput input;
    rocking::RockingChecks checks;
};

/// The checked request's checks; InputError naming the field otherwise, IoError for a
/// spectrum file that cannot be read.
RockResult rock(const RockRequest& request);

/// `rock --json`.
json to_json(const RockResult& result);

}  // namespace freestand::api
