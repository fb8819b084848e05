// simulate and assess.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <ctime>
#include <limits>
#include <optional>

#include "bindings.hpp"
#include "cli/build_info.hpp"
#include "cli/documents.hpp"
#include "convert.hpp"
#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "report/case_assessment.hpp"

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

/// The model and run options `simulate`'s arguments describe.
struct SimulateSetup {
    dynamics::BlockModel model;
    dynamics::Options options;
};

SimulateSetup simulate_setup(const std::vector<std::string>& args) {
    const auto vm = cli::parse_document_options("simulate", cli::simulate_model_options(), args);
    return {cli::simulate_model(vm, cli::simulate_block(vm)),
            cli::simulate_run_options(vm, dynamics::Options{})};
}

/// simulate_setup of the arguments, remembered for the last few argument lists: a study calls
/// simulate with one block over many records, and parsing the options costs as much as a 20 s
/// resting run (bench/python_simulate.py). Called with the GIL held, which serialises it; the
/// copy returned stays valid while another thread changes the cache.
SimulateSetup cached_simulate_setup(const std::vector<std::string>& args) {
    static std::vector<std::pair<std::vector<std::string>, SimulateSetup>> cache;
    for (const auto& [key, setup] : cache)
        if (key == args) return setup;
    SimulateSetup setup = simulate_setup(args);  // may throw: nothing cached
    constexpr std::size_t capacity = 16;
    if (cache.size() == capacity) cache.erase(cache.begin());
    cache.emplace_back(args, std::move(setup));
    return cache.back().second;
}

py::list mode_names() {
    py::list names;
    for (std::size_t m = 0; m < dynamics::mode_count; ++m)
        names.append(dynamics::mode_name(static_cast<dynamics::Mode>(m)));
    return names;
}

double thread_cpu_s() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

py::object json_loads(const std::string& text) {
    return py::module_::import("json").attr("loads")(text);
}

}  // namespace

void bind_runs(py::module_& m) {
    m.attr("mode_names") = mode_names();
    m.def(
        "simulate",
        [](const std::vector<std::string>& args, const py::handle& accel_mps2, double dt_s,
           const py::object& vertical_mps2, double scale, const std::string& label,
           bool series) {
            const SimulateSetup setup = cached_simulate_setup(args);
            const dynamics::BlockModel& model = setup.model;
            dynamics::Options opt = setup.options;
            opt.record_series = series;
            const core::Record h = make_record(accel_mps2, dt_s, label, "python", "h");
            std::optional<core::Record> v;
            if (!vertical_mps2.is_none())
                v = make_record(vertical_mps2, dt_s, label, "python", "v");
            // On the horizontal's samples: a shorter vertical would be read as zero after its
            // end (sample_at), which for arrays is a mistake, not a resampling.
            if (v && v->size() != h.size())
                throw InputError(SourceLocation{"", 0, "vertical_mps2"},
                                 fmt::format("{} samples; expected the {} of accel_mps2 (the same "
                                             "time steps)", v->size(), h.size()));
            dynamics::SimulationResult res;
            {
                py::gil_scoped_release unlocked;
                const dynamics::Excitation exc =
                    dynamics::excitation_from_record(h, scale, v ? &*v : nullptr, scale);
                res = dynamics::simulate(model, exc, opt);
            }
            py::dict out(to_python(cli::summary_json(res.summary), Arrays::lists));
            if (series) out["series"] = series_dict(res.series);
            return out;
        },
        py::arg("args"), py::arg("accel_mps2"), py::arg("dt_s"), py::arg("vertical_mps2"),
        py::arg("scale"), py::arg("label"), py::arg("series"));
    // bench/python_simulate.py's reference: the C++ call `simulate` makes (the record as the
    // library's own, its excitation and the run), timed in C++ as the thread's CPU seconds, the
    // least of `repeats` calls.
    m.def(
        "_simulate_cpu_s",
        [](const std::vector<std::string>& args, const py::handle& accel_mps2, double dt_s,
           double scale, bool series, int repeats) {
            const SimulateSetup setup = simulate_setup(args);
            dynamics::Options opt = setup.options;
            opt.record_series = series;
            const core::Record h = make_record(accel_mps2, dt_s, "bench", "python", "h");
            double best_s = std::numeric_limits<double>::infinity();
            for (int i = 0; i < repeats; ++i) {
                const double t0 = thread_cpu_s();
                dynamics::simulate(setup.model, dynamics::excitation_from_record(h, scale), opt);
                best_s = std::min(best_s, thread_cpu_s() - t0);
            }
            return best_s;
        },
        py::arg("args"), py::arg("accel_mps2"), py::arg("dt_s"), py::arg("scale"),
        py::arg("series"), py::arg("repeats"));
    m.def(
        "assess",
        [](const std::string& case_file, const std::optional<std::vector<double>>& pga_g) {
            std::string json;
            {
                py::gil_scoped_release unlocked;
                const report::CaseAssessment a =
                    report::assess_case_file(case_file, pga_g, cli::build_commit);
                json = report::result_json_text(a.result, a.stamp,
                                                a.fragility ? &*a.fragility : nullptr,
                                                a.goal ? &*a.goal : nullptr);
            }
            return json_loads(json);
        },
        py::arg("case_file"), py::arg("pga_g"));
}

}  // namespace freestand::python
