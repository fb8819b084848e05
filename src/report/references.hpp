#pragma once
/// The sources the reports cite: the project's methods document and the standards and papers
/// behind each model (docs/methods.md "Sources"). One list, so every report cites the same text.
#include <string>
#include <vector>

namespace freestand::report {

struct Reference {
    std::string key;   ///< short label used in the text, e.g. "ASCE 4-16"
    std::string text;  ///< full citation
};

/// In report order: the methods document first, then standards, then papers.
const std::vector<Reference>& references();

/// The references with these keys, in the order given. Throws std::out_of_range naming an
/// unknown key (a programming error: the keys are literals in the code).
std::vector<Reference> references(const std::vector<std::string>& keys);

}  // namespace freestand::report
