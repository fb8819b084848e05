// The case document: its tables and their order, the line-length limit, the batch list's
// overrides written in before it is read (case.hpp).
#include "assess/case_detail.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "assess/materials.hpp"
#include "assess/overrides.hpp"
#include "core/file_io.hpp"
#include "core/limits.hpp"

namespace freestand::assess {

namespace {

// Lines beyond core::limits::max_case_line_chars are refused before toml++ sees them.
void check_line_lengths(const std::string& text, const std::string& file_label) {
    int line = 1;
    for (std::size_t start = 0; start <= text.size(); ++line) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        if (end - start > core::limits::max_case_line_chars) {
            throw InputError(SourceLocation{file_label, line, ""},
                             fmt::format("line is {} characters long; a case file's lines are "
                                         "limited to {} (README, Limits)",
                                         end - start, core::limits::max_case_line_chars));
        }
        start = end + 1;
    }
}

}  // namespace

using case_detail::line_of;
using case_detail::read_component;
using case_detail::read_gravity_mps2;
using case_detail::read_options;
using case_detail::read_site;
using case_detail::read_uncertainty;
using case_detail::read_units;
using case_detail::subtable;

Case with_base_material(Case c, const std::string& material) {
    const Material* m = find_material(material);
    if (m == nullptr) throw std::invalid_argument("with_base_material: unknown " + material);
    // A case's own bounds for its own base stay (docs/methods.md s.6 step 7).
    const Material* own = find_material(c.component.base.material);
    if (own != m) c.component.base = material_contact(*m);
    return c;
}


Case parse_case(const std::string& text, const std::string& file_label) {
    return parse_case(text, file_label, CaseOverrides{});
}

Case parse_case(const std::string& text, const std::string& file_label,
                const CaseOverrides& overrides) {
    check_line_lengths(text, file_label);
    toml::table root = parse_toml(text, file_label);
    apply_overrides(root, overrides);
    Case out;
    out.file = file_label;
    for (const auto& [k, node] : root) {
        const std::string key(k.str());
        if (key != "component" && key != "site" && key != "options" && key != "uncertainty" &&
            key != "unit" && key != "tunnel") {
            throw InputError(
                SourceLocation{file_label, static_cast<int>(node.source().begin.line), key},
                "unknown table; allowed tables: [component] (or two [[unit]] and a [tunnel]), "
                "[site], [options], [uncertainty]");
        }
    }
    const toml::table* comp = subtable(root, "component", file_label);
    const toml::table* site = subtable(root, "site", file_label);
    // The components' p_radps needs the case's gravity, which [site] holds.
    TableReader gravity_reader(site, file_label, "site");
    const double g_mps2 = read_gravity_mps2(gravity_reader);
    if (const toml::node* units = root.get("unit")) {
        read_units(root, *units, file_label, out, g_mps2);
    } else if (const toml::node* tunnel = root.get("tunnel")) {
        throw InputError(SourceLocation{file_label, line_of(*tunnel), "tunnel"},
                         "[tunnel] joins two [[unit]] tables; a [component] has none (a braced "
                         "pair is one component: give allowable_relative_m there)");
    } else if (comp == nullptr) {
        throw InputError(SourceLocation{file_label, 0, "component"},
                         "missing required table [component] (or two [[unit]] and a [tunnel])");
    }
    if (site == nullptr)
        throw InputError(SourceLocation{file_label, 0, "site"}, "missing required table [site]");
    if (out.units.empty()) {
        TableReader rc(comp, file_label, "component");
        out.component = read_component(rc, out.assumptions, g_mps2);
    }
    TableReader rs(site, file_label, "site");
    out.site = read_site(rs, out.assumptions, std::filesystem::path(file_label).parent_path());
    if (out.site.dbe_pga_g && !out.units.empty())
        rs.fail("dbe_pga_g",
                "the performance goal runs the fragility engine, which takes one "
                "component, not two [[unit]] tables");
    TableReader ro(subtable(root, "options", file_label), file_label, "options");
    out.options = read_options(ro, std::filesystem::path(file_label).parent_path());
    TableReader ru(subtable(root, "uncertainty", file_label), file_label, "uncertainty");
    out.uncertainty = read_uncertainty(ru, file_label);
    return out;
}

Case read_case(const std::filesystem::path& path) {
    return parse_case(core::read_input_file(path), path.string());
}

namespace case_detail {

const toml::table* subtable(const toml::table& root, const std::string& name,
                            const std::string& file) {
    const toml::node* n = root.get(name);
    if (n == nullptr) return nullptr;
    if (!n->is_table()) {
        throw InputError(SourceLocation{file, static_cast<int>(n->source().begin.line), name},
                         "expected a table [" + name + "]");
    }
    return n->as_table();
}


int line_of(const toml::node& n) { return static_cast<int>(n.source().begin.line); }

}  // namespace case_detail

}  // namespace freestand::assess
