#include "convert.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "core/errors.hpp"

namespace freestand::python {

namespace {

bool all_numbers(const nlohmann::ordered_json& array) {
    return !array.empty() && std::all_of(array.begin(), array.end(), [](const auto& v) {
        return v.is_number();
    });
}

}  // namespace

py::object to_python(const nlohmann::ordered_json& j, Arrays arrays) {
    switch (j.type()) {
    case nlohmann::ordered_json::value_t::null: return py::none();
    case nlohmann::ordered_json::value_t::boolean: return py::bool_(j.get<bool>());
    case nlohmann::ordered_json::value_t::number_integer: return py::int_(j.get<std::int64_t>());
    case nlohmann::ordered_json::value_t::number_unsigned: return py::int_(j.get<std::uint64_t>());
    case nlohmann::ordered_json::value_t::number_float: return py::float_(j.get<double>());
    case nlohmann::ordered_json::value_t::string: return py::str(j.get_ref<const std::string&>());
    case nlohmann::ordered_json::value_t::array: {
        if (arrays == Arrays::numpy && all_numbers(j)) {
            std::vector<double> values;
            values.reserve(j.size());
            for (const auto& v : j) values.push_back(v.get<double>());
            return to_numpy(values);
        }
        py::list out;
        for (const auto& v : j) out.append(to_python(v, arrays));
        return out;
    }
    case nlohmann::ordered_json::value_t::object: {
        py::dict out;
        for (const auto& [key, value] : j.items()) out[py::str(key)] = to_python(value, arrays);
        return out;
    }
    default: throw std::logic_error("to_python: a JSON value of an unexpected type");
    }
}

py::array_t<double> to_numpy(const std::vector<double>& values) {
    py::array_t<double> out(static_cast<py::ssize_t>(values.size()));
    std::copy(values.begin(), values.end(), out.mutable_data());
    return out;
}

std::vector<double> from_numpy(const py::handle& values, const std::string& what) {
    // ensure() leaves a Python error where it cannot make an array: that is the same bad input
    // as a 2-D array, so it is reported the same way.
    const SourceLocation where{"", 0, what};
    const std::string expected = "expected a one-dimensional array of real numbers";
    const py::array given = py::array::ensure(values);
    if (!given) PyErr_Clear();
    if (!given || given.ndim() != 1) throw InputError(where, expected);
    // Integers and floats only: the cast to double would drop a complex sample's imaginary part
    // with no more than a NumPy warning, and read bools and numeric text as numbers.
    const char kind = given.dtype().kind();
    if (kind != 'i' && kind != 'u' && kind != 'f')
        throw InputError(where, fmt::format("{}, got an array of {}", expected,
                                            py::str(given.dtype()).cast<std::string>()));
    const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(given);
    if (!a) throw py::error_already_set();
    return {a.data(), a.data() + a.size()};
}

std::optional<double> optional_number(const py::dict& d, const char* key) {
    if (!d.contains(key) || d[key].is_none()) return std::nullopt;
    return d[key].cast<double>();
}

sliding::BoxSpec box_spec(const py::dict& box) {
    sliding::BoxSpec s;
    s.half_width_m = box["half_width_m"].cast<double>();
    s.half_height_m = box["half_height_m"].cast<double>();
    s.mass_kg = optional_number(box, "mass_kg");
    s.cg_offset_m = optional_number(box, "cg_offset_m");
    s.cg_height_m = optional_number(box, "cg_height_m");
    s.inertia_cg_kgm2 = optional_number(box, "inertia_cg_kgm2");
    return s;
}

}  // namespace freestand::python
