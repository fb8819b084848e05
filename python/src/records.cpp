// read_record and spectrum.
#include <pybind11/stl.h>

#include "api/spectrum.hpp"
#include "bindings.hpp"
#include "convert.hpp"
#include "core/readers.hpp"

namespace freestand::python {

namespace {

py::dict record_dict(const core::Record& r) {
    py::dict d;
    d["name"] = r.name;
    d["source"] = r.source;
    d["component"] = r.component;
    d["dt_s"] = r.dt_s;
    d["accel_mps2"] = to_numpy(r.accel_mps2);
    return d;
}

}  // namespace

api::FrequencyGrid frequency_grid(const std::optional<std::vector<double>>& frequency_hz,
                                  const std::optional<double>& fmin_hz,
                                  const std::optional<double>& fmax_hz,
                                  const std::optional<double>& per_decade) {
    api::FrequencyGrid grid;
    if (frequency_hz) grid.frequency_hz = *frequency_hz;
    if (fmin_hz) grid.fmin_hz = *fmin_hz;
    if (fmax_hz) grid.fmax_hz = *fmax_hz;
    if (per_decade) grid.per_decade = *per_decade;
    return grid;
}

core::Record make_record(const py::handle& accel_mps2, double dt_s, const std::string& name,
                         const std::string& source, const std::string& component) {
    core::Record r{name, source, component, dt_s, from_numpy(accel_mps2, "accel_mps2")};
    core::validate(r);
    return r;
}

void bind_records(py::module_& m) {
    m.def(
        "read_record",
        [](const std::string& path) {
            core::Record r;
            {
                py::gil_scoped_release unlocked;
                r = core::read_record(path);
            }
            return record_dict(r);
        },
        py::arg("path"));
    m.def(
        "spectrum",
        [](const py::handle& accel_mps2, double dt_s, const std::string& name,
           const std::string& source, const std::string& component,
           const std::vector<double>& dampings,
           const std::optional<std::vector<double>>& frequency_hz,
           const std::optional<double>& fmin_hz, const std::optional<double>& fmax_hz,
           const std::optional<double>& per_decade) {
            api::SpectrumRequest request;
            request.record = make_record(accel_mps2, dt_s, name, source, component);
            request.dampings = dampings;
            request.grid = frequency_grid(frequency_hz, fmin_hz, fmax_hz, per_decade);
            api::json doc;
            {
                py::gil_scoped_release unlocked;
                doc = api::to_json(api::spectrum(request));
            }
            return to_python(doc, Arrays::numpy);
        },
        py::arg("accel_mps2"), py::arg("dt_s"), py::arg("name"), py::arg("source"),
        py::arg("component"), py::arg("dampings"), py::arg("frequency_hz"), py::arg("fmin_hz"),
        py::arg("fmax_hz"), py::arg("per_decade"));
}

}  // namespace freestand::python
