#pragma once
/// Internal: typed, range-checked reading of one TOML table that remembers which keys were read,
/// so finish() can reject the rest (STYLE.md: unknown keys are errors, as SeisSol's
/// warnUnknown()). For the case reader (case_detail.hpp) and batch lists' TOML form only: a
/// *_detail header is not installed (cmake/install.cmake), so toml++ stays out of the package.
#include <toml++/toml.h>

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "assess/overrides.hpp"
#include "core/errors.hpp"
#include "core/limits.hpp"

namespace freestand::assess {

/// The TOML document (UTF-8, a BOM dropped, UTF-16 refused: core::text::utf8_text); a syntax
/// error is an InputError at file_label and its line.
toml::table parse_toml(const std::string& text, const std::string& file_label);

/// Allowed interval of a number; bounds inclusive unless stated (the limits' own type, so that
/// a case key and a command-line option can share one range of core/limits.hpp).
using Range = core::limits::Range;
using core::limits::describe;

/// Reads keys of one table. Errors name "file:line: table.key: ..." and the allowed range.
class TableReader {
  public:
    /// table may be null (the table is absent): every key reads as missing.
    TableReader(const toml::table* table, std::string file, std::string table_name);

    bool has(const std::string& key) const;
    /// The key is present and holds an array (for keys that take a number or an array).
    bool holds_array(const std::string& key) const;
    /// Location of key (its value's line), or of the table when the key is absent.
    SourceLocation where(const std::string& key) const;

    /// A number (integer or float) within range, or nullopt when absent.
    std::optional<double> number(const std::string& key, Range range);
    /// As number(), but a missing key is an error.
    double required_number(const std::string& key, Range range);
    /// An integer within [lo, hi], or nullopt when absent.
    std::optional<long long> integer(const std::string& key, long long lo, long long hi);
    /// A string, or nullopt when absent.
    std::optional<std::string> string(const std::string& key);
    std::string required_string(const std::string& key);
    /// An array of numbers, each within range; size must equal exact_size when it is > 0.
    std::optional<std::vector<double>> numbers(const std::string& key, Range range,
                                               std::size_t exact_size = 0);
    std::optional<std::vector<std::string>> strings(const std::string& key);
    /// A nested (inline) table, or nullptr when absent; an error when the key holds another type.
    const toml::table* table(const std::string& key);
    /// A boolean, or nullopt when absent.
    std::optional<bool> boolean(const std::string& key);

    /// Throws InputError for the first key (in file order) that was never read, listing the
    /// allowed keys.
    void finish(const std::vector<std::string>& allowed) const;

    [[noreturn]] void fail(const std::string& key, const std::string& message) const;
    /// Fails at key when text holds a control character (tab and line breaks excepted).
    void require_printable(const std::string& key, const std::string& text) const;

  private:
    const toml::node* find(const std::string& key);
    double as_number(const std::string& key, const toml::node& node, Range range) const;

    const toml::table* table_;
    std::string file_;
    std::string name_;
    std::set<std::string> read_;
};

/// Writes a batch list's overrides (assess/overrides.hpp) into a parsed case document, creating
/// [site] or [options] when absent; declared here, with the TOML reader, so that the overrides'
/// own header needs no toml++.
void apply_overrides(toml::table& root, const CaseOverrides& o);

}  // namespace freestand::assess
