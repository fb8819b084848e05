// simulate.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <ctime>
#include <limits>
#include <optional>

#include "api/simulate.hpp"
#include "bindings.hpp"
#include "convert.hpp"
#include "core/errors.hpp"

namespace freestand::python {

namespace {

/// One NumPy array per series column (dynamics::Sample), the mode as its code.
py::dict series_dict(const std::vector<dynamics::Sample>& series) {
    const auto n = static_cast<py::ssize_t>(series.size());
    py::array_t<double> t(n), u(n), du(n), th(n), dth(n), fn(n), ff(n), top(n);
    py::array_t<std::int8_t> mode(n);
    double* cols[] = {t.mutable_data(), u.mutable_data(), du.mutable_data(), th.mutable_data(),
                      dth.mutable_data(), fn.mutable_data(), ff.mutable_data(), top.mutable_data()};
    std::int8_t* modes = mode.mutable_data();
    for (py::ssize_t i = 0; i < n; ++i) {
        const dynamics::Sample& s = series[static_cast<std::size_t>(i)];
        cols[0][i] = s.time_s;
        cols[1][i] = s.slide_m;
        cols[2][i] = s.slide_velocity_mps;
        cols[3][i] = s.rotation_rad;
        cols[4][i] = s.angular_velocity_radps;
        cols[5][i] = s.normal_force_N;
        cols[6][i] = s.friction_force_N;
        cols[7][i] = s.top_accel_mps2;
        modes[i] = static_cast<std::int8_t>(s.mode);
    }
    py::dict d;
    d["time_s"] = t;
    d["slide_m"] = u;
    d["slide_velocity_mps"] = du;
    d["rotation_rad"] = th;
    d["angular_velocity_radps"] = dth;
    d["mode"] = mode;
    d["normal_force_N"] = fn;
    d["friction_force_N"] = ff;
    d["top_accel_mps2"] = top;
    return d;
}

/// The request of simulate's typed arguments, the record's samples copied in. The vertical
/// must be on the horizontal's samples: a shorter one would be read as zero after its end
/// (sample_at), which for arrays is a mistake, not a resampling.
api::SimulateRequest simulate_request(const py::dict& box, double mu_s,
                                      std::optional<double> mu_k,
                                      std::optional<double> restitution,
                                      std::optional<double> top_height_m,
                                      const std::string& integrator, double cd_dt_s,
                                      const py::handle& accel_mps2, double dt_s,
                                      const py::object& vertical_mps2, double scale,
                                      const std::string& label, bool series) {
    api::SimulateRequest r;
    r.box = box_spec(box);
    r.mu_s = mu_s;
    r.mu_k = mu_k;
    r.restitution = restitution;
    r.top_height_m = top_height_m;
    const auto named = api::integrator_named(integrator);
    if (!named)
        throw InputError(SourceLocation{"", 0, "integrator"},
                         fmt::format("expected \"event\" or \"cd\"; got \"{}\"", integrator));
    r.integrator = *named;
    r.cd_dt_s = cd_dt_s;
    r.record_series = series;
    api::SimulateExcitation& e = r.excitation;
    e.horizontal = make_record(accel_mps2, dt_s, label, "python", "h");
    if (!vertical_mps2.is_none()) {
        e.vertical = make_record(vertical_mps2, dt_s, label, "python", "v");
        if (e.vertical->size() != e.horizontal->size())
            throw InputError(SourceLocation{"", 0, "vertical_mps2"},
                             fmt::format("{} samples; expected the {} of accel_mps2 (the same "
                                         "time steps)",
                                         e.vertical->size(), e.horizontal->size()));
    }
    e.scale = scale;
    return r;
}

py::list mode_names() {
    py::list names;
    for (std::size_t m = 0; m < dynamics::mode_count; ++m)
        names.append(dynamics::to_string(static_cast<dynamics::Mode>(m)));
    return names;
}

double thread_cpu_s() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace

void bind_runs(py::module_& m) {
    m.attr("mode_names") = mode_names();
    m.def(
        "simulate",
        [](const py::dict& box, double mu_s, std::optional<double> mu_k,
           std::optional<double> restitution, std::optional<double> top_height_m,
           const std::string& integrator, double cd_dt_s, const py::handle& accel_mps2,
           double dt_s, const py::object& vertical_mps2, double scale, const std::string& label,
           bool series) {
            const api::SimulateRequest request =
                simulate_request(box, mu_s, mu_k, restitution, top_height_m, integrator, cd_dt_s,
                                 accel_mps2, dt_s, vertical_mps2, scale, label, series);
            api::SimulateResult result;
            {
                py::gil_scoped_release unlocked;
                result = api::simulate(request);
            }
            const auto& run = std::get<api::PlanarRun>(result.run);
            py::dict out(to_python(api::to_json(run.result.summary), Arrays::lists));
            if (series) out["series"] = series_dict(run.result.series);
            return out;
        },
        py::arg("box"), py::arg("mu_s"), py::arg("mu_k"), py::arg("restitution"),
        py::arg("top_height_m"), py::arg("integrator"), py::arg("cd_dt_s"), py::arg("accel_mps2"),
        py::arg("dt_s"), py::arg("vertical_mps2"), py::arg("scale"), py::arg("label"),
        py::arg("series"));
    // bench/python_simulate.py's reference: the C++ call `simulate` makes (api::simulate of the
    // request, with the record already the library's own), timed in C++ as the thread's CPU
    // seconds, the least of `repeats` calls.
    m.def(
        "_simulate_cpu_s",
        [](const py::dict& box, double mu_s, const py::handle& accel_mps2, double dt_s,
           double scale, bool series, int repeats) {
            const api::SimulateRequest request =
                simulate_request(box, mu_s, std::nullopt, std::nullopt, std::nullopt, "event",
                                 1e-4, accel_mps2, dt_s, py::none(), scale, "bench", series);
            double best_s = std::numeric_limits<double>::infinity();
            for (int i = 0; i < repeats; ++i) {
                const double t0 = thread_cpu_s();
                api::simulate(request);
                best_s = std::min(best_s, thread_cpu_s() - t0);
            }
            return best_s;
        },
        py::arg("box"), py::arg("mu_s"), py::arg("accel_mps2"), py::arg("dt_s"), py::arg("scale"),
        py::arg("series"), py::arg("repeats"));
}

}  // namespace freestand::python
