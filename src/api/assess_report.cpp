// Apart from assess.cpp: rendering pulls in mstch, which a program that only wants the
// result.json document (the Python module, a shared object) must not link.
#include <chrono>

#include "api/assess.hpp"
#include "report/pdf.hpp"

namespace freestand::api {

namespace assess_report_detail {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace assess_report_detail

AssessReport assess_report(const AssessRequest& request) {
    AssessReport out;
    // A missing converter stops the run before the assessment, not after it.
    if (request.pdf) out.pdf_converter = report::find_pdf_converter();
    const auto start = std::chrono::steady_clock::now();
    out.assessed = assess(request);
    const AssessResult& a = out.assessed;
    out.rendered = report::render(a.result, a.stamp, a.fragility ? &*a.fragility : nullptr,
                                  a.goal ? &*a.goal : nullptr);
    out.assess_s = assess_report_detail::seconds_since(start);
    out.files = report::report_files(out.rendered);
    if (out.pdf_converter) {
        const auto pdf_start = std::chrono::steady_clock::now();
        out.files.push_back(
            {"report.pdf", report::html_to_pdf(*out.pdf_converter, out.rendered.html)});
        out.pdf_s = assess_report_detail::seconds_since(pdf_start);
    }
    return out;
}

}  // namespace freestand::api
