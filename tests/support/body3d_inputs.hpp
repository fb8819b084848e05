#pragma once
/// Inputs the 3D body's tests share: a base acceleration along one plan direction, a sine, and
/// the engine's options at the tests' g.
#include <cmath>
#include <cstddef>
#include <numbers>

#include "dynamics/biaxial.hpp"
#include "dynamics/body3d.hpp"

namespace freestand::test {

inline constexpr double body3d_g_mps2 = 9.81;

/// Samples at dt_s of the base acceleration along plan direction phi_rad with magnitude a(t).
template <class F>
dynamics::BiaxialExcitation along(double phi_rad, double seconds, double dt_s, F a_mps2) {
    dynamics::BiaxialExcitation e;
    e.label = "test";
    e.dt_s = dt_s;
    const auto n = static_cast<std::size_t>(std::lround(seconds / dt_s)) + 1;
    for (std::size_t i = 0; i < n; ++i) {
        const double a = a_mps2(dt_s * static_cast<double>(i));
        e.x_mps2.push_back(a * std::cos(phi_rad));
        e.y_mps2.push_back(a * std::sin(phi_rad));
    }
    return e;
}

/// A g sin(2 pi f t), m/s^2.
inline double sine_mps2(double amplitude_g, double f_hz, double t_s) {
    return amplitude_g * body3d_g_mps2 * std::sin(2.0 * std::numbers::pi * f_hz * t_s);
}

/// The engine's default options with the tests' g and the given tail.
inline dynamics::Body3dOptions body3d_options(double tail_s) {
    dynamics::Body3dOptions o;
    o.tail_s = tail_s;
    o.g_mps2 = body3d_g_mps2;
    return o;
}

}  // namespace freestand::test
