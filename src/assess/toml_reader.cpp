#include "assess/toml_reader_detail.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <string_view>

#include "core/text_parse.hpp"

namespace freestand::assess {

toml::table parse_toml(const std::string& text, const std::string& file_label) {
    // UTF-16 is refused as such (toml++ would say "invalid utf-8 sequence"); a BOM is dropped
    // as every reader drops it.
    const std::string_view body = core::text::utf8_text(text, file_label);
    try {
        return toml::parse(body, file_label);
    } catch (const toml::parse_error& e) {
        throw InputError(SourceLocation{file_label, static_cast<int>(e.source().begin.line), ""},
                         fmt::format("TOML syntax error: {}", e.description()));
    }
}

namespace {

const char* type_name(toml::node_type t) {
    switch (t) {
        case toml::node_type::table:
            return "a table";
        case toml::node_type::array:
            return "an array";
        case toml::node_type::string:
            return "a string";
        case toml::node_type::integer:
            return "an integer";
        case toml::node_type::floating_point:
            return "a number";
        case toml::node_type::boolean:
            return "a boolean";
        case toml::node_type::date:
            return "a date";
        case toml::node_type::time:
            return "a time";
        case toml::node_type::date_time:
            return "a date-time";
        case toml::node_type::none:
            break;
    }
    return "nothing";
}

int line_of(const toml::node& node) { return static_cast<int>(node.source().begin.line); }

}  // namespace

TableReader::TableReader(const toml::table* table, std::string file, std::string table_name)
    : table_(table), file_(std::move(file)), name_(std::move(table_name)) {}

bool TableReader::has(const std::string& key) const {
    return table_ != nullptr && table_->contains(key);
}

bool TableReader::holds_array(const std::string& key) const {
    const toml::node* n = table_ == nullptr ? nullptr : table_->get(key);
    return n != nullptr && n->is_array();
}

SourceLocation TableReader::where(const std::string& key) const {
    SourceLocation loc{file_, 0, name_ + "." + key};
    if (table_ == nullptr) return loc;
    if (const toml::node* n = table_->get(key)) {
        loc.line = line_of(*n);
    } else {
        loc.line = line_of(*table_);
    }
    return loc;
}

void TableReader::fail(const std::string& key, const std::string& message) const {
    throw InputError(where(key), message);
}

const toml::node* TableReader::find(const std::string& key) {
    read_.insert(key);
    return table_ == nullptr ? nullptr : table_->get(key);
}

double TableReader::as_number(const std::string& key, const toml::node& node, Range range) const {
    double value = 0.0;
    if (const auto* f = node.as_floating_point()) {
        value = f->get();
    } else if (const auto* i = node.as_integer()) {
        value = static_cast<double>(i->get());
    } else {
        fail(key, fmt::format("expected a number in {}, got {}", describe(range),
                              type_name(node.type())));
    }
    if (!core::limits::within(value, range)) {
        fail(key, fmt::format("value {} is out of range; expected {}", value, describe(range)));
    }
    return value;
}

std::optional<double> TableReader::number(const std::string& key, Range range) {
    const toml::node* n = find(key);
    if (n == nullptr) return std::nullopt;
    return as_number(key, *n, range);
}

double TableReader::required_number(const std::string& key, Range range) {
    const auto v = number(key, range);
    if (!v) fail(key, fmt::format("missing required key (a number in {})", describe(range)));
    return *v;
}

std::optional<long long> TableReader::integer(const std::string& key, long long lo, long long hi) {
    const toml::node* n = find(key);
    if (n == nullptr) return std::nullopt;
    const auto* i = n->as_integer();
    if (i == nullptr) {
        fail(key,
             fmt::format("expected an integer in [{}, {}], got {}", lo, hi, type_name(n->type())));
    }
    const long long v = i->get();
    if (v < lo || v > hi) {
        fail(key,
             fmt::format("value {} is out of range; expected an integer in [{}, {}]", v, lo, hi));
    }
    return v;
}

void TableReader::require_printable(const std::string& key, const std::string& text) const {
    // Control characters (ESC, BEL, NUL...) in names would pass into terminals and reports.
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7F) {
            fail(key, fmt::format("contains the control character U+{:04X} at byte {}; expected "
                                  "printable text",
                                  static_cast<unsigned>(c), i + 1));
        }
    }
}

std::optional<std::string> TableReader::string(const std::string& key) {
    const toml::node* n = find(key);
    if (n == nullptr) return std::nullopt;
    const auto* s = n->as_string();
    if (s == nullptr) fail(key, fmt::format("expected a string, got {}", type_name(n->type())));
    require_printable(key, s->get());
    return s->get();
}

std::string TableReader::required_string(const std::string& key) {
    auto v = string(key);
    if (!v) fail(key, "missing required key (a string)");
    return *v;
}

std::optional<std::vector<double>> TableReader::numbers(const std::string& key, Range range,
                                                        std::size_t exact_size) {
    const toml::node* n = find(key);
    if (n == nullptr) return std::nullopt;
    const auto* arr = n->as_array();
    const std::string shape =
        exact_size > 0 ? fmt::format("an array of {} numbers in {}", exact_size, describe(range))
                       : fmt::format("a non-empty array of numbers in {}", describe(range));
    if (arr == nullptr) fail(key, fmt::format("expected {}, got {}", shape, type_name(n->type())));
    if (arr->empty() || (exact_size > 0 && arr->size() != exact_size)) {
        fail(key, fmt::format("expected {}, got {} element(s)", shape, arr->size()));
    }
    std::vector<double> out;
    for (const toml::node& element : *arr) {
        if (!element.is_number()) {
            fail(key, fmt::format("expected {}, got {} element", shape, type_name(element.type())));
        }
        out.push_back(as_number(key, element, range));
    }
    return out;
}

std::optional<std::vector<std::string>> TableReader::strings(const std::string& key) {
    const toml::node* n = find(key);
    if (n == nullptr) return std::nullopt;
    const auto* arr = n->as_array();
    if (arr == nullptr) {
        fail(key, fmt::format("expected an array of strings, got {}", type_name(n->type())));
    }
    std::vector<std::string> out;
    for (const toml::node& element : *arr) {
        const auto* s = element.as_string();
        if (s == nullptr) {
            fail(key, fmt::format("expected an array of strings, got {} element",
                                  type_name(element.type())));
        }
        require_printable(key, s->get());
        out.push_back(s->get());
    }
    return out;
}

void TableReader::finish(const std::vector<std::string>& allowed) const {
    if (table_ == nullptr) return;
    // Report the first offending key in file order so the message is stable.
    std::vector<std::pair<int, std::string>> unread;
    for (const auto& [k, node] : *table_) {
        const std::string key(k.str());
        if (!read_.contains(key)) unread.emplace_back(line_of(node), key);
    }
    if (unread.empty()) return;
    std::sort(unread.begin(), unread.end());
    const std::string& key = unread.front().second;
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) {
        fail(key, "key is not used together with the other keys given; remove it");
    }
    fail(key, fmt::format("unknown key; allowed keys: {}", fmt::join(allowed, ", ")));
}

const toml::table* TableReader::table(const std::string& key) {
    const toml::node* n = find(key);
    if (n == nullptr) return nullptr;
    if (!n->is_table()) fail(key, fmt::format("expected a table, got {}", type_name(n->type())));
    return n->as_table();
}

std::optional<bool> TableReader::boolean(const std::string& key) {
    const toml::node* n = find(key);
    if (n == nullptr) return std::nullopt;
    if (!n->is_boolean()) fail(key, fmt::format("expected true or false, got {}", type_name(n->type())));
    return n->as_boolean()->get();
}

}  // namespace freestand::assess
