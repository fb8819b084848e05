// CSV records (readers.hpp contract): '#' comment lines anywhere, blank lines ignored; a header
// "time_s,accel_<unit>" (two columns) or "accel_<unit>" (one column, after a "# dt_s: <value>"
// comment); <unit> is g, mps2 or cmps2. Optional "# name:" and "# component:" comments fill
// the record's labels, so write_csv_g output reads back unchanged.
#include <cmath>
#include <fmt/format.h>
#include <optional>

#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/readers.hpp"
#include "core/text_parse.hpp"
#include "core/units.hpp"

namespace freestand::core {

namespace {

/// Relative tolerance on the time step of a two-column file (issue 2).
constexpr double dt_rel_tol = 1e-6;

std::optional<double> unit_to_mps2(std::string_view column) {
    if (column == "accel_g") return units::g_mps2;
    if (column == "accel_mps2") return 1.0;
    if (column == "accel_cmps2") return units::cm_to_m;
    return std::nullopt;
}

std::vector<std::string_view> split_commas(std::string_view line) {
    std::vector<std::string_view> fields;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = line.find(',', start);
        fields.push_back(text::trim(line.substr(start, comma == std::string_view::npos ? comma : comma - start)));
        if (comma == std::string_view::npos) return fields;
        start = comma + 1;
    }
}

struct CsvHeader {
    std::size_t line_index = 0;
    bool has_time = false;
    std::string accel_column;
    double to_mps2 = 0.0;
};

class CsvParser {
public:
    CsvParser(std::string file, std::vector<std::string> lines)
        : file_(std::move(file)), lines_(std::move(lines)) {}
    Record parse();

private:
    SourceLocation at(std::size_t index, std::string field) const {
        return {file_, static_cast<int>(index + 1), std::move(field)};
    }
    void read_comment(std::size_t index, Record& rec);
    CsvHeader read_header(std::size_t index) const;
    double number(std::size_t index, std::string_view field, std::size_t column, const std::string& name) const;
    void check_step(std::size_t index, double t_prev, double t) ;

    std::string file_;
    std::vector<std::string> lines_;
    std::optional<double> comment_dt_s_;
    std::size_t comment_dt_index_ = 0;
    double first_step_s_ = 0.0;
    std::size_t first_step_index_ = 0;
};

void CsvParser::read_comment(std::size_t index, Record& rec) {
    const std::string_view body = text::trim(std::string_view(lines_[index]).substr(1));
    const std::size_t colon = body.find(':');
    if (colon == std::string_view::npos) return;
    const std::string key = text::lower(text::trim(body.substr(0, colon)));
    const std::string_view value = text::trim(body.substr(colon + 1));
    if (key == "name") rec.name = std::string(value);
    if (key == "component") rec.component = std::string(value);
    if (key != "dt_s") return;
    double dt_s = 0.0;
    if (!text::parse_double(value, dt_s) || !std::isfinite(dt_s) || dt_s <= 0.0)
        throw InputError(at(index, "dt_s"), fmt::format("expected a time step > 0 s; got \"{}\"", value));
    comment_dt_s_ = dt_s;
    comment_dt_index_ = index;
}

CsvHeader CsvParser::read_header(std::size_t index) const {
    const std::vector<std::string_view> cols = split_commas(lines_[index]);
    CsvHeader h;
    h.line_index = index;
    h.has_time = cols.size() == 2;
    if (cols.size() > 2 || (h.has_time && cols[0] != "time_s"))
        throw InputError(at(index, "header"), fmt::format("expected \"time_s,accel_<unit>\" or \"accel_<unit>\"; "
                                                          "got \"{}\"", lines_[index]));
    h.accel_column = std::string(cols.back());
    const std::optional<double> factor = unit_to_mps2(h.accel_column);
    if (!factor)
        throw InputError(at(index, "header"),
                         fmt::format("column \"{}\" has no recognised unit; expected accel_g, accel_mps2 or accel_cmps2",
                                     h.accel_column));
    h.to_mps2 = *factor;
    return h;
}

double CsvParser::number(std::size_t index, std::string_view field, std::size_t column, const std::string& name) const {
    const std::string where = fmt::format("column {} ({})", column, name);
    double value = 0.0;
    if (!text::parse_double(field, value))
        throw InputError(at(index, where), fmt::format("expected a number; got \"{}\"", field));
    if (!std::isfinite(value))
        throw InputError(at(index, where), fmt::format("value \"{}\" is not finite; expected a finite number", field));
    return value;
}

void CsvParser::check_step(std::size_t index, double t_prev, double t) {
    const double step = t - t_prev;
    if (first_step_index_ == 0) {
        if (!(step > 0.0))
            throw InputError(at(index, "column 1 (time_s)"),
                             fmt::format("time {} s does not increase after {} s; expected a step > 0", t, t_prev));
        first_step_s_ = step;
        first_step_index_ = index;
        return;
    }
    if (std::abs(step - first_step_s_) > dt_rel_tol * first_step_s_)
        throw InputError(at(index, "column 1 (time_s)"),
                         fmt::format("non-uniform time step: {} s here but {} s at line {}; expected a uniform step "
                                     "(relative tolerance {})", step, first_step_s_, first_step_index_ + 1, dt_rel_tol));
}

Record CsvParser::parse() {
    Record rec;
    rec.name = std::filesystem::path(file_).stem().string();
    rec.source = file_;
    std::optional<CsvHeader> header;
    std::vector<double> times;
    std::size_t last_row = 0;
    for (std::size_t i = 0; i < lines_.size(); ++i) {
        const std::string_view line = text::trim(lines_[i]);
        if (line.empty()) continue;
        if (line.front() == '#') {
            read_comment(i, rec);
            continue;
        }
        if (!header) {
            header = read_header(i);
            continue;
        }
        const std::vector<std::string_view> fields = split_commas(line);
        const std::size_t expected = header->has_time ? 2 : 1;
        if (fields.size() != expected)
            throw InputError(at(i, ""), fmt::format("expected {} comma-separated column(s) as in the header at line {}; "
                                                    "got {}", expected, header->line_index + 1, fields.size()));
        if (header->has_time) {
            times.push_back(number(i, fields[0], 1, "time_s"));
            if (times.size() > 1) check_step(i, times[times.size() - 2], times.back());
        }
        rec.accel_mps2.push_back(number(i, fields.back(), expected, header->accel_column) * header->to_mps2);
        last_row = i;
    }
    if (!header)
        throw InputError(at(lines_.empty() ? 0 : lines_.size() - 1, ""),
                         "empty file; expected a header \"time_s,accel_<unit>\" or \"accel_<unit>\"");
    if (rec.accel_mps2.empty()) throw InputError(at(header->line_index, ""), "no data rows after the header");
    if (header->has_time) {
        if (times.size() < 2)
            throw InputError(at(last_row, "time_s"), "a single row gives no time step; expected at least two rows");
        // The mean step: equal to every step within the tolerance, and least affected by the
        // rounding of printed times.
        rec.dt_s = (times.back() - times.front()) / static_cast<double>(times.size() - 1);
        if (comment_dt_s_ && std::abs(*comment_dt_s_ - rec.dt_s) > dt_rel_tol * rec.dt_s)
            throw InputError(at(comment_dt_index_, "dt_s"),
                             fmt::format("comment says dt_s {} but the time column steps by {} s", *comment_dt_s_, rec.dt_s));
    } else {
        if (!comment_dt_s_)
            throw InputError(at(header->line_index, "dt_s"),
                             "one-column file without a time step; expected a \"# dt_s: <value>\" line before the header");
        rec.dt_s = *comment_dt_s_;
    }
    return rec;
}

}  // namespace

Record parse_csv(const std::string& text, const std::string& file_label) {
    return CsvParser(file_label, text::split_lines(text)).parse();
}

Record read_csv(const std::filesystem::path& path) {
    return parse_csv(read_input_file(path), path.string());
}

}  // namespace freestand::core
