// classify, slide and rock: typed arguments to the request.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "api/classify.hpp"
#include "api/rock.hpp"
#include "api/slide.hpp"
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
    m.def(
        "slide",
        [](double mu_s, double av_g, std::optional<double> pgd_m, std::optional<double> pga_h_g,
           std::optional<double> fes_hz, const std::vector<std::filesystem::path>& spectrum10) {
            const api::SlideRequest request{mu_s, av_g, pgd_m, pga_h_g, fes_hz, spectrum10};
            return to_python(api::to_json(api::slide(request)), Arrays::lists);
        },
        py::arg("mu_s"), py::arg("av_g"), py::arg("pgd_m"), py::arg("pga_h_g"), py::arg("fes_hz"),
        py::arg("spectrum10_files"));
    m.def(
        "rock",
        [](const py::dict& box, const py::dict& demand,
           const std::vector<std::filesystem::path>& spectrum,
           const std::vector<std::filesystem::path>& spectrum_v,
           std::optional<std::array<double, 2>> rock_band_hz) {
            api::RockRequest r;
            r.box = box_spec(box);
            r.spectrum_files = spectrum;
            r.spectrum_v_files = spectrum_v;
            r.v_ratio = optional_number(demand, "v_ratio");
            r.pga_h_g = optional_number(demand, "pga_h_g");
            r.av_g = optional_number(demand, "av_g");
            r.pgv_mps = optional_number(demand, "pgv_mps");
            r.mu_s = optional_number(demand, "mu_s");
            r.restitution = optional_number(demand, "restitution");
            r.fs_required = optional_number(demand, "fs_required").value_or(r.fs_required);
            r.fixed_base_hz = optional_number(demand, "fixed_base_hz");
            r.rock_band_hz = rock_band_hz;
            return to_python(api::to_json(api::rock(r)), Arrays::lists);
        },
        py::arg("box"), py::arg("demand"), py::arg("spectrum_files"),
        py::arg("spectrum_v_files"), py::arg("rock_band_hz"));
}

}  // namespace freestand::python
