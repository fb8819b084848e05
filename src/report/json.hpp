#pragma once
/// result.json: every number of the assessment, with the stamp under "stamp" (issue 6).
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "assess/result.hpp"

namespace freestand::report {

/// Reproducibility stamp (STYLE.md: stamp outputs with version, commit and input hash).
struct Stamp {
    std::string tool_version;  ///< FREESTAND_VERSION
    std::string commit;        ///< passed in by the CLI (build_commit), "unknown" outside git
    std::string input_sha256;  ///< of the case file's bytes
    std::string case_file;     ///< path as given
    std::uint64_t seed = 0;
};

/// Stamp for a case file's bytes.
Stamp make_stamp(const std::string& case_bytes, const std::string& case_file, std::uint64_t seed,
                 const std::string& commit);

/// Numbers are rounded to 10 significant digits so the file is stable across platforms;
/// absent values are null. Key order is fixed (ordered_json).
nlohmann::ordered_json to_json(const assess::AssessmentResult& r, const Stamp& stamp);

/// Rounds to 10 significant digits (the JSON precision).
double round10(double v);

}  // namespace freestand::report
