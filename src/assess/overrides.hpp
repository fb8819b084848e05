#pragma once
/// Values given to a case from outside its file (a batch list's columns, README "Batch"). They are
/// written into the case's TOML document before it is read, so an overridden case reads exactly
/// as a case file carrying those values: the same checks, defaults and echoed assumptions.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/errors.hpp"

namespace freestand::assess {

/// Limits of the overridable values; the case reader applies the same ones (PGA levels:
/// core::limits::require_pga_levels).
inline constexpr long long histories_limit = 1000;  ///< [options] histories_per_level and max_histories_per_level
/// [options] seed in [0, 2^53 - 1]: every seed is exact as a JSON number.
inline constexpr long long max_seed = 9007199254740991LL;

/// What a batch list may give a case in place of its file's values; absent = the file's.
struct CaseOverrides {
    std::optional<std::vector<double>> pga_g;  ///< [site] pga_g, g
    /// [component] base_material, replacing the case's whole base description (mu_s, mu_k,
    /// restitution, mu_s_range, restitution_range): the case then reads as one naming only the
    /// material, as the base-material search assesses it.
    std::optional<std::string> base_material;
    std::optional<long long> seed;                 ///< [options] seed
    std::optional<long long> histories_per_level;  ///< [options] histories_per_level

    bool empty() const { return !pga_g && !base_material && !seed && !histories_per_level; }
};

/// The keys CaseOverrides sets, as a batch list names them.
inline const std::vector<std::string>& override_keys() {
    static const std::vector<std::string> keys{"pga_g", "base_material", "seed",
                                               "histories_per_level"};
    return keys;
}

/// Checks each value on its own (levels as core::limits::require_pga_levels takes them, a material of the
/// table, seed and histories within the case reader's ranges); where(key) locates a key for the
/// InputError. What depends on the case (a level weightless at its vertical ratio, a DeltaD
/// table of another length) is checked when the case is read.
void check_overrides(const CaseOverrides& o,
                     const std::function<SourceLocation(const std::string& key)>& where);

/// "pga_g = [0.1, 0.2]; seed = 4", in key order; "" when none.
std::string describe(const CaseOverrides& o);

}  // namespace freestand::assess
