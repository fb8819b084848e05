#pragma once
/// A paginated PDF of an HTML report (`assess --pdf`, `fragility --pdf`; README "PDF reports"),
/// made by WeasyPrint (Debian package weasyprint) run as a subprocess on the rendered HTML.
///
/// WeasyPrint is a layout engine for paged media: the reports' print CSS (templates/
/// print_style.html.mustache: @page margin boxes with "page N of M", table headers repeated on
/// every page, sections on new pages) is what it implements, it draws the inline SVG figures
/// as vectors, and with SOURCE_DATE_EPOCH set (the one thing that varied: the time stamp
/// fontTools writes into each embedded font subset) the same HTML gives the same PDF bytes,
/// which keeps the outputs byte-identical for the same inputs. Headless Chromium prints the
/// same HTML faster but stamps the time into every PDF (CreationDate, ModDate) with no option
/// to leave it out.
#include <chrono>
#include <filesystem>
#include <string>

namespace freestand::report {

/// The converter's program, looked up on PATH.
inline constexpr const char* pdf_converter_program = "weasyprint";

/// How long one conversion may take before the converter is killed: a report of 20-30 pages
/// takes 10-30 s on a loaded 2-core machine.
inline constexpr std::chrono::seconds pdf_time_limit{300};

/// The converter's path: the first executable `weasyprint` on PATH. Throws IoError (exit 5)
/// naming the program, PATH and scripts/setup.sh when there is none; the commands call it
/// before their run, so a missing converter stops them before the work, not after it.
std::filesystem::path find_pdf_converter();

/// The PDF bytes of html (a self-contained report: inline CSS and SVG, nothing to fetch),
/// converted by converter in a private temporary folder (its file:// base, removed after;
/// folders of runs that died are removed first) with SOURCE_DATE_EPOCH=0, standard input from
/// /dev/null and a process group of its own that is killed after time_limit, and killed by the
/// kernel if this thread dies (PR_SET_PDEATHSIG). SIGINT, SIGTERM and SIGHUP during the
/// conversion kill the converter's group and remove the folder, then take their course (by
/// default the process ends with the signal: exit status 128 + signal). Throws IoError with
/// the converter's standard error when it fails, is killed or writes no PDF. One conversion
/// runs at a time.
std::string html_to_pdf(const std::filesystem::path& converter, const std::string& html,
                        std::chrono::milliseconds time_limit = pdf_time_limit);

}  // namespace freestand::report
