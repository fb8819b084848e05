// target and generate: typed arguments to the requests.
#include <pybind11/stl.h>

#include "api/generate.hpp"
#include "api/target.hpp"
#include "bindings.hpp"
#include "convert.hpp"

namespace freestand::python {

namespace {

/// The design values the package passes as a dict keyed by DesignValues' field names, each a
/// float (pga_g, sds_g, sd1_g, tl_s, ag_g) or a str (type, ground, soil); the package has
/// refused unknown keys and values of the wrong type.
api::DesignValues design_values(const py::dict& values) {
    api::DesignValues v;
    const auto number = [&](const char* key, std::optional<double>& out) {
        if (values.contains(key)) out = values[key].cast<double>();
    };
    const auto text = [&](const char* key, std::optional<std::string>& out) {
        if (values.contains(key)) out = values[key].cast<std::string>();
    };
    number("pga_g", v.pga_g);
    number("sds_g", v.sds_g);
    number("sd1_g", v.sd1_g);
    number("tl_s", v.tl_s);
    number("ag_g", v.ag_g);
    text("type", v.type);
    text("ground", v.ground);
    text("soil", v.soil);
    return v;
}

std::optional<motion::Range> range(const std::optional<std::pair<double, double>>& r) {
    if (!r) return std::nullopt;
    return motion::Range{r->first, r->second};
}

py::list generated_records(const motion::GeneratedSet& set) {
    py::list records;
    for (const motion::GeneratedComponent& c : set.components) {
        py::dict d;
        d["component"] = c.record.component;
        d["dt_s"] = c.record.dt_s;
        d["accel_mps2"] = to_numpy(c.record.accel_mps2);
        records.append(d);
    }
    return records;
}

}  // namespace

void bind_motion(py::module_& m) {
    m.def(
        "target",
        [](const std::string& design, const py::dict& values, const std::vector<double>& dampings,
           bool vertical, const std::optional<std::vector<double>>& frequency_hz,
           const std::optional<double>& fmin_hz, const std::optional<double>& fmax_hz,
           const std::optional<double>& per_decade) {
            api::TargetRequest request;
            request.design = design;
            request.values = design_values(values);
            request.dampings = dampings;
            request.vertical = vertical;
            request.grid = frequency_grid(frequency_hz, fmin_hz, fmax_hz, per_decade);
            return to_python(api::to_json(api::target(request)), Arrays::numpy);
        },
        py::arg("design"), py::arg("values"), py::arg("dampings"), py::arg("vertical"),
        py::arg("frequency_hz"), py::arg("fmin_hz"), py::arg("fmax_hz"), py::arg("per_decade"));
    m.def(
        "generate",
        [](const std::string& target, const py::dict& values, const std::string& target_file,
           const std::string& target_file_10, const std::optional<double>& vertical_ratio,
           const std::vector<std::string>& seed_records,
           const std::vector<std::string>& components, const std::optional<double>& duration_s,
           const std::optional<double>& dt_s, std::uint64_t seed,
           const std::optional<std::pair<double, double>>& va_range_mps_per_g,
           const std::optional<std::pair<double, double>>& adv2_range,
           const std::optional<double>& da_max_m_per_g, bool timing) {
            api::GenerateRequest request;
            request.target = target;
            request.design = design_values(values);
            request.target_file = target_file;
            request.target_file_10 = target_file_10;
            request.vertical_ratio = vertical_ratio;
            request.seed_records.assign(seed_records.begin(), seed_records.end());
            request.components = components;
            request.duration_s = duration_s;
            request.dt_s = dt_s;
            request.seed = seed;
            request.va_range_mps_per_g = range(va_range_mps_per_g);
            request.adv2_range = range(adv2_range);
            request.da_max_m_per_g = da_max_m_per_g;
            request.timing = timing;
            std::optional<api::GenerateResult> result;
            {
                py::gil_scoped_release unlocked;
                result = api::generate(request);
            }
            return py::make_tuple(to_python(api::to_json(*result), Arrays::lists),
                                  generated_records(result->set));
        },
        py::arg("target"), py::arg("values"), py::arg("target_file"), py::arg("target_file_10"),
        py::arg("vertical_ratio"), py::arg("seed_records"), py::arg("components"),
        py::arg("duration_s"), py::arg("dt_s"), py::arg("seed"), py::arg("va_range_mps_per_g"),
        py::arg("adv2_range"), py::arg("da_max_m_per_g"), py::arg("timing"));
}

}  // namespace freestand::python
