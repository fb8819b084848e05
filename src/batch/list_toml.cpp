// TOML lists (list.hpp): [[case]] tables, read with the case files' TableReader so errors name
// list:line and case.<key> as a case file's do.
#include <fmt/format.h>

#include "assess/toml_reader_detail.hpp"
#include "core/limits.hpp"
#include "batch/list.hpp"
#include "batch/list_detail.hpp"

namespace freestand::batch {

namespace {

int line_of(const toml::node& n) { return static_cast<int>(n.source().begin.line); }

BatchEntry read_case_table(const toml::table& t, const std::string& file) {
    assess::TableReader r(&t, file, "case");
    BatchEntry e;
    e.line = line_of(t);
    e.case_file = detail::resolve_case(r.required_string("file"), file);
    e.name = r.string("name").value_or(e.case_file.stem().string());
    assess::CaseOverrides& o = e.overrides;
    o.pga_g = r.numbers("pga_g", core::limits::pga_level_g);
    o.base_material = r.string("base_material");
    o.seed = r.integer("seed", 0, assess::max_seed);
    o.histories_per_level =
        r.integer("histories_per_level", 1, assess::histories_limit);
    r.finish(list_keys());
    assess::check_overrides(o, [&](const std::string& key) { return r.where(key); });
    return e;
}

// The one array of [[case]] tables the list holds.
const toml::array& case_tables(const toml::table& root, const std::string& file) {
    for (const auto& [k, node] : root) {
        const std::string key(k.str());
        if (key == "case") continue;
        const bool case_file = key == "component" || key == "site" || key == "options";
        throw InputError(SourceLocation{file, line_of(node), key},
                         fmt::format("unknown key; a batch list holds [[case]] tables{}",
                                     case_file ? " (this looks like a case file: assess it on its "
                                                 "own, or list it in a [[case]] table's file)"
                                               : ""));
    }
    const toml::node* cases = root.get("case");
    const toml::array* arr = cases ? cases->as_array() : nullptr;
    if (cases == nullptr || arr == nullptr || !arr->is_array_of_tables()) {
        throw InputError(SourceLocation{file, cases ? line_of(*cases) : 0, "case"},
                         cases ? "expected [[case]] tables (an array of tables)"
                               : "no [[case]] tables: expected one per component, each with "
                                 "file and any of name, pga_g, base_material, seed, "
                                 "histories_per_level");
    }
    return *arr;
}

}  // namespace

BatchList parse_toml_list(const std::string& text, const std::string& file_label) {
    const toml::table root = assess::parse_toml(text, file_label);
    const toml::array& tables = case_tables(root, file_label);
    BatchList list{file_label, "", {}};
    detail::EntryCollector collect(list);
    for (const toml::node& node : tables) {
        const toml::table& t = *node.as_table();
        BatchEntry e = read_case_table(t, file_label);
        const toml::node* name = t.get("name");
        const SourceLocation at{file_label, name ? line_of(*name) : line_of(t),
                                name ? "case.name" : "case.name (the file's stem)"};
        collect.add(std::move(e), at);
    }
    detail::require_entries(list, SourceLocation{file_label, 0, "case"}, "no [[case]] tables");
    return list;
}

}  // namespace freestand::batch
