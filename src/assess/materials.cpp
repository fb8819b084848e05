#include "assess/materials.hpp"

#include "assess/case.hpp"

#include <algorithm>
#include <cctype>

namespace freestand::assess {

const std::vector<Material>& materials() {
    // docs/methods.md s.7: the thesis's measurements (Saraswat 2017) and the literature ranges
    // it quotes beside them, which are the friction bounds; PVC has no published range.
    const char* const literature = "literature range quoted by Saraswat 2017 (docs/methods.md s.7)";
    static const std::vector<Material> table{
        {"plywood", 0.15, {0.1, 0.3}, literature, 0.94},
        {"PVC sheet on concrete", 0.15, {0.12, 0.18},
         "0.8-1.2 x the measured 0.15: no range published (docs/methods.md s.7)", std::nullopt},
        {"HDPE", 0.32, {0.2, 0.4}, literature, 0.95},
        {"aluminium", 0.48, {0.3, 0.5}, literature, 0.97},
        {"steel", 0.72, {0.7, 0.8}, literature, 0.98},
    };
    return table;
}

namespace {
std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}
}  // namespace

const Material* find_material(const std::string& name) {
    const std::string key = lower(name);
    for (const Material& m : materials()) {
        if (lower(m.name) == key) return &m;
    }
    return nullptr;
}

BaseContact material_contact(const Material& m) {
    BaseContact b;
    b.material = m.name;
    b.mu_s = m.mu_s;
    b.mu_k = m.mu_s;
    b.restitution = m.restitution;
    b.source = "material table (docs/methods.md s.7; Saraswat 2017)";
    b.mu_s_range = m.mu_s_range;
    b.mu_s_range_source = m.range_source;
    return b;
}

std::string material_names() {
    std::string out;
    for (const Material& m : materials()) {
        if (!out.empty()) out += ", ";
        out += "\"" + m.name + "\"";
    }
    return out;
}

}  // namespace freestand::assess
