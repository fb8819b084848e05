// classify (and, as they move onto api/, slide and rock): typed arguments to the request.
#include <pybind11/stl.h>

#include "api/classify.hpp"
#include "bindings.hpp"
#include "convert.hpp"

namespace freestand::python {

void bind_closed_forms(py::module_& m) {
    m.def(
        "classify",
        [](const py::dict& box, double mu_s, double a_h_g, double av_g) {
            const api::ClassifyRequest request{box_spec(box), mu_s, a_h_g, av_g};
            return to_python(api::to_json(api::classify(request)), Arrays::lists);
        },
        py::arg("box"), py::arg("mu_s"), py::arg("a_h_g"), py::arg("av_g"));
}

}  // namespace freestand::python
