// [[unit]] x 2 and [tunnel] of a case file: two units joined by a tunnel (docs/methods.md s.10).
#include "assess/case_detail.hpp"

#include <fmt/format.h>

namespace freestand::assess {

namespace case_detail {

// [[unit]] x 2 and [tunnel] (docs/methods.md s.10), each unit read as a [component].
void read_units(const toml::table& root, const toml::node& units, const std::string& file,
                Case& out, double g_mps2) {
    const toml::array* arr = units.as_array();
    if (arr == nullptr || !arr->is_array_of_tables())
        throw InputError(SourceLocation{file, line_of(units), "unit"},
                         "expected [[unit]] tables (an array of tables)");
    if (root.get("component") != nullptr)
        throw InputError(SourceLocation{file, line_of(*root.get("component")), "component"},
                         "[component] and [[unit]] are exclusive: describe one component, or "
                         "two units joined by a [tunnel]");
    if (arr->size() != 2)
        throw InputError(SourceLocation{file, line_of(arr->back()), "unit"},
                         fmt::format("expected exactly two [[unit]] tables, got {}", arr->size()));
    for (std::size_t i = 0; i < arr->size(); ++i) {
        const std::string name = fmt::format("unit[{}]", i + 1);
        TableReader r((*arr)[i].as_table(), file, name);
        if (r.has("allowable_relative_m"))
            r.fail("allowable_relative_m", "give the relative allowable once, in [tunnel]");
        out.units.push_back(read_component(r, out.assumptions, g_mps2));
    }
    const toml::table* tunnel = subtable(root, "tunnel", file);
    if (tunnel == nullptr)
        throw InputError(SourceLocation{file, 0, "tunnel"},
                         "missing required table [tunnel] (height_m, allowable_relative_m) for "
                         "the two [[unit]] tables");
    TableReader rt(tunnel, file, "tunnel");
    Tunnel t;
    t.height_m = rt.required_number("height_m", Range{0.0, 100.0});
    t.allowable_relative_m =
        rt.required_number("allowable_relative_m", Range{0.0, 10.0, false, true});
    rt.finish({"height_m", "allowable_relative_m"});
    out.tunnel = t;
}

}  // namespace case_detail

}  // namespace freestand::assess
