// The consumer of tests/package: computes through the installed headers and libraries what a
// user of the library would (a response spectrum, a case's assessment with its rendered report)
// and prints lines tests/package/check.cmake compares with known answers.
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <exception>
#include <optional>

#include <freestand/core/record.hpp>
#include <freestand/core/units.hpp>
#include <freestand/api/assess.hpp>
#include <freestand/report/verdict_line.hpp>
#include <freestand/spectra/response.hpp>

namespace fs = freestand;

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: consumer CASE.toml\n");
        return 2;
    }
    try {
        // A 0.3 g, 1 Hz sine for 10 s. An oscillator at 100 Hz is rigid against it (frequency
        // ratio 0.01: steady-state amplification 1 / (1 - 0.01^2)), so its PSA is the PGA.
        fs::core::Record sine;
        sine.name = "sine";
        sine.dt_s = 0.005;
        for (std::size_t i = 0; i <= 2000; ++i) {
            const double t_s = static_cast<double>(i) * sine.dt_s;
            sine.accel_mps2.push_back(fs::units::g_to_mps2(0.3) * std::sin(fs::units::two_pi * t_s));
        }
        const fs::spectra::ResponseSpectra rs = fs::spectra::response_spectra(sine, {0.05}, {100.0});
        std::printf("psa_100hz_g %.3f\n", rs.psa_g[0][0]);

        // The whole pipeline: read, assess and render a case (templates compiled into the library).
        fs::api::AssessRequest request;
        request.case_file = argv[1];
        request.commit = "consumer";
        const fs::api::AssessReport run = fs::api::assess_report(request);
        std::printf("%s\n", fs::report::verdict_line(run.assessed.result).c_str());
        std::printf("report_html_bytes %zu\n", run.rendered.html.size());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "consumer: %s\n", e.what());
        return 1;
    }
    return 0;
}
