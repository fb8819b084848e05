#pragma once
/// Physical constants and unit conversions. Everything inside freestand is SI; conversions
/// happen once, where input is read or output written (docs/methods.md, Conventions).
#include <numbers>

namespace freestand::units {

/// The thesis's gravity, m/s^2: standard gravity (9.80665 m/s^2) rounded to 9.81, as the
/// thesis's arithmetic and the published results it is validated against use it
/// (docs/methods.md, Conventions). Not standard gravity: the one place this value is written.
inline constexpr double g_thesis_mps2 = 9.81;
/// Gravity of every computation, and the size of the unit "g" in inputs and outputs, m/s^2: the
/// thesis's value (docs/methods.md, Conventions; not a case parameter).
inline constexpr double g_mps2 = g_thesis_mps2;
inline constexpr double pi = std::numbers::pi;
inline constexpr double two_pi = 2.0 * std::numbers::pi;
inline constexpr double cm_to_m = 0.01;
inline constexpr double inch_to_m = 0.0254;

constexpr double g_to_mps2(double a_g) { return a_g * g_mps2; }
constexpr double mps2_to_g(double a_mps2) { return a_mps2 / g_mps2; }
constexpr double hz_to_radps(double f_hz) { return two_pi * f_hz; }

}  // namespace freestand::units
