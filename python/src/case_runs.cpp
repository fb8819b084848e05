// assess: a case file to its result.json document, as a dict.
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "api/assess.hpp"
#include "bindings.hpp"
#include "api/build_commit.hpp"
#include "convert.hpp"

namespace freestand::python {

void bind_case_runs(py::module_& m) {
    m.def(
        "assess",
        [](const std::string& case_file, const std::optional<std::vector<double>>& pga_g) {
            api::AssessRequest request;
            request.case_file = case_file;
            request.pga_g = pga_g;
            request.commit = api::build_commit;
            api::json document;
            {
                py::gil_scoped_release unlocked;
                document = api::to_json(api::assess(request));
            }
            return to_python(document, Arrays::lists);
        },
        py::arg("case_file"), py::arg("pga_g"));
}

}  // namespace freestand::python
