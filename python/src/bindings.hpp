#pragma once
/// The extension module's functions, by group.
#include <pybind11/pybind11.h>

#include <string>

#include <optional>
#include <vector>

#include "api/spectrum.hpp"
#include "core/record.hpp"

namespace freestand::python {

/// A record of the samples (m/s^2) at dt_s, validated as a file's would be (InputError).
core::Record make_record(const pybind11::handle& accel_mps2, double dt_s, const std::string& name,
                         const std::string& source, const std::string& component);

/// The frequency grid of the optional arguments (api::FrequencyGrid's defaults for those absent).
api::FrequencyGrid frequency_grid(const std::optional<std::vector<double>>& frequency_hz,
                                  const std::optional<double>& fmin_hz,
                                  const std::optional<double>& fmax_hz,
                                  const std::optional<double>& per_decade);

/// read_record, spectrum.
void bind_records(pybind11::module_& m);
/// classify, slide, rock.
void bind_closed_forms(pybind11::module_& m);
/// target, generate.
void bind_motion(pybind11::module_& m);
/// simulate.
void bind_runs(pybind11::module_& m);
/// simulate_3d.
void bind_body3d(pybind11::module_& m);
/// assess.
void bind_case_runs(pybind11::module_& m);
/// fragility.
void bind_fragility(pybind11::module_& m);

}  // namespace freestand::python
