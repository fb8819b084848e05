#pragma once
/// The assessment pipeline (docs/methods.md s.6; model only what the scene needs):
/// per PGA level and direction, classify; stop at rest; else closed-form sliding and rocking;
/// generate histories and simulate only where the closed forms leave the verdict open; then the
/// base-material search and the overall verdict.
#include <vector>

#include "assess/case.hpp"
#include "assess/result.hpp"
#include "assess/run_settings.hpp"

namespace freestand::assess {

/// Runs the whole assessment of a case. Deterministic: the same case gives the same result,
/// whatever run's threads and cache. Throws InputError for bad seed records, NumericalError if
/// a stage fails to converge.
AssessmentResult assess(const Case& c, const RunSettings& run = {});

/// The base-material search of docs/methods.md s.6 step 7 on its own: every material of the table
/// assessed as assess() assesses a case naming it (used by assess() when the case's own base
/// fails, and by tests for every case).
Upgrade search_materials(const Case& c, const RunSettings& run = {});

/// Returns the case with its PGA levels replaced (the command line's --pga). Levels must be as
/// core::limits::require_pga_levels takes them (1 to 1000, in [0.001, 3] g, strictly
/// increasing), with a vertical PGA below 1 g, and as many as the case's
/// energy_table_displacement_m: InputError with field "pga_levels" otherwise.
Case with_pga_levels(Case c, const std::vector<double>& pga_g);

}  // namespace freestand::assess
