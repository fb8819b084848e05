#include "core/csv_table.hpp"

#include "core/errors.hpp"
#include "core/text_parse.hpp"

namespace freestand::core {

namespace {

// Reads records character by character; line counts every LF, inside quotes too, so a
// record's line is where it starts in the file.
class CsvScanner {
  public:
    CsvScanner(std::string_view text, const std::string& file)
        : text_(text::utf8_text(text, file)), file_(file) {}

    std::vector<CsvRecord> records() {
        std::vector<CsvRecord> out;
        while (pos_ < text_.size()) {
            CsvRecord r{line_, {}};
            read_record(r.fields);
            if (!(r.fields.size() == 1 && r.fields[0].empty() && !quoted_last_))
                out.push_back(std::move(r));
        }
        return out;
    }

  private:
    [[noreturn]] void fail(int line, const std::string& message) const {
        throw InputError(SourceLocation{file_, line, ""}, message);
    }

    bool at_record_end() const {
        return pos_ >= text_.size() || text_[pos_] == '\n' ||
               (text_[pos_] == '\r' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n');
    }

    void end_record() {
        if (pos_ < text_.size() && text_[pos_] == '\r') ++pos_;
        if (pos_ < text_.size() && text_[pos_] == '\n') {
            ++pos_;
            ++line_;
        }
    }

    void read_record(std::vector<std::string>& fields) {
        while (true) {
            fields.push_back(read_field());
            if (at_record_end()) return end_record();
            ++pos_;  // the ','
        }
    }

    std::string read_field() {
        quoted_last_ = pos_ < text_.size() && text_[pos_] == '"';
        return quoted_last_ ? read_quoted() : read_plain();
    }

    std::string read_plain() {
        std::string out;
        while (pos_ < text_.size() && text_[pos_] != ',' && !at_record_end()) {
            if (text_[pos_] == '"')
                fail(line_, "a double quote inside an unquoted field; quote the whole field "
                            "(\"...\") and double the quote inside it (RFC 4180)");
            out += text_[pos_++];
        }
        return out;
    }

    std::string read_quoted() {
        const int start_line = line_;
        std::string out;
        ++pos_;
        while (true) {
            if (pos_ >= text_.size())
                fail(start_line, "a quoted field that never closes (RFC 4180)");
            const char c = text_[pos_++];
            if (c == '"') {
                if (pos_ < text_.size() && text_[pos_] == '"') {
                    out += '"';
                    ++pos_;
                    continue;
                }
                if (pos_ < text_.size() && text_[pos_] != ',' && !at_record_end())
                    fail(line_, "text after the closing quote of a field; expected ',' or the "
                                "end of the line (RFC 4180)");
                return out;
            }
            if (c == '\n') ++line_;
            out += c;
        }
    }

    std::string_view text_;
    const std::string& file_;
    std::size_t pos_ = 0;
    int line_ = 1;
    bool quoted_last_ = false;
};

}  // namespace

std::vector<CsvRecord> parse_csv_table(std::string_view text, const std::string& file) {
    return CsvScanner(text, file).records();
}

std::string csv_field(std::string_view text) {
    const bool quote = text.find_first_of(",\"\r\n") != std::string_view::npos ||
                       (!text.empty() && (text.front() == ' ' || text.back() == ' '));
    if (!quote) return std::string(text);
    std::string out = "\"";
    for (char c : text) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + "\"";
}

std::string csv_record(const std::vector<std::string>& fields) {
    std::string out;
    for (std::size_t i = 0; i < fields.size(); ++i) {
        if (i > 0) out += ',';
        out += csv_field(fields[i]);
    }
    return out + "\r\n";
}

}  // namespace freestand::core
