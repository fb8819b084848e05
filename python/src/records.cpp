// read_record and spectrum.
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "cli/documents.hpp"
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
           const std::vector<std::string>& args) {
            const core::Record r = make_record(accel_mps2, dt_s, name, source, component);
            const auto vm = cli::parse_document_options("spectrum", cli::spectrum_grid_options(), args);
            nlohmann::ordered_json doc;
            {
                py::gil_scoped_release unlocked;
                doc = cli::spectrum_document(r, vm);
            }
            return to_python(doc, Arrays::numpy);
        },
        py::arg("accel_mps2"), py::arg("dt_s"), py::arg("name"), py::arg("source"),
        py::arg("component"), py::arg("args"));
}

}  // namespace freestand::python
