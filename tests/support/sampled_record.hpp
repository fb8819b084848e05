#pragma once
/// A record sampled from a closed-form ground acceleration, for the tests that compare what is
/// computed from a record (measures, spectra, table displacement) with the exact value.
#include <cstddef>

#include "core/record.hpp"

namespace freestand::test {

/// n samples, accel_mps2(t) at t = i dt_s, of a record named "synthetic" from "test".
template <class AccelOfTime>
core::Record sampled_record(double dt_s, std::size_t n, AccelOfTime accel_mps2) {
    core::Record r;
    r.name = "synthetic";
    r.source = "test";
    r.dt_s = dt_s;
    r.accel_mps2.resize(n);
    for (std::size_t i = 0; i < n; ++i) r.accel_mps2[i] = accel_mps2(r.time_s(i));
    return r;
}

}  // namespace freestand::test
