#pragma once
/// A minimal valid case file for the case reader's tests, which add or replace one line at a
/// time, and the message of the InputError a case text raises.
#include <string>

#include "assess/case.hpp"
#include "core/errors.hpp"

namespace freestand::test {

/// [component] of a valid case: lines 1-8 (the next line added is line 9).
inline const std::string box_component = R"([component]
name = "Box"
mass_kg = 100.0
cg_height_m = 1.0
cg_to_edge_x_m = [0.4, 0.5]
cg_to_edge_y_m = [0.3, 0.3]
mu_s = 0.3
allowable_slide_m = 0.05
)";

/// [site] of a valid case: two RG 1.60 levels.
inline const std::string box_site = R"([site]
pga_g = [0.1, 0.2]
)";

/// The InputError's text case_text raises, read as "case.toml", or "no error".
inline std::string case_error(const std::string& case_text) {
    try {
        assess::parse_case(case_text, "case.toml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace freestand::test
