#pragma once
/// Physical constants and unit conversions. Everything inside freestand is SI; conversions
/// happen once, where input is read or output written (docs/methods.md, Conventions).
#include <numbers>

namespace freestand::units {

/// The thesis's gravity, m/s^2: standard gravity (9.80665 m/s^2) rounded to 9.81, as the
/// thesis's arithmetic and the published results it is validated against use it
/// (docs/methods.md, Conventions). Not standard gravity: the one place this value is written.
inline constexpr double g_thesis_mps2 = 9.81;
/// Default gravity, m/s^2: the thesis's value. A case sets its own (site.g_mps2), which is both
/// the gravity of its physics and the size of the unit "g" of its inputs and outputs; library
/// functions that use gravity take it as a parameter defaulting to this (docs/methods.md,
/// Conventions).
inline constexpr double g_mps2 = g_thesis_mps2;
inline constexpr double pi = std::numbers::pi;
inline constexpr double two_pi = 2.0 * std::numbers::pi;
inline constexpr double cm_to_m = 0.01;
inline constexpr double inch_to_m = 0.0254;

/// Converts between g and m/s^2 with the unit g of size unit_g_mps2.
constexpr double g_to_mps2(double a_g, double unit_g_mps2 = g_mps2) { return a_g * unit_g_mps2; }
constexpr double mps2_to_g(double a_mps2, double unit_g_mps2 = g_mps2) {
    return a_mps2 / unit_g_mps2;
}
constexpr double hz_to_radps(double f_hz) { return two_pi * f_hz; }

}  // namespace freestand::units
