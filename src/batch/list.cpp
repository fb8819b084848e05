#include "batch/list.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "batch/list_detail.hpp"
#include "core/file_io.hpp"
#include "core/printable.hpp"
#include "core/sha256.hpp"
#include "report/summary.hpp"

namespace freestand::batch {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t max_name_chars = 100;

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

bool name_char(char c) {
    const auto u = static_cast<unsigned char>(c);
    return std::isalnum(u) || c == '.' || c == '_' || c == '-' || c == '+';
}

std::string location_text(const SourceLocation& where) {
    return where.line > 0 ? fmt::format("{}:{}", where.file, where.line) : where.file;
}

BatchList read_folder(const fs::path& dir) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir)) {
        const std::string file_name = e.path().filename().string();
        if (e.is_regular_file() && e.path().extension() == ".toml" && file_name[0] != '.')
            files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    BatchList list{dir.string(), "", {}};
    detail::EntryCollector collect(list);
    for (const fs::path& f : files) {
        BatchEntry e;
        e.name = f.stem().string();
        e.case_file = f;
        collect.add(std::move(e), SourceLocation{f.string(), 0, "name (the file's stem)"});
    }
    detail::require_entries(list, SourceLocation{dir.string(), 0, ""},
                            "holds no case files (*.toml)");
    return list;
}

}  // namespace

const std::vector<std::string>& list_keys() {
    static const std::vector<std::string> keys{"file",          "name", "pga_g",
                                               "base_material", "seed", "histories_per_level"};
    return keys;
}

void check_name(const std::string& name, const SourceLocation& where) {
    const bool ok = !name.empty() && name.size() <= max_name_chars &&
                    std::isalnum(static_cast<unsigned char>(name[0])) &&
                    std::all_of(name.begin(), name.end(), name_char);
    if (!ok) {
        // Quoted on one line: the name's line breaks and bidirectional overrides are shown.
        throw InputError(where, fmt::format("\"{}\" cannot name a report folder: use 1-{} letters, "
                                            "digits, '.', '_', '-' or '+', starting with a "
                                            "letter or digit",
                                            core::printable_name(name), max_name_chars));
    }
    for (const std::string& s : report::summary_file_names()) {
        if (lower(name) == s)
            throw InputError(where, fmt::format("\"{}\" is the name of a summary file; choose "
                                                "another name",
                                                name));
    }
}

namespace detail {

void EntryCollector::add(BatchEntry entry, const SourceLocation& name_at) {
    check_name(entry.name, name_at);
    const auto [it, fresh] = seen_.emplace(lower(entry.name), location_text(name_at));
    if (!fresh) {
        throw InputError(name_at, fmt::format("duplicate name \"{}\" (also {}); names must "
                                              "differ, ignoring case: each names a report folder",
                                              entry.name, it->second));
    }
    list_.entries.push_back(std::move(entry));
}

fs::path resolve_case(const std::string& given, const std::string& list_label) {
    const fs::path p(given);
    return p.is_absolute() ? p : fs::path(list_label).parent_path() / p;
}

void require_entries(const BatchList& list, const SourceLocation& where,
                     const std::string& what) {
    if (list.entries.empty()) throw InputError(where, what);
}

}  // namespace detail

BatchList read_batch_list(const fs::path& list) {
    const fs::file_status st = fs::status(list);
    if (st.type() == fs::file_type::not_found) throw IoError(list.string() + ": no such file or folder");
    if (fs::is_directory(st)) return read_folder(list);
    const std::string ext = lower(list.extension().string());
    if (ext != ".csv" && ext != ".toml") {
        throw InputError(SourceLocation{list.string(), 0, "list"},
                         fmt::format("a list is a folder of case files, a .csv or a .toml file; "
                                     "got \"{}\"",
                                     list.extension().string()));
    }
    const std::string text = core::read_input_file(list);
    BatchList out = ext == ".csv" ? parse_csv_list(text, list.string())
                                  : parse_toml_list(text, list.string());
    out.sha256 = core::sha256_hex(text);
    return out;
}

}  // namespace freestand::batch
