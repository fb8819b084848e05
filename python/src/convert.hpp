#pragma once
/// Between the library's values and Python's: JSON documents to dicts, sample vectors to and
/// from NumPy arrays.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "sliding/block_spec.hpp"

namespace freestand::python {

namespace py = pybind11;

/// How a document's arrays of numbers come out in Python.
enum class Arrays { lists, numpy };

/// The document as Python objects: objects as dicts (in the document's key order), strings,
/// bools, None, ints and floats (the same doubles); arrays of numbers as float64 NumPy arrays
/// with Arrays::numpy, as lists otherwise.
py::object to_python(const nlohmann::ordered_json& j, Arrays arrays);

/// A copy of the samples as a 1-D float64 array.
py::array_t<double> to_numpy(const std::vector<double>& values);

/// The samples of a 1-D array-like of numbers (a NumPy array or a sequence), as doubles;
/// InputError naming `what` if it is not one-dimensional.
std::vector<double> from_numpy(const py::handle& values, const std::string& what);

/// The number d[key], or nullopt when the key is absent or None. The package has checked each
/// value is a real number.
std::optional<double> optional_number(const py::dict& d, const char* key);

/// The box the package passes as a dict with BoxSpec's field names (half_width_m and
/// half_height_m; mass_kg, cg_offset_m, cg_height_m and inertia_cg_kgm2 when given). The package
/// has checked each value is a real number.
sliding::BoxSpec box_spec(const py::dict& box);

}  // namespace freestand::python
