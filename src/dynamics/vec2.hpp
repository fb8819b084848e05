#pragma once
/// Internal: the plane vector of the biaxial slide and of the flexible body's pose, with the
/// few operations their equations use.
#include <array>
#include <cmath>

namespace freestand::dynamics::detail {

using Vec2 = std::array<double, 2>;
inline double dot(const Vec2& a, const Vec2& b) { return a[0] * b[0] + a[1] * b[1]; }
// sqrt rather than hypot: the values are far from overflow, and hypot costs several times more
// in the slide's inner loop.
inline double norm(const Vec2& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1]); }
/// p rotated by the angle whose cosine and sine are c and s.
inline Vec2 rot(double c, double s, const Vec2& p) {
    return {c * p[0] - s * p[1], s * p[0] + c * p[1]};
}
/// v turned a quarter counter-clockwise.
inline Vec2 perp(const Vec2& v) { return {-v[1], v[0]}; }
/// The z component of a x b.
inline double cross(const Vec2& a, const Vec2& b) { return a[0] * b[1] - a[1] * b[0]; }

}  // namespace freestand::dynamics::detail
