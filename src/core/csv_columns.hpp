#pragma once
/// Column names of CSV acceleration records (internal to core; read_csv's contract in
/// readers.hpp, the list in docs/methods.md "Record formats"). A name is a quantity word and a
/// unit: `time_s`, `t (s)`, `Acceleration [m/s^2]`, `acc_g`. Case, surrounding blanks and double
/// quotes are ignored, as are spaces and '^' inside the unit; '²' reads as '2'.
#include <optional>
#include <string>
#include <string_view>

namespace freestand::core::csv {

enum class Quantity { time, accel };

/// A recognised column: what it holds and the factor to SI (s or m/s^2).
struct Column {
    Quantity quantity = Quantity::accel;
    double to_si = 1.0;
};

/// Outcome of reading one header field.
struct NameReading {
    std::optional<Column> column;      ///< set when the name is accepted
    std::optional<Quantity> quantity;  ///< set when the quantity word was recognised
};

/// Reads one header field. Time: `time` or `t`, unit s (also `sec`) or ms, seconds when no unit
/// is written. Acceleration: `acceleration`, `accel`, `acc` or `a`, unit g, m/s2 (`mps2`,
/// `ms-2`) or cm/s2 (`cmps2`, `cms-2`, `gal`); an acceleration must state its unit. The unit
/// follows the word after '_' or ' ', or stands in "(...)" or "[...]". The unit g is
/// unit_g_mps2 m/s^2 (the case's g; docs/methods.md, Conventions).
NameReading read_column_name(std::string_view field, double unit_g_mps2);

/// The accepted names as one sentence, for error messages.
const std::string& accepted_names();

/// The accepted units of a quantity as one phrase, for error messages.
const std::string& accepted_units(Quantity quantity);

}  // namespace freestand::core::csv
