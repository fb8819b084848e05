#pragma once
/// A uniformly sampled acceleration history, stored in SI units.
#include <cstddef>
#include <string>
#include <vector>

namespace freestand::core {

/// Ground acceleration sampled at a uniform step. Sample i is at time i * dt_s.
struct Record {
    std::string name;       ///< short name, e.g. the file stem
    std::string source;     ///< provenance: path, or how it was generated
    std::string component;  ///< component label: "h1", "h2", "v", or the file's own label
    double dt_s = 0.0;      ///< time step, s (> 0)
    std::vector<double> accel_mps2;  ///< acceleration, m/s^2

    std::size_t size() const { return accel_mps2.size(); }
    /// Time of the last sample, s.
    double duration_s() const {
        return accel_mps2.empty() ? 0.0 : dt_s * static_cast<double>(accel_mps2.size() - 1);
    }
    double time_s(std::size_t i) const { return dt_s * static_cast<double>(i); }
};

/// Throws InputError if dt is not positive or any sample is not finite or the record is empty.
void validate(const Record& record);

}  // namespace freestand::core
