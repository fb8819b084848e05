// simulate_3d: the rigid body in three dimensions (docs/methods.md s.11).
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <optional>

#include "api/simulate.hpp"
#include "bindings.hpp"
#include "convert.hpp"
#include "core/errors.hpp"

namespace freestand::python {

namespace {

/// One NumPy array per series column (dynamics::Body3dSample), the state as its code; the
/// modal displacements with a mode.
py::dict body3d_series(const std::vector<dynamics::Body3dSample>& series, bool with_mode) {
    const auto n = static_cast<py::ssize_t>(series.size());
    py::array_t<double> t(n), ux(n), uy(n), tilt(n), ratio(n), twist(n);
    py::array_t<std::int8_t> state(n);
    for (py::ssize_t i = 0; i < n; ++i) {
        const dynamics::Body3dSample& s = series[static_cast<std::size_t>(i)];
        t.mutable_data()[i] = s.time_s;
        ux.mutable_data()[i] = s.slide_x_m;
        uy.mutable_data()[i] = s.slide_y_m;
        tilt.mutable_data()[i] = s.tilt_rad;
        ratio.mutable_data()[i] = s.tilt_over_critical;
        twist.mutable_data()[i] = s.twist_rad;
        state.mutable_data()[i] = static_cast<std::int8_t>(s.state);
    }
    py::dict d;
    d["time_s"] = t;
    d["slide_x_m"] = ux;
    d["slide_y_m"] = uy;
    d["tilt_rad"] = tilt;
    d["tilt_over_critical"] = ratio;
    d["twist_rad"] = twist;
    d["state"] = state;
    if (with_mode) {
        py::array_t<double> qx(n), qy(n);
        for (py::ssize_t i = 0; i < n; ++i) {
            qx.mutable_data()[i] = series[static_cast<std::size_t>(i)].modal_x_m;
            qy.mutable_data()[i] = series[static_cast<std::size_t>(i)].modal_y_m;
        }
        d["modal_x_m"] = qx;
        d["modal_y_m"] = qy;
    }
    return d;
}

/// A component on the x record's samples (the same time steps).
core::Record same_steps(const py::handle& samples, const core::Record& x, const char* field,
                        const char* component) {
    core::Record r = make_record(samples, x.dt_s, x.name, "python", component);
    if (r.size() != x.size())
        throw InputError(SourceLocation{"", 0, field},
                         fmt::format("{} samples; expected the {} of accel_mps2 (the same time "
                                     "steps)",
                                     r.size(), x.size()));
    return r;
}

double number(const py::dict& d, const char* key, const char* prefix = "block.") {
    if (!d.contains(key))
        throw InputError(SourceLocation{"", 0, std::string(prefix) + key}, "missing");
    return d[key].cast<double>();
}

/// flexible = {f, zeta, mass, height} as the mode the 3D body carries (api::SimulateRequest).
dynamics::FlexibleMode mode_of(const py::dict& flexible) {
    dynamics::FlexibleMode mode;
    mode.frequency_hz = number(flexible, "f", "flexible.");
    mode.damping = optional_number(flexible, "zeta").value_or(mode.damping);
    mode.mass_fraction = optional_number(flexible, "mass");
    mode.height_m = optional_number(flexible, "height");
    return mode;
}

api::SimulateRequest body3d_request(const py::dict& block, double mu_s, std::optional<double> mu_k,
                                    std::optional<double> restitution, double step_s,
                                    const py::handle& accel_x, double dt_s,
                                    const py::object& accel_y, const py::object& vertical,
                                    double scale, const std::string& label, bool series,
                                    const py::object& flexible, bool phases) {
    api::SimulateRequest r;
    if (!flexible.is_none()) r.flexible = mode_of(flexible.cast<py::dict>());
    api::Body3dSpec spec;
    spec.half_x_m = number(block, "b");
    spec.half_y_m = number(block, "d");
    spec.cg_height_m = number(block, "h");
    spec.mass_kg = optional_number(block, "m").value_or(spec.mass_kg);
    spec.total_height_m = optional_number(block, "height");
    spec.cg_x_m = optional_number(block, "cgx").value_or(0.0);
    spec.cg_y_m = optional_number(block, "cgy").value_or(0.0);
    const auto ixx = optional_number(block, "ixx"), iyy = optional_number(block, "iyy"),
               izz = optional_number(block, "izz");
    if (ixx || iyy || izz) {
        if (!(ixx && iyy && izz))
            throw InputError(SourceLocation{"", 0, "block.ixx"},
                             "give all three of ixx, iyy and izz (kg m^2), or none");
        spec.inertia_cg_kgm2 = std::array<double, 3>{*ixx, *iyy, *izz};
    }
    spec.dt_s = step_s;
    spec.phases = phases;
    r.body3d = spec;
    r.mu_s = mu_s;
    r.mu_k = mu_k;
    r.restitution = restitution;
    r.record_series = series;
    api::SimulateExcitation& e = r.excitation;
    e.horizontal = make_record(accel_x, dt_s, label, "python", "h");
    if (!accel_y.is_none()) e.horizontal_y = same_steps(accel_y, *e.horizontal, "accel_y_mps2", "y");
    if (!vertical.is_none()) e.vertical = same_steps(vertical, *e.horizontal, "vertical_mps2", "v");
    e.scale = scale;
    return r;
}

py::list state_names() {
    py::list names;
    for (std::size_t s = 0; s < dynamics::contact_state_count; ++s)
        names.append(dynamics::to_string(static_cast<dynamics::ContactState>(s)));
    return names;
}

}  // namespace

void bind_body3d(py::module_& m) {
    m.attr("state_names") = state_names();
    m.def(
        "simulate_3d",
        [](const py::dict& block, double mu_s, std::optional<double> mu_k,
           std::optional<double> restitution, double step_s,
           const py::handle& accel_x, double dt_s, const py::object& accel_y,
           const py::object& vertical, double scale, const std::string& label, bool series,
           const py::object& flexible, bool phases) {
            const api::SimulateRequest request = body3d_request(
                block, mu_s, mu_k, restitution, step_s, accel_x, dt_s, accel_y, vertical, scale,
                label, series, flexible, phases);
            api::SimulateResult result;
            {
                py::gil_scoped_release unlocked;
                result = api::simulate(request);
            }
            const auto& run = std::get<api::Body3dRun>(result.run);
            py::dict out(to_python(api::to_json(result), Arrays::lists));
            if (series) out["series"] = body3d_series(run.result.series, run.model.mode.has_value());
            return out;
        },
        py::arg("block"), py::arg("mu_s"), py::arg("mu_k"), py::arg("restitution"),
        py::arg("step_s"), py::arg("accel_x"),
        py::arg("dt_s"), py::arg("accel_y"), py::arg("vertical"), py::arg("scale"),
        py::arg("label"), py::arg("series"), py::arg("flexible"), py::arg("phases"));
}

}  // namespace freestand::python
