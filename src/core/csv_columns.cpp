#include "core/csv_columns.hpp"

#include <array>
#include <cctype>

#include "core/text_parse.hpp"
#include "core/units.hpp"

namespace freestand::core::csv {

namespace {

struct Word {
    std::string_view text;
    Quantity quantity;
};

// Longest first, so "accel_g" is read as accel + g and not as a + "ccel_g".
constexpr std::array<Word, 6> words{{{"acceleration", Quantity::accel},
                                     {"accel", Quantity::accel},
                                     {"time", Quantity::time},
                                     {"acc", Quantity::accel},
                                     {"a", Quantity::accel},
                                     {"t", Quantity::time}}};

struct Unit {
    std::string_view text;
    Quantity quantity;
    double to_si;
};

constexpr std::array<Unit, 11> unit_table{{{"s", Quantity::time, 1.0},
                                           {"sec", Quantity::time, 1.0},
                                           {"ms", Quantity::time, 1e-3},
                                           // to_si of g is the reader's unit_g_mps2
                                           {"g", Quantity::accel, 0.0},
                                           {"m/s2", Quantity::accel, 1.0},
                                           {"mps2", Quantity::accel, 1.0},
                                           {"ms-2", Quantity::accel, 1.0},
                                           {"cm/s2", Quantity::accel, units::cm_to_m},
                                           {"cmps2", Quantity::accel, units::cm_to_m},
                                           {"cms-2", Quantity::accel, units::cm_to_m},
                                           {"gal", Quantity::accel, units::cm_to_m}}};

/// Lower case, runs of blanks as one space, "²" as "2", without surrounding blanks and quotes.
std::string normalise(std::string_view field) {
    std::string_view f = text::trim(field);
    if (f.size() >= 2 && f.front() == '"' && f.back() == '"') f = text::trim(f.substr(1, f.size() - 2));
    std::string out;
    for (std::size_t i = 0; i < f.size(); ++i) {
        const auto c = static_cast<unsigned char>(f[i]);
        if (c == 0xC2 && i + 1 < f.size() && static_cast<unsigned char>(f[i + 1]) == 0xB2) {
            out += '2';
            ++i;
        } else if (c == ' ' || c == '\t') {
            if (!out.empty() && out.back() != ' ') out += ' ';
        } else {
            out += static_cast<char>(std::tolower(c));
        }
    }
    return out;
}

struct Split {
    std::string quantity;
    std::string unit;
    bool has_unit = false;
};

std::string trim_separators(std::string_view s) {
    while (!s.empty() && (s.back() == ' ' || s.back() == '_')) s.remove_suffix(1);
    return std::string(s);
}

/// "word (unit)", "word [unit]", "word_unit", "word unit" or "word".
Split split_name(const std::string& name) {
    if (!name.empty() && (name.back() == ')' || name.back() == ']')) {
        const std::size_t open = name.rfind(name.back() == ')' ? '(' : '[');
        if (open != std::string::npos)
            return {trim_separators(std::string_view(name).substr(0, open)), name.substr(open + 1, name.size() - open - 2),
                    true};
    }
    for (const Word& w : words) {
        if (name == w.text) return {name, "", false};
        if (name.size() > w.text.size() && name.compare(0, w.text.size(), w.text) == 0 &&
            (name[w.text.size()] == '_' || name[w.text.size()] == ' '))
            return {std::string(w.text), name.substr(w.text.size() + 1), true};
    }
    return {name, "", false};
}

std::string normalise_unit(std::string_view unit) {
    std::string out;
    for (char c : unit)
        if (c != ' ' && c != '^') out += c;
    return out;
}

}  // namespace

NameReading read_column_name(std::string_view field, double unit_g_mps2) {
    const Split split = split_name(normalise(field));
    NameReading reading;
    const Word* word = nullptr;
    for (const Word& w : words)
        if (split.quantity == w.text) word = &w;
    if (!word) return reading;
    reading.quantity = word->quantity;
    if (!split.has_unit) {
        // A time column is in seconds unless it says otherwise; an acceleration has no such
        // convention (g, m/s^2 and cm/s^2 are all common), so it must state its unit.
        if (word->quantity == Quantity::time) reading.column = Column{Quantity::time, 1.0};
        return reading;
    }
    const std::string unit = normalise_unit(split.unit);
    for (const Unit& u : unit_table)
        if (u.quantity == word->quantity && unit == u.text)
            reading.column = Column{u.quantity, u.text == "g" ? unit_g_mps2 : u.to_si};
    return reading;
}

const std::string& accepted_units(Quantity quantity) {
    static const std::string time = "s (also sec; s when no unit is written) or ms";
    static const std::string accel = "g, m/s2 (also mps2, ms-2) or cm/s2 (also cmps2, cms-2, gal)";
    return quantity == Quantity::time ? time : accel;
}

const std::string& accepted_names() {
    static const std::string text =
        "time: time or t, in " + accepted_units(Quantity::time) +
        "; acceleration: acceleration, accel, acc or a, in " + accepted_units(Quantity::accel) +
        "; the unit follows '_' or a space or stands in (...) or [...], as in time_s, t (s), accel_g, "
        "acc (m/s^2), a [gal]; case, blanks and '^' are ignored";
    return text;
}

}  // namespace freestand::core::csv
