#pragma once
/// Base materials of docs/methods.md s.7 (static friction on steel; restitution measured on
/// steel specimens, absent where the table gives none).
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace freestand::assess {

struct Material {
    std::string name;
    double mu_s;                        ///< the thesis's single measurement
    std::array<double, 2> mu_s_range;   ///< default friction bounds (docs/methods.md s.7)
    std::string range_source;           ///< where the bounds come from
    std::optional<double> restitution;  ///< measured on small steel specimens
};

/// The library in the table's order (weakest friction first).
const std::vector<Material>& materials();

/// Looks a material up by name, ignoring case; nullptr when unknown.
const Material* find_material(const std::string& name);

struct BaseContact;

/// The base contact of a case naming only `base_material = m`: tabulated mu_s, mu_k = mu_s,
/// tabulated restitution (absent: Housner's), the literature range as friction bounds
/// (docs/methods.md s.7).
BaseContact material_contact(const Material& m);

/// Names joined with ", " for error messages.
std::string material_names();

}  // namespace freestand::assess
