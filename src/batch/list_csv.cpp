// CSV lists (list.hpp): a header row naming the columns, then one component per row.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>

#include "batch/list.hpp"
#include "batch/list_detail.hpp"
#include "core/csv_table.hpp"
#include "core/text_parse.hpp"

namespace freestand::batch {

namespace {

std::string trim(const std::string& s) { return std::string(core::text::trim(s)); }

// Column name -> index, from the header row.
std::map<std::string, std::size_t> read_header(const core::CsvRecord& header,
                                               const std::string& file) {
    std::map<std::string, std::size_t> columns;
    for (std::size_t i = 0; i < header.fields.size(); ++i) {
        const std::string name = trim(header.fields[i]);
        const SourceLocation at{file, header.line, name};
        const auto& keys = list_keys();
        if (std::find(keys.begin(), keys.end(), name) == keys.end()) {
            throw InputError(at, fmt::format("unknown column (column {}); allowed columns: {}",
                                             i + 1, fmt::join(keys, ", ")));
        }
        if (!columns.emplace(name, i).second)
            throw InputError(at, fmt::format("column given twice (columns {} and {})",
                                             columns[name] + 1, i + 1));
    }
    if (!columns.count("file")) {
        throw InputError(SourceLocation{file, header.line, "file"},
                         "missing required column (the case file of each row)");
    }
    return columns;
}

std::vector<double> read_levels(const std::string& cell, const SourceLocation& at) {
    std::vector<double> out;
    int item = 0;
    for (const std::string& text : core::text::split(cell, ';')) {
        ++item;
        const std::string token = trim(text);
        const auto v = core::text::parse_number(token);
        if (!v) {
            throw InputError(at, fmt::format("item {} \"{}\" of \"{}\" is not a number; expected "
                                             "levels in g separated by ';', e.g. 0.1;0.2;0.3",
                                             item, token, cell));
        }
        out.push_back(*v);
    }
    return out;
}

long long read_integer(const std::string& cell, const SourceLocation& at) {
    long long v = 0;
    if (!core::text::parse_integer(cell, v))
        throw InputError(at, fmt::format("\"{}\" is not a whole number", cell));
    return v;
}

// One row's entry: the cells of the columns given, empty cells keeping the case's values.
BatchEntry read_row(const core::CsvRecord& row, const std::map<std::string, std::size_t>& columns,
                    const std::string& file) {
    const auto cell = [&](const std::string& key) -> std::string {
        const auto it = columns.find(key);
        return it == columns.end() ? "" : trim(row.fields[it->second]);
    };
    const auto at = [&](const std::string& key) { return SourceLocation{file, row.line, key}; };
    BatchEntry e;
    e.line = row.line;
    const std::string case_file = cell("file");
    if (case_file.empty()) throw InputError(at("file"), "empty: expected the case file of the row");
    e.case_file = detail::resolve_case(case_file, file);
    e.name = cell("name").empty() ? e.case_file.stem().string() : cell("name");
    if (!cell("pga_g").empty()) e.overrides.pga_g = read_levels(cell("pga_g"), at("pga_g"));
    if (!cell("base_material").empty()) e.overrides.base_material = cell("base_material");
    if (!cell("seed").empty()) e.overrides.seed = read_integer(cell("seed"), at("seed"));
    if (!cell("histories_per_level").empty())
        e.overrides.histories_per_level =
            read_integer(cell("histories_per_level"), at("histories_per_level"));
    assess::check_overrides(e.overrides, at);
    return e;
}

}  // namespace

BatchList parse_csv_list(const std::string& text, const std::string& file_label) {
    const std::vector<core::CsvRecord> records = core::parse_csv_table(text, file_label);
    if (records.empty()) {
        throw InputError(SourceLocation{file_label, 0, ""},
                         "empty list: expected a header row naming the columns (file, and any "
                         "of name, pga_g, base_material, seed, histories_per_level)");
    }
    const auto columns = read_header(records[0], file_label);
    BatchList list{file_label, "", {}};
    detail::EntryCollector collect(list);
    for (std::size_t i = 1; i < records.size(); ++i) {
        const core::CsvRecord& row = records[i];
        if (row.fields.size() != records[0].fields.size()) {
            throw InputError(SourceLocation{file_label, row.line, ""},
                             fmt::format("{} field(s); expected {}, one per column of the header",
                                         row.fields.size(), records[0].fields.size()));
        }
        BatchEntry e = read_row(row, columns, file_label);
        const bool named = columns.count("name") && !e.name.empty() &&
                           !trim(row.fields[columns.at("name")]).empty();
        collect.add(std::move(e), SourceLocation{file_label, row.line,
                                                 named ? "name" : "name (the file's stem)"});
    }
    detail::require_entries(list, SourceLocation{file_label, records[0].line, ""},
                            "no components listed below the header");
    return list;
}

}  // namespace freestand::batch
