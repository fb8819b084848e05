// slide and rock: the commands' documents from their options.
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "cli/documents.hpp"
#include "convert.hpp"

namespace freestand::python {

namespace {

/// A closed-form command as a function of its arguments: its options parsed and checked as the
/// command line does, its computation, and the document `COMMAND --json` prints.
template <typename Run>
void bind_closed_form(py::module_& m, const char* command,
                      cli::po::options_description (*options)(),
                      Run (*run)(const cli::po::variables_map&), cli::json (*to_json)(const Run&)) {
    m.def(
        command,
        [command, options, run, to_json](const std::vector<std::string>& args) {
            const auto vm = cli::parse_document_options(command, options(), args);
            return to_python(to_json(run(vm)), Arrays::lists);
        },
        py::arg("args"));
}

}  // namespace

void bind_documents(py::module_& m) {
    bind_closed_form(m, "slide", cli::slide_options, cli::slide_run, cli::slide_json);
    bind_closed_form(m, "rock", cli::rock_options, cli::rock_run, cli::rock_json);
}

}  // namespace freestand::python
