// target and generate: the commands' documents from their options.
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "cli/documents.hpp"
#include "convert.hpp"

namespace freestand::python {

void bind_documents(py::module_& m) {
    m.def(
        "target",
        [](const std::vector<std::string>& args) {
            const auto vm = cli::parse_document_options("target", cli::target_options(), args);
            return to_python(cli::target_document(vm, cli::target_spectra(vm)), Arrays::numpy);
        },
        py::arg("args"));
    m.def(
        "generate",
        [](const std::vector<std::string>& args, bool timing) {
            const auto vm = cli::parse_document_options("generate", cli::generate_options(), args);
            const cli::GenerateRequest request = cli::generate_request(vm);
            motion::GeneratedSet set;
            {
                py::gil_scoped_release unlocked;
                set = motion::generate_set(request.targets, request.options);
            }
            py::list records;
            for (const motion::GeneratedComponent& c : set.components) {
                py::dict d;
                d["component"] = c.record.component;
                d["dt_s"] = c.record.dt_s;
                d["accel_mps2"] = to_numpy(c.record.accel_mps2);
                records.append(d);
            }
            return py::make_tuple(
                to_python(cli::match_document(request.targets, set, timing), Arrays::lists),
                records);
        },
        py::arg("args"), py::arg("timing"));
}

}  // namespace freestand::python
