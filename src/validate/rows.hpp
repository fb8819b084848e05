#pragma once
/// Helpers the row builders share: numeric comparison rows and number formatting.
#include <string>

#include "validate/validate.hpp"

namespace freestand::validate {

/// A numeric comparison: sets thesis_value, predicted_value, unit, difference (absolute and
/// relative, e.g. "+0.1 mm (+0.2%)") and agreement: agrees when |predicted - thesis| <= abs_tol
/// or <= rel_tol |thesis|.
void compare_numbers(Row& row, double thesis_value, double predicted_value,
                     const std::string& unit, double abs_tol, double rel_tol);

/// "0.283" style: n significant digits, no exponent for the magnitudes used here.
std::string sig(double v, int digits = 3);

}  // namespace freestand::validate
