// CSV records (readers.hpp contract): '#' comment lines anywhere, blank lines ignored; a header
// naming a time and an acceleration column in either order (names and units in csv_columns.hpp),
// or one acceleration column after a "# dt_s: <value>" comment. The separator is the header's:
// ';', else a tab, else ','. Optional "# name:" and "# component:" comments fill the record's
// labels, so write_csv_g output reads back unchanged.
#include <cmath>
#include <fmt/format.h>
#include <optional>

#include "core/csv_columns.hpp"
#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/readers.hpp"
#include "core/text_parse.hpp"

namespace freestand::core {

namespace {

/// Relative tolerance on the time step of a two-column file: every step must equal the first
/// within it, or the file is rejected as having a non-uniform time step.
constexpr double dt_rel_tol = 1e-6;

std::vector<std::string_view> split_fields(std::string_view line, char separator) {
    std::vector<std::string_view> fields;
    std::size_t start = 0;
    while (true) {
        const std::size_t end = line.find(separator, start);
        fields.push_back(text::trim(line.substr(start, end == std::string_view::npos ? end : end - start)));
        if (end == std::string_view::npos) return fields;
        start = end + 1;
    }
}

char header_separator(std::string_view header) {
    if (header.find(';') != std::string_view::npos) return ';';
    if (header.find('\t') != std::string_view::npos) return '\t';
    return ',';
}

std::string separator_name(char separator) {
    if (separator == ';') return "semicolon";
    if (separator == '\t') return "tab";
    return "comma";
}

/// Where the separator is not ',' (a spreadsheet in a decimal-comma locale writes ';'), one
/// ',' in a number without a '.' is its decimal point: "0,25" is 0.25.
std::string decimal_point(std::string_view field, char separator) {
    std::string number(field);
    if (separator == ',' || number.find('.') != std::string::npos) return number;
    const std::size_t comma = number.find(',');
    if (comma != std::string::npos && number.find(',', comma + 1) == std::string::npos) number[comma] = '.';
    return number;
}

struct CsvHeader {
    std::size_t line_index = 0;
    std::string text;  ///< the header line as written, for messages
    char separator = ',';
    std::size_t columns = 0;
    std::optional<std::size_t> time_column;  ///< 0-based
    std::size_t accel_column = 0;             ///< 0-based
    std::string time_name = "time_s";         ///< as written, for messages
    std::string accel_name;
    double time_to_s = 1.0;
    double accel_to_mps2 = 1.0;
};

/// Reads the text line by line as it goes, so that a file's size (up to 512 MiB of one-digit
/// rows) costs no more than the samples it is allowed (limits::max_samples), and refuses the
/// first row beyond them.
class CsvParser {
public:
    CsvParser(std::string file, std::string_view text, double max_samples, double unit_g_mps2)
        : file_(std::move(file)), text_(text), max_samples_(max_samples),
          unit_g_mps2_(unit_g_mps2) {}
    Record parse();

private:
    SourceLocation at(std::size_t index, std::string field) const {
        return {file_, static_cast<int>(index + 1), std::move(field)};
    }
    void read_comment(std::size_t index, std::string_view line, Record& rec);
    void read_dt_comment(std::size_t index, std::string_view value);
    CsvHeader read_header(std::size_t index, std::string_view line) const;
    void place_column(CsvHeader& h, std::size_t column, std::string_view name) const;
    double number(std::size_t index, std::string_view field, std::size_t column, const std::string& name,
                  char separator) const;
    void read_row(std::size_t index, std::string_view line, const CsvHeader& h, Record& rec, std::vector<double>& times_s);
    void check_step(std::size_t index, const std::string& where, double t_prev, double t);

    std::string file_;
    std::string_view text_;
    double max_samples_;
    double unit_g_mps2_;
    std::optional<double> comment_dt_s_;
    std::size_t comment_dt_index_ = 0;
    double first_step_s_ = 0.0;
    std::size_t first_step_index_ = 0;
};

void CsvParser::read_comment(std::size_t index, std::string_view line, Record& rec) {
    const std::string_view body = text::trim(line.substr(1));
    const std::size_t colon = body.find(':');
    if (colon == std::string_view::npos) return;
    const std::string key = text::lower(text::trim(body.substr(0, colon)));
    const std::string_view value = text::trim(body.substr(colon + 1));
    if (key == "name") rec.name = std::string(value);
    if (key == "component") rec.component = std::string(value);
    if (key == "dt_s") read_dt_comment(index, value);
}

// A repeated "# dt_s" line that states the same step is harmless (a file written in parts);
// one that disagrees leaves the record's time axis ambiguous, so neither is taken.
void CsvParser::read_dt_comment(std::size_t index, std::string_view value) {
    double dt_s = 0.0;
    if (!text::parse_double(value, dt_s) || !std::isfinite(dt_s) || dt_s <= 0.0)
        throw InputError(at(index, "dt_s"), fmt::format("expected a time step > 0 s; got \"{}\"", value));
    if (comment_dt_s_ && *comment_dt_s_ != dt_s)
        throw InputError(at(index, "dt_s"),
                         fmt::format("{} s here but {} s at line {}; expected one time step, stated "
                                     "once (or repeated unchanged)",
                                     dt_s, *comment_dt_s_, comment_dt_index_ + 1));
    if (comment_dt_s_) return;
    comment_dt_s_ = dt_s;
    comment_dt_index_ = index;
}

void CsvParser::place_column(CsvHeader& h, std::size_t column, std::string_view name) const {
    const csv::NameReading reading = csv::read_column_name(name, unit_g_mps2_);
    const std::string& header = h.text;
    if (!reading.quantity)
        throw InputError(at(h.line_index, "header"),
                         fmt::format("column {} \"{}\" of \"{}\" is not a recognised name; accepted names: {}",
                                     column + 1, name, header, csv::accepted_names()));
    if (!reading.column) {
        const bool time = *reading.quantity == csv::Quantity::time;
        throw InputError(at(h.line_index, "header"),
                         fmt::format("column \"{}\" has no recognised unit; expected {} in {} (accepted names: {})", name,
                                     time ? "a time" : "an acceleration", csv::accepted_units(*reading.quantity),
                                     csv::accepted_names()));
    }
    const bool is_time = reading.column->quantity == csv::Quantity::time;
    if ((is_time && h.time_column) || (!is_time && !h.accel_name.empty()))
        throw InputError(at(h.line_index, "header"),
                         fmt::format("two {} columns in \"{}\"; expected one time and one acceleration column",
                                     is_time ? "time" : "acceleration", header));
    if (is_time) {
        h.time_column = column;
        h.time_name = std::string(name);
        h.time_to_s = reading.column->to_si;
    } else {
        h.accel_column = column;
        h.accel_name = std::string(name);
        h.accel_to_mps2 = reading.column->to_si;
    }
}

CsvHeader CsvParser::read_header(std::size_t index, std::string_view line) const {
    CsvHeader h;
    h.line_index = index;
    h.text = std::string(line);
    h.separator = header_separator(line);
    const std::vector<std::string_view> cols = split_fields(line, h.separator);
    h.columns = cols.size();
    if (cols.size() > 2)
        throw InputError(at(index, "header"),
                         fmt::format("expected \"time_s,accel_<unit>\" or \"accel_<unit>\" (a time and an acceleration "
                                     "column, or one acceleration column); got {} columns in \"{}\"",
                                     cols.size(), h.text));
    for (std::size_t c = 0; c < cols.size(); ++c) place_column(h, c, cols[c]);
    if (h.accel_name.empty())
        throw InputError(at(index, "header"),
                         fmt::format("no acceleration column in \"{}\"; expected \"time_s,accel_<unit>\" or "
                                     "\"accel_<unit>\"", h.text));
    return h;
}

double CsvParser::number(std::size_t index, std::string_view field, std::size_t column, const std::string& name,
                         char separator) const {
    const std::string where = fmt::format("column {} ({})", column + 1, name);
    double value = 0.0;
    if (!text::parse_double(decimal_point(field, separator), value))
        throw InputError(at(index, where), fmt::format("expected a number; got \"{}\"", field));
    if (!std::isfinite(value))
        throw InputError(at(index, where), fmt::format("value \"{}\" is not finite; expected a finite number", field));
    return value;
}

void CsvParser::check_step(std::size_t index, const std::string& where, double t_prev, double t) {
    const double step = t - t_prev;
    if (first_step_index_ == 0) {
        if (!(step > 0.0))
            throw InputError(at(index, where),
                             fmt::format("time {} s does not increase after {} s; expected a step > 0", t, t_prev));
        first_step_s_ = step;
        first_step_index_ = index;
        return;
    }
    if (std::abs(step - first_step_s_) > dt_rel_tol * first_step_s_)
        throw InputError(at(index, where),
                         fmt::format("non-uniform time step: {} s here but {} s at line {}; expected a uniform step "
                                     "(relative tolerance {})", step, first_step_s_, first_step_index_ + 1, dt_rel_tol));
}

void CsvParser::read_row(std::size_t index, std::string_view line, const CsvHeader& h, Record& rec,
                         std::vector<double>& times_s) {
    const std::vector<std::string_view> fields = split_fields(line, h.separator);
    if (fields.size() != h.columns)
        throw InputError(at(index, ""), fmt::format("expected {} {}-separated column(s) as in the header at line {}; "
                                                    "got {}", h.columns, separator_name(h.separator), h.line_index + 1,
                                                    fields.size()));
    if (h.time_column) {
        const std::size_t c = *h.time_column;
        times_s.push_back(number(index, fields[c], c, h.time_name, h.separator) * h.time_to_s);
        if (times_s.size() > 1)
            check_step(index, fmt::format("column {} ({})", c + 1, h.time_name), times_s[times_s.size() - 2],
                       times_s.back());
    }
    rec.accel_mps2.push_back(number(index, fields[h.accel_column], h.accel_column, h.accel_name, h.separator) *
                             h.accel_to_mps2);
    if (static_cast<double>(rec.accel_mps2.size()) > max_samples_)
        throw InputError(at(index, ""), fmt::format("more than {:.0f} samples, the limit of a record "
                                                    "(README, Limits); the reading stops at this row",
                                                    max_samples_));
}

Record CsvParser::parse() {
    Record rec;
    rec.name = std::filesystem::path(file_).stem().string();
    rec.source = file_;
    std::optional<CsvHeader> header;
    std::vector<double> times_s;
    std::size_t last_row = 0;
    std::size_t i = 0;  // 0-based index of the line being read
    for (std::size_t start = 0; start < text_.size(); ++i) {
        const std::size_t end = std::min(text_.find('\n', start), text_.size());
        const std::string_view line = text::trim(text_.substr(start, end - start));
        start = end + 1;
        if (line.empty()) continue;
        if (line.front() == '#') {
            read_comment(i, line, rec);
            continue;
        }
        if (!header) {
            header = read_header(i, line);
            continue;
        }
        read_row(i, line, *header, rec, times_s);
        last_row = i;
    }
    if (!header)
        throw InputError(at(i == 0 ? 0 : i - 1, ""),
                         "empty file; expected a header \"time_s,accel_<unit>\" or \"accel_<unit>\"");
    if (rec.accel_mps2.empty()) throw InputError(at(header->line_index, ""), "no data rows after the header");
    if (header->time_column) {
        if (times_s.size() < 2)
            throw InputError(at(last_row, header->time_name),
                             "a single row gives no time step; expected at least two rows");
        // The mean step: equal to every step within the tolerance, and least affected by the
        // rounding of printed times.
        rec.dt_s = (times_s.back() - times_s.front()) / static_cast<double>(times_s.size() - 1);
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

Record parse_csv(const std::string& text, const std::string& file_label, double max_samples,
                 double unit_g_mps2) {
    return CsvParser(file_label, text::utf8_text(text, file_label), max_samples, unit_g_mps2)
        .parse();
}

Record read_csv(const std::filesystem::path& path, double unit_g_mps2) {
    return parse_csv(read_input_file(path), path.string(), limits::max_samples, unit_g_mps2);
}

}  // namespace freestand::core
