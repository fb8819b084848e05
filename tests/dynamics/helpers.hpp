#pragma once
// Shared builders for the dynamics tests.
#include <cmath>
#include <vector>

#include "support/paths.hpp"
#include "core/readers.hpp"
#include "dynamics/simulate.hpp"

namespace freestand::test {

inline dynamics::Excitation samples(double dt_s, std::vector<double> ax_mps2,
                                    std::vector<double> ay_mps2 = {}) {
    dynamics::Excitation e;
    e.label = "test";
    e.dt_s = dt_s;
    e.horizontal_mps2 = std::move(ax_mps2);
    e.vertical_mps2 = std::move(ay_mps2);
    return e;
}

inline dynamics::Options opts(dynamics::Integrator i = dynamics::Integrator::event,
                              double cd_dt_s = 1e-4) {
    dynamics::Options o;
    o.integrator = i;
    o.cd_dt_s = cd_dt_s;
    return o;
}

inline core::Record elcentro() {
    return core::read_at2(freestand::test::data_dir() + "/RSN175_IMPVALL.H_H-E12140.AT2");
}

/// Record scaled to a peak ground acceleration (g).
inline dynamics::Excitation scaled_to(const core::Record& r, double pga_g) {
    double peak = 0.0;
    for (double a : r.accel_mps2) peak = std::max(peak, std::abs(a));
    return dynamics::excitation_from_record(r, pga_g * 9.81 / peak);
}

}  // namespace freestand::test
