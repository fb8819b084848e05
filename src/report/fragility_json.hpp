#pragma once
/// fragility.json and the "fragility" object of result.json, apart from the fragility report's
/// rendering (the Python module returns the JSON only).
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "fragility/fragility.hpp"
#include "report/json.hpp"
#include "report/references.hpp"

namespace freestand::report {

/// {"levels": [{"pga_g", "n", "events": {"overturn": {"k", "p", "ci"}, "slide", "rock",
/// "any"}}], "fit": {"overturn": {"theta_m_g", "beta", "pga_1pct_g", "pga_5pct_g",
/// "pga_50pct_g", "log_likelihood", "chi2", "dof", "p_value"} | null, ...}, "fit_notes",
/// "inputs", "references", "stamp"}; numbers to 10 significant digits.
nlohmann::ordered_json fragility_json(const fragility::Result& r, const Stamp& stamp);

/// fragility_json without the stamp: what an assessment's result.json carries as "fragility".
nlohmann::ordered_json fragility_body_json(const fragility::Result& r);

/// What the event means for the run's inputs ("peak slide above the allowable 50.0 mm").
std::string event_meaning(fragility::Event e, const fragility::Meta& m);
/// What a fragility report and fragility.json cite.
std::vector<Reference> fragility_references();

}  // namespace freestand::report
