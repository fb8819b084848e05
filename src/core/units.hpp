#pragma once
/// Physical constants and unit conversions. Everything inside freestand is SI; conversions
/// happen once, where input is read or output written (docs/methods.md, Conventions).
#include <numbers>

namespace freestand::units {

/// Standard gravity used throughout, m/s^2 (docs/methods.md, Conventions: not a case parameter).
inline constexpr double g_mps2 = 9.81;
inline constexpr double pi = std::numbers::pi;
inline constexpr double two_pi = 2.0 * std::numbers::pi;
inline constexpr double cm_to_m = 0.01;
inline constexpr double inch_to_m = 0.0254;

constexpr double g_to_mps2(double a_g) { return a_g * g_mps2; }
constexpr double mps2_to_g(double a_mps2) { return a_mps2 / g_mps2; }
constexpr double hz_to_radps(double f_hz) { return two_pi * f_hz; }

}  // namespace freestand::units
