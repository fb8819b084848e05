#pragma once
/// RFC 4180 comma-separated tables (a batch list read, a batch summary written): fields
/// separated by ',', records by CRLF or LF; a field in double quotes may hold commas, line
/// breaks and "" for one quote. Hand-written (about 80 lines) because none of the project's
/// libraries reads or writes CSV; the acceleration-record reader (readers.hpp) is a fixed
/// two-column format of its own.
#include <string>
#include <string_view>
#include <vector>

namespace freestand::core {

/// One record of a table and the 1-based line it starts on.
struct CsvRecord {
    int line = 0;
    std::vector<std::string> fields;
};

/// Parses text as RFC 4180 records. A leading UTF-8 BOM is dropped and UTF-16 refused
/// (text::utf8_text); empty lines are skipped (an empty record carries nothing). Fields are returned as written, without their quotes and
/// not trimmed. Throws InputError at file:line on a double quote inside an unquoted field, text
/// after a closing quote, or a quoted field that never closes.
std::vector<CsvRecord> parse_csv_table(std::string_view text, const std::string& file);

/// A field as RFC 4180 writes it: in double quotes (each quote doubled) when it holds a comma,
/// a double quote, a CR or an LF, or starts or ends with a space; else as it is.
std::string csv_field(std::string_view text);

/// Fields quoted by csv_field, joined by ',' and ended by CRLF (RFC 4180 s.2 rule 1).
std::string csv_record(const std::vector<std::string>& fields);

}  // namespace freestand::core
