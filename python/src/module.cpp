// The `freestand._freestand` extension module: the library's commands as functions, their
// errors as Python exceptions. python/freestand/__init__.py is the documented API on top.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "api/build_commit.hpp"
#include "core/errors.hpp"
#include "core/units.hpp"
#include "core/version.hpp"
#include "parameter_names.hpp"

namespace py = pybind11;

namespace {

/// Python classes for the exit-code classes (README "Exit codes"): freestand.Error and one
/// subclass per class, each with the exit code the command line would return. Borrowed
/// handles: the module's attributes own the classes, so nothing is released after the
/// interpreter has shut down.
struct ErrorClasses {
    py::handle base, usage, input, numerical, io;
};

py::handle make_class(py::module_& m, const char* name, py::handle base, int exit_code,
                      const char* doc) {
    py::object cls = py::reinterpret_steal<py::object>(
        PyErr_NewExceptionWithDoc((std::string("freestand.") + name).c_str(), doc, base.ptr(),
                                  nullptr));
    if (!cls) throw py::error_already_set();
    cls.attr("exit_code") = exit_code;
    m.attr(name) = cls;  // the module's reference keeps the class alive
    return cls;
}

}  // namespace

PYBIND11_MODULE(_freestand, m) {
    m.doc() = "freestand's C++ library (see the freestand package for the documented API)";
    static ErrorClasses errors;
    errors.base = make_class(m, "Error", PyExc_Exception, 1, "Base of every freestand error.");
    // Raised by the package for arguments that exclude or need each other (the library never
    // raises it): also a TypeError, as a bad combination of arguments is in Python.
    const py::tuple usage_bases = py::make_tuple(errors.base, py::handle(PyExc_TypeError));
    errors.usage = make_class(m, "UsageError", usage_bases, 2,
                              "Arguments that exclude or need each other (exit code 2 on the "
                              "command line); also a TypeError.");
    // Also a ValueError: a value out of its range is what Python callers catch as one.
    const py::tuple input_bases = py::make_tuple(errors.base, py::handle(PyExc_ValueError));
    errors.input = make_class(m, "InputError", input_bases, 3,
                              "Bad input data or value (exit code 3); also a ValueError.");
    errors.numerical = make_class(m, "NumericalError", errors.base, 4,
                                  "A solver could not reach its tolerance or limit (exit code 4).");
    errors.io = make_class(m, "IoError", errors.base, 5,
                           "A file could not be read or written (exit code 5).");
    py::register_exception_translator([](std::exception_ptr p) {
        using namespace freestand;
        try {
            if (p) std::rethrow_exception(p);
        } catch (const InputError& e) {
            // A request field is renamed to the keyword the caller typed.
            PyErr_SetString(errors.input.ptr(), freestand::python::in_python(e).what());
        } catch (const NumericalError& e) {
            PyErr_SetString(errors.numerical.ptr(), e.what());
        } catch (const IoError& e) {
            PyErr_SetString(errors.io.ptr(), e.what());
        } catch (const Error& e) {
            PyErr_SetString(errors.base.ptr(), e.what());
        }
    });
    m.attr("version") = freestand::core::version();
    m.attr("g_mps2") = freestand::units::g_mps2;
    m.attr("commit") = freestand::api::build_commit;
    freestand::python::bind_records(m);
    freestand::python::bind_closed_forms(m);
    freestand::python::bind_motion(m);
    freestand::python::bind_runs(m);
    freestand::python::bind_body3d(m);
    freestand::python::bind_case_runs(m);
    freestand::python::bind_fragility(m);
}
