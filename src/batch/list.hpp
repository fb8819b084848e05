#pragma once
/// A facility's equipment list for a batch (README "Batch"): a folder of case files, or a
/// CSV or TOML list of case files with values replacing each case's own (assess/overrides.hpp).
///
/// - A folder: every `*.toml` in it (not in sub-folders; hidden files skipped), sorted by file
///   name, each named by its file's stem, none overridden.
/// - A `.csv` list (RFC 4180): a header row naming the columns, then one row per component.
///   Columns: `file` (required), `name`, `pga_g` (levels separated by ';', e.g. 0.1;0.2;0.3),
///   `base_material`, `seed`, `histories_per_level`, in any order; an empty cell keeps the case
///   file's value (the stem for `name`). Cells are trimmed of blanks; empty lines are skipped.
/// - A `.toml` list: `[[case]]` tables with the same keys, `pga_g` an array of numbers.
///
/// Case paths are relative to the list file's folder. A name is a report folder: 1-100
/// characters among letters, digits, '.', '_', '-', '+', starting with a letter or digit, not a
/// summary file's name, and unique ignoring case. Every problem of the list (an unknown column
/// or key, a missing file column, a duplicate name, a bad value) is an InputError naming
/// list:line and the field, before any case is read; a case file that is missing or bad is the
/// batch's business (a failed row), not the list's.
#include <filesystem>
#include <string>
#include <vector>

#include "assess/overrides.hpp"
#include "core/errors.hpp"

namespace freestand::batch {

/// One component of a list.
struct BatchEntry {
    std::string name;                ///< its report folder's name
    std::filesystem::path case_file;  ///< resolved against the list file's folder
    assess::CaseOverrides overrides;  ///< checked on their own (assess::check_overrides)
    int line = 0;                     ///< line of the list that gives it; 0 in a folder
};

struct BatchList {
    std::string source;  ///< the list file or folder, as given
    std::string sha256;  ///< of the list file's bytes; "" for a folder
    std::vector<BatchEntry> entries;  ///< in list order
};

/// Columns of a CSV list and keys of a TOML list's [[case]] tables.
const std::vector<std::string>& list_keys();

/// Reads a list: a folder, a `.csv` or a `.toml` file (see above). Throws InputError with field
/// `list` (the path as its file, no line) when the path is none of these, IoError when it
/// cannot be read, InputError on any bad content or a list without components.
BatchList read_batch_list(const std::filesystem::path& list);

/// Reads list text; file_label names the file in messages and its folder resolves case paths.
BatchList parse_csv_list(const std::string& text, const std::string& file_label);
BatchList parse_toml_list(const std::string& text, const std::string& file_label);

/// Throws InputError at where unless name can be a report folder's name (see above).
void check_name(const std::string& name, const SourceLocation& where);

}  // namespace freestand::batch
