#include <cmath>
#include <fmt/format.h>
#include <regex>
#include <sstream>

#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/limits.hpp"
#include "core/readers.hpp"
#include "core/text_parse.hpp"
#include "core/units.hpp"

namespace freestand::core {

Record read_at2(const std::filesystem::path& path, double unit_g_mps2) {
    return parse_at2(read_input_file(path), path.string(), unit_g_mps2);
}

Record parse_at2(const std::string& text, const std::string& file, double unit_g_mps2) {
    const std::filesystem::path path(file);
    std::istringstream in(std::string(text::utf8_text(text, file)));
    std::string line;
    std::string header[4];
    for (int i = 0; i < 4; ++i) {
        if (!std::getline(in, line))
            throw InputError({file, i + 1, ""}, "file ends inside the four-line AT2 header");
        if (!line.empty() && line.back() == '\r') line.pop_back();
        text::check_record_line_length(line, file, i + 1);
        header[i] = line;
    }
    if (header[2].find("UNITS OF G") == std::string::npos)
        throw InputError({file, 3, "units"},
                         "expected the AT2 units line to say \"UNITS OF G\"; got \"" + header[2] + "\"");
    static const std::regex npts_dt(R"(NPTS\s*=\s*(\d+)\s*,\s*DT\s*=\s*([0-9.Ee+-]+)\s*SEC)",
                                    std::regex::icase);
    std::smatch m;
    if (!std::regex_search(header[3], m, npts_dt))
        throw InputError({file, 4, "NPTS/DT"},
                         "expected \"NPTS= n, DT= dt SEC\"; got \"" + header[3] + "\"");
    long npts = 0;
    const std::string npts_text = m[1].str();
    if (!text::parse_integer(npts_text, npts) || npts <= 0 || static_cast<double>(npts) > limits::max_samples)
        throw InputError({file, 4, "NPTS"}, fmt::format("expected a point count between 1 and {:g} "
                                                        "(README, Limits); got \"{}\"",
                                                        limits::max_samples, npts_text));
    double dt_s = 0.0;
    if (!text::parse_double(m[2].str(), dt_s) || !std::isfinite(dt_s) || dt_s <= 0.0)
        throw InputError({file, 4, "DT"}, "expected a time step > 0 s; got \"" + m[2].str() + "\"");

    Record rec;
    rec.name = path.stem().string();
    rec.source = file;
    rec.component = header[1];
    rec.dt_s = dt_s;
    rec.accel_mps2.reserve(static_cast<std::size_t>(npts));
    int line_no = 4;
    while (std::getline(in, line)) {
        ++line_no;
        text::check_record_line_length(line, file, line_no);
        std::istringstream tokens(line);
        std::string token;
        while (tokens >> token) {
            double a_g = 0.0;
            if (!text::parse_double(token, a_g))
                throw InputError({file, line_no, "acceleration"},
                                 "expected a number in g; got \"" + token + "\"");
            if (!std::isfinite(a_g))
                throw InputError({file, line_no, "acceleration"},
                                 "value \"" + token + "\" is not finite");
            rec.accel_mps2.push_back(units::g_to_mps2(a_g, unit_g_mps2));
            // NPTS bounds the reading, not only the check after it: the values beyond it are
            // never stored (a 512 MiB file holds 2.5e8 of them).
            if (static_cast<long>(rec.accel_mps2.size()) > npts)
                throw InputError({file, line_no, "acceleration"},
                                 fmt::format("more values than the header's NPTS= {} (line 4); "
                                             "expected {} values",
                                             npts, npts));
        }
    }
    if (rec.accel_mps2.empty()) throw InputError({file, line_no, ""}, "no acceleration values after the header");
    if (static_cast<long>(rec.accel_mps2.size()) != npts)
        throw InputError({file, 4, "NPTS"}, fmt::format("header says NPTS= {} but the file holds {} values",
                                                        npts, rec.accel_mps2.size()));
    return rec;
}

}  // namespace freestand::core
