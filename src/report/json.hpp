#pragma once
/// result.json: every number of the assessment, with the stamp under "stamp" (README "Outputs").
#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "assess/result.hpp"

namespace freestand::report {

/// Reproducibility stamp (STYLE.md: stamp outputs with version, commit and input hash).
/// One input file of a run and the SHA-256 of its bytes.
struct StampedInput {
    std::string file;  ///< path as the case or the command line gives it
    std::string sha256;
};

struct Stamp {
    std::string tool_version;  ///< core::version()
    /// The build's commit (api::build_commit): 12 hex digits, "-dirty" appended when the build's tree had
    /// uncommitted changes; "unknown" outside git.
    std::string commit;
    std::string input_sha256;  ///< of the case file's bytes
    std::string case_file;     ///< path as given
    std::uint64_t seed = 0;
    /// Every other input the run read: target spectra and seed records.
    std::vector<StampedInput> inputs;
};

/// Stamp for a case file's bytes.
Stamp make_stamp(const std::string& case_bytes, const std::string& case_file, std::uint64_t seed,
                 const std::string& commit);

/// The case's other input files (target spectra, seed records), hashed.
std::vector<StampedInput> stamped_inputs(const assess::Case& c);

/// [{"file", "sha256"}] of a stamp's other inputs, as written under "stamp"/"inputs".
nlohmann::ordered_json inputs_json(const std::vector<StampedInput>& inputs);

/// The stamp as written under "stamp", and read back (shard files carry it to `merge`).
nlohmann::ordered_json stamp_json(const Stamp& stamp);
Stamp stamp_from_json(const nlohmann::json& j);

/// Numbers are rounded to 10 significant digits so the file is stable across platforms;
/// absent values are null. Key order is fixed (ordered_json).
nlohmann::ordered_json to_json(const assess::AssessmentResult& r, const Stamp& stamp);

/// Rounds to 10 significant digits (the JSON precision).
double round10(double v);

/// A JSON number rounded by round10; null when not finite.
nlohmann::ordered_json json_number(double v);

/// A level's settling (docs/methods.md s.6 step 4): n_sets, resamples, settled_fraction,
/// settled, batches.
nlohmann::ordered_json settling_json(const assess::Settling& s);

}  // namespace freestand::report
