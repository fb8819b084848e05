#pragma once
/// generate: spectrum-compatible acceleration histories (h1, h2, v) and their acceptance against
/// SRP 3.7.1 and the realism checks (docs/methods.md s.8).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "api/json.hpp"
#include "api/target.hpp"
#include "motion/motion.hpp"

namespace freestand::api {

struct GenerateRequest {
    /// The design target (rg1.60, asce7, ec8, is1893) of `design`; empty when target_file gives
    /// the target instead. One of the two, not both.
    std::string target;
    DesignValues design;
    std::filesystem::path target_file;     ///< 5%-damped target spectrum file, or empty
    std::filesystem::path target_file_10;  ///< optional 10%-damped target (reported only)
    /// Vertical PGA over horizontal: rg1.60 scales its vertical spectrum to this ZPA (default 1,
    /// RG 1.60's own); other targets take ratio x horizontal (default 2/3).
    std::optional<double> vertical_ratio;
    /// Seed records to match, one per component; empty selects synthetic records.
    std::vector<std::filesystem::path> seed_records;
    /// h1, h2, v; empty: all three, or with seed records as many as records given.
    std::vector<std::string> components;
    std::optional<double> duration_s;  ///< synthetic records only (default 20, >= 20)
    std::optional<double> dt_s;        ///< synthetic records only (default 0.005, <= 0.01)
    std::uint64_t seed = 1;
    /// Realism ranges on the horizontals; rg1.60 sets all three by default, others none.
    std::optional<motion::Range> va_range_mps_per_g;
    std::optional<motion::Range> adv2_range;
    std::optional<double> da_max_m_per_g;
    /// wall_s in match.json; false writes it as null so identical runs are byte-identical.
    bool timing = true;
};

struct GenerateResult {
    GenerateRequest request;
    motion::TargetSet targets;
    motion::GeneratedSet set;
};

/// The targets, generation options and records of the checked request, generated; InputError
/// naming the field, IoError for a file that cannot be read.
GenerateResult generate(const GenerateRequest& request);

/// match.json.
json to_json(const GenerateResult& result);

}  // namespace freestand::api
