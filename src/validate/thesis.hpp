#pragma once
/// The thesis values the validation compares with (docs/methods.md s.13), each with where it stands
/// in the thesis text: S. (A.) Saraswat, "Response Evaluation of Freestanding Systems subjected to
/// Seismic Loading", PhD thesis, HBNI / BARC, 2017, in the text extraction
/// ../shared/thesis/000_da2bef6b73563e7f.txt (figures lost; tables and conclusions present).
/// This table is the one place each value is written. tests/data/thesis/excerpt.txt holds the cited
/// lines with their numbers: the tests check that every quote and every value stands on its line
/// of the excerpt and, where the shared thesis folder is present, that the excerpt is the
/// thesis's own text.
#include <optional>
#include <string>
#include <vector>

namespace freestand::validate {

/// File name of the thesis text in the shared thesis folder.
inline constexpr const char* thesis_text_file = "000_da2bef6b73563e7f.txt";

/// Where a value stands in the thesis.
struct Citation {
    std::string where;  ///< section, table, equation or figure, e.g. "s.3.3.4.1, Table 3-6"
    int line = 0;       ///< 1-based line of the thesis text file
    std::string quote;  ///< a verbatim piece of that line (no tab)
};

/// One value or observation of the thesis.
struct Fact {
    std::string key;              ///< e.g. "ts1.vpeak_mps"
    std::optional<double> value;  ///< in `unit`; empty for an observation in words
    std::string unit;             ///< "m/s", "mm", "g", "Hz", "m/s^2", "rad", "m", "kg", "s", ""
    std::string text;             ///< what the thesis states, in a few words
    Citation cite;
};

/// Every fact, in report order.
const std::vector<Fact>& facts();

/// The fact with this key; std::logic_error if there is none (a programming error).
const Fact& fact(const std::string& key);

/// The fact's value; std::logic_error if it has none.
double value(const std::string& key);

/// "thesis s.3.3.4.1, Table 3-6, line 997" for a citation.
std::string cite_text(const Citation& c);

}  // namespace freestand::validate
