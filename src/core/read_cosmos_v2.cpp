// COSMOS Strong Motion Data Format v1.20 (COSMOS Strong Motion Programs Board, 2001), processed
// ("V2", "Corrected acceleration") channel. Layout of one channel:
//   text header     line 1 "Corrected acceleration    (Format v01.20 with 13 text lines) ..."
//   integer header  "100 Integer-header values follow on 10 lines, Format= (10I8)" + lines
//   real header     "100 Real-header values follow on 17 lines, Format= (6F13.6)" + lines
//   comments        "  2 Comment line(s) follow, each starting with a "|":" + lines
//   data            "  2000 acceleration pts, approx 20 secs, units=cm/sec2 (04), Format=(8F10.5)"
//   end             "End-of-data for Chan  1 acceleration"
// Values are Fortran fixed-width fields and may touch ("-999.000000426212.000000"), so they are
// cut by the width in the Format= specifier, never split on blanks. Indices used (1-based, as in
// the format tables; USGS PRISM and gmprocess read the same ones): integer #2 physical parameter
// (1 = acceleration), #3 units code (2 = g, 4 = cm/s/s, 10 = gal); real #62 sampling interval in
// ms of the processed series, #34 sampling interval in s (of the raw record, used only when #62
// is unknown). Only the first acceleration channel of a file is read.
#include <cmath>
#include <fmt/format.h>
#include <optional>
#include <regex>

#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/readers.hpp"
#include "core/limits.hpp"
#include "core/text_parse.hpp"
#include "core/units.hpp"

namespace freestand::core {

namespace {

constexpr std::size_t int_physical_parameter = 1;  // integer #2
constexpr std::size_t int_units_code = 2;          // integer #3
constexpr std::size_t real_dt_ms = 61;             // real #62
constexpr std::size_t real_dt_raw_s = 33;          // real #34

struct FortranFormat {
    std::size_t per_line = 0;
    std::size_t width = 0;
    std::string spec;  // as written, for messages
};

struct Unit {
    double to_mps2 = 0.0;
    std::string label;
};

std::optional<Unit> unit_from_code(long code, double unit_g_mps2) {
    if (code == 2) return Unit{unit_g_mps2, "g"};
    if (code == 4 || code == 10) return Unit{units::cm_to_m, "cm/s/s"};
    return std::nullopt;
}

std::optional<Unit> unit_from_text(std::string_view label, double unit_g_mps2) {
    std::string key;
    for (char c : text::lower(label))
        if (c != ' ') key += c;
    if (key == "g") return Unit{unit_g_mps2, "g"};
    for (const char* cm : {"cm/s/s", "cm/s^2", "cm/s2", "cm/sec2", "cm/sec/sec", "cm/sec^2", "gal"})
        if (key == cm) return Unit{units::cm_to_m, "cm/s/s"};
    return std::nullopt;
}

class CosmosParser {
public:
    CosmosParser(std::string file, std::vector<std::string> lines, double unit_g_mps2)
        : file_(std::move(file)), lines_(std::move(lines)), unit_g_mps2_(unit_g_mps2) {}

    Record parse();

private:
    SourceLocation at(std::size_t index, std::string field) const {
        return {file_, static_cast<int>(index + 1), std::move(field)};
    }
    const std::string& line(std::size_t index, const std::string& what) const;
    std::smatch block_header(std::size_t index, const std::regex& re, const std::string& what,
                             const std::string& example) const;
    FortranFormat format_of(std::size_t index) const;
    std::vector<double> header_values(std::size_t header_index, const std::string& what);
    void read_unknown_sentinel(std::size_t n_text);
    Unit data_unit(std::size_t data_index, const std::vector<double>& ints) const;
    double time_step_s(std::size_t real_index, const std::vector<double>& reals) const;
    std::vector<double> data_values(std::size_t data_index, const FortranFormat& format,
                                    std::size_t npts) const;
    std::size_t count(const std::string& digits, std::size_t index, const std::string& field) const;
    bool known(double v) const { return v != unknown_real_; }
    bool known_int(double v) const { return v != unknown_int_; }

    std::string file_;
    std::vector<std::string> lines_;
    double unit_g_mps2_;
    std::size_t next_ = 0;  // index of the next unread line
    double unknown_int_ = -999.0;
    double unknown_real_ = -999.0;
};

const std::string& CosmosParser::line(std::size_t index, const std::string& what) const {
    if (index >= lines_.size())
        throw InputError(at(index, ""), "file ends where " + what + " was expected");
    return lines_[index];
}

// Regex-matched digit strings; from_chars keeps absurd lengths an InputError, not std::out_of_range.
std::size_t CosmosParser::count(const std::string& digits, std::size_t index, const std::string& field) const {
    constexpr auto max_count = static_cast<std::size_t>(limits::max_samples);
    std::size_t value = 0;
    if (!text::parse_integer(digits, value) || value > max_count)
        throw InputError(at(index, field), fmt::format("count \"{}\" is not a whole number up to {}", digits, max_count));
    return value;
}

std::smatch CosmosParser::block_header(std::size_t index, const std::regex& re, const std::string& what,
                                       const std::string& example) const {
    const std::string& text = line(index, "the " + what + " line");
    std::smatch m;
    if (!std::regex_search(text, m, re))
        throw InputError(at(index, what), fmt::format("expected a line like \"{}\"; got \"{}\"", example, text));
    return m;
}

FortranFormat CosmosParser::format_of(std::size_t index) const {
    static const std::regex re(R"(format\s*=\s*\(\s*(\d+)\s*[a-z]\s*(\d+)[^)]*\))", std::regex::icase);
    std::smatch m;
    if (!std::regex_search(lines_[index], m, re))
        throw InputError(at(index, "Format"),
                         fmt::format("expected a Fortran format such as \"Format=(8F10.5)\"; got \"{}\"", lines_[index]));
    FortranFormat f{count(m[1].str(), index, "Format"), count(m[2].str(), index, "Format"), m[0].str()};
    if (f.per_line == 0 || f.width == 0)
        throw InputError(at(index, "Format"), "expected a positive count and field width in \"" + f.spec + "\"");
    return f;
}

// Cuts one line into fields of the format's width; a line may hold fewer fields (the last line
// of a block) but never text past per_line fields.
void cut_fields(const std::string& text, const FortranFormat& format, const SourceLocation& where,
                std::vector<double>& out) {
    const std::size_t limit = format.per_line * format.width;
    if (text.size() > limit && !text::trim(std::string_view(text).substr(limit)).empty())
        throw InputError(where, fmt::format("expected at most {} fields of width {} ({}); the line is longer",
                                            format.per_line, format.width, format.spec));
    for (std::size_t k = 0; k * format.width < text.size() && k < format.per_line; ++k) {
        const std::string_view field = text::trim(std::string_view(text).substr(k * format.width, format.width));
        if (field.empty()) continue;
        double value = 0.0;
        if (!text::parse_double(field, value))
            throw InputError(where, fmt::format("field {} (columns {}-{}, {}): expected a number; got \"{}\"", k + 1,
                                                k * format.width + 1, (k + 1) * format.width, format.spec, field));
        if (!std::isfinite(value))
            throw InputError(where, fmt::format("field {}: value \"{}\" is not finite; expected a finite number",
                                                k + 1, field));
        out.push_back(value);
    }
}

std::vector<double> CosmosParser::header_values(std::size_t header_index, const std::string& what) {
    static const std::regex re(R"(^\s*(\d+)\s+(integer|real)-header\s+values\s+follow\s+on\s+(\d+)\s+lines?)",
                               std::regex::icase);
    const std::smatch m =
        block_header(header_index, re, what, "100 " + what + " values follow on 10 lines, Format= (10I8)");
    if (!text::icontains(m[2].str(), what.substr(0, what.find('-'))))
        throw InputError(at(header_index, what), "expected the " + what + " block here; got \"" + lines_[header_index] + "\"");
    const std::size_t n_values = count(m[1].str(), header_index, what);
    const std::size_t n_lines = count(m[3].str(), header_index, what);
    const FortranFormat format = format_of(header_index);
    std::vector<double> values;
    for (std::size_t i = header_index + 1; i <= header_index + n_lines; ++i)
        cut_fields(line(i, "a " + what + " line"), format, at(i, what), values);
    if (values.size() != n_values)
        throw InputError(at(header_index, what),
                         fmt::format("header says {} values on {} lines but they hold {}", n_values, n_lines, values.size()));
    next_ = header_index + n_lines + 1;
    return values;
}

void CosmosParser::read_unknown_sentinel(std::size_t n_text) {
    // Text line 13: "Values used when parameter or data value is unknown/unspecified:   -999, -999.0".
    for (std::size_t i = 0; i < n_text && i < lines_.size(); ++i) {
        if (!text::icontains(lines_[i], "unknown/unspecified")) continue;
        static const std::regex number(R"([-+]?\d+(\.\d*)?)");
        const std::string tail = lines_[i].substr(lines_[i].rfind(':') + 1);
        std::vector<double> found;
        for (auto it = std::sregex_iterator(tail.begin(), tail.end(), number); it != std::sregex_iterator(); ++it) {
            double v = 0.0;
            if (text::parse_double(it->str(), v)) found.push_back(v);
        }
        if (found.size() == 2) {
            unknown_int_ = found[0];
            unknown_real_ = found[1];
        }
    }
}

Unit CosmosParser::data_unit(std::size_t data_index, const std::vector<double>& ints) const {
    static const std::regex re(R"(units\s*=\s*([^,(]*?)\s*(\(\s*(\d+)\s*\))?\s*(,|$))", std::regex::icase);
    std::smatch m;
    const std::string& text = lines_[data_index];
    std::optional<Unit> stated;
    std::string stated_as;
    if (std::regex_search(text, m, re)) {
        stated_as = std::string(text::trim(m[1].str()));
        if (m[2].matched) stated_as = fmt::format("{} {}", stated_as, m[2].str());
        stated = m[3].matched ? unit_from_code(static_cast<long>(count(m[3].str(), data_index, "units")), unit_g_mps2_)
                              : unit_from_text(m[1].str(), unit_g_mps2_);
        if (!stated)
            throw InputError(at(data_index, "units"),
                             fmt::format("unsupported units \"{}\"; expected g (code 2) or cm/s/s (code 4 or 10)",
                                         stated_as));
    }
    const double code = ints[int_units_code];
    if (known_int(code)) {
        const std::optional<Unit> coded = unit_from_code(std::lround(code), unit_g_mps2_);
        if (!coded)
            throw InputError(at(data_index, "units"),
                             fmt::format("integer-header #3 gives units code {}; expected 2 (g) or 4/10 (cm/s/s)", code));
        if (stated && coded->to_mps2 != stated->to_mps2)
            throw InputError(at(data_index, "units"),
                             fmt::format("data header says \"{}\" but integer-header #3 says code {} ({})", stated_as,
                                         code, coded->label));
        return *coded;
    }
    if (!stated)
        throw InputError(at(data_index, "units"),
                         "no unit given: expected \"units=cm/sec2 (04)\" or \"units=g (02)\" in the data header "
                         "or a units code in integer-header #3");
    return *stated;
}

double CosmosParser::time_step_s(std::size_t real_index, const std::vector<double>& reals) const {
    const auto checked = [&](double dt_s, const char* which) {
        if (!(std::isfinite(dt_s) && dt_s > 0.0))
            throw InputError(at(real_index, "dt"), fmt::format("real-header {} gives a sampling interval of {} s; "
                                                               "expected a value > 0", which, dt_s));
        return dt_s;
    };
    if (known(reals[real_dt_ms])) return checked(reals[real_dt_ms] * 1e-3, "#62");
    if (known(reals[real_dt_raw_s])) return checked(reals[real_dt_raw_s], "#34");
    throw InputError(at(real_index, "dt"),
                     "no time step: expected the sampling interval in real-header #62 (ms) or #34 (s); both "
                     "hold the unknown value");
}

// Reading stops at the first line that takes the count past the header's NPTS (itself at most
// the sample limit), so a data block longer than its header says costs no more than NPTS values.
std::vector<double> CosmosParser::data_values(std::size_t data_index, const FortranFormat& format,
                                              std::size_t npts) const {
    static const std::regex next_block(R"(^\s*\d+\s+[a-z]+\s+(pts|points)\b)", std::regex::icase);
    std::vector<double> values;
    for (std::size_t i = data_index + 1; i < lines_.size(); ++i) {
        if (text::icontains(lines_[i], "end-of-data") || std::regex_search(lines_[i], next_block)) break;
        cut_fields(lines_[i], format, at(i, "acceleration"), values);
        if (values.size() > npts)
            throw InputError(at(data_index, "NPTS"),
                             fmt::format("data header says {} acceleration pts but the data block "
                                         "holds more (line {} reaches {})",
                                         npts, i + 1, values.size()));
    }
    return values;
}

Record CosmosParser::parse() {
    if (lines_.empty()) throw InputError(at(0, ""), "empty file; expected a COSMOS V2 text header");
    for (std::size_t i = 0; i < lines_.size(); ++i)
        text::check_record_line_length(lines_[i], file_, static_cast<int>(i + 1));
    static const std::regex text_lines(R"(with\s+(\d+)\s+text\s+lines)", std::regex::icase);
    std::smatch m;
    if (!std::regex_search(lines_[0], m, text_lines))
        throw InputError(at(0, "format"), "expected a COSMOS line 1 such as \"Corrected acceleration    (Format v01.20 "
                                          "with 13 text lines)\"; got \"" + lines_[0] + "\"");
    if (!text::icontains(lines_[0], "corrected acceleration") || text::icontains(lines_[0], "uncorrected"))
        throw InputError(at(0, "data type"), "expected a processed (V2) record starting \"Corrected acceleration\"; "
                                             "got \"" + lines_[0] + "\"");
    const std::size_t n_text = count(m[1].str(), 0, "format");
    read_unknown_sentinel(n_text);

    const std::vector<double> ints = header_values(n_text, "Integer-header");
    if (ints.size() <= int_units_code)
        throw InputError(at(n_text, "Integer-header"), "expected at least 3 integer-header values");
    if (known_int(ints[int_physical_parameter]) && ints[int_physical_parameter] != 1.0)
        throw InputError(at(n_text + 1, "physical parameter"),
                         fmt::format("integer-header #2 is {}; expected 1 (acceleration)", ints[int_physical_parameter]));
    const std::size_t real_index = next_;
    const std::vector<double> reals = header_values(real_index, "Real-header");
    if (reals.size() <= real_dt_ms)
        throw InputError(at(real_index, "Real-header"), "expected at least 62 real-header values");

    static const std::regex comments(R"(^\s*(\d+)\s+comment\s+line)", std::regex::icase);
    const std::size_t n_comments = count(block_header(next_, comments, "comments",
                                                      "2 Comment line(s) follow, each starting with a \"|\":")[1].str(),
                                         next_, "comments");
    const std::size_t data_index = next_ + n_comments + 1;
    static const std::regex data_header(R"(^\s*(\d+)\s+acceleration\s+(pts|points)\b)", std::regex::icase);
    const std::size_t npts = count(block_header(data_index, data_header, "data header",
                                                "2000 acceleration pts, approx 20 secs, units=cm/sec2 (04), "
                                                "Format=(8F10.5)")[1].str(),
                                   data_index, "NPTS");

    Record rec;
    rec.name = std::filesystem::path(file_).stem().string();
    rec.source = file_;
    for (std::size_t i = 0; i < n_text && i < lines_.size(); ++i)
        if (text::istarts_with(lines_[i], "Sta Chan")) rec.component = std::string(text::trim(lines_[i]));
    rec.dt_s = time_step_s(real_index, reals);
    const Unit unit = data_unit(data_index, ints);
    rec.accel_mps2 = data_values(data_index, format_of(data_index), npts);
    if (rec.accel_mps2.empty())
        throw InputError(at(data_index, ""), "no acceleration values after the data header");
    if (rec.accel_mps2.size() != npts)
        throw InputError(at(data_index, "NPTS"), fmt::format("data header says {} acceleration pts but the data "
                                                             "block holds {} values", npts, rec.accel_mps2.size()));
    for (double& a : rec.accel_mps2) a *= unit.to_mps2;
    return rec;
}

}  // namespace

Record parse_cosmos_v2(const std::string& text, const std::string& file_label,
                       std::size_t max_lines, double unit_g_mps2) {
    return CosmosParser(file_label, text::split_lines(text, file_label, max_lines), unit_g_mps2)
        .parse();
}

Record read_cosmos_v2(const std::filesystem::path& path, double unit_g_mps2) {
    return parse_cosmos_v2(read_input_file(path), path.string(), limits::max_cosmos_lines,
                           unit_g_mps2);
}

}  // namespace freestand::core
