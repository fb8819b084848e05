#pragma once
/// Typed errors and the process exit codes they map to (README "Exit codes").
#include <stdexcept>
#include <string>

#include "core/printable.hpp"

namespace freestand {

/// Exit codes of the `freestand` executable.
enum class ExitCode : int {
    ok = 0,
    failure = 1,    ///< the run worked but a check failed (e.g. regress found a drift)
    usage = 2,      ///< bad command line
    input = 3,      ///< bad input file or value
    numerical = 4,  ///< a solver could not reach its tolerance or limit
    io = 5,         ///< a file could not be read or written
    internal = 70,  ///< a bug: an invariant did not hold
};

/// Base of every freestand error; carries the exit code it maps to. The message is kept with its
/// control characters shown as \xNN (core::printable): it quotes fields and file names from
/// input, and what() is a C string that a NUL among them would cut short.
class Error : public std::runtime_error {
public:
    Error(ExitCode code, const std::string& message)
        : std::runtime_error(core::printable(message)), code_(code) {}
    ExitCode code() const noexcept { return code_; }

private:
    ExitCode code_;
};

/// Where a bad value came from: a file (and line, 0 if not known), or a command-line option.
struct SourceLocation {
    std::string file;   ///< path as the user gave it, or "" for the command line
    int line = 0;       ///< 1-based line, 0 when the value has no line
    std::string field;  ///< key, column or option name, "" when the whole file is at fault
};

/// Formats "file:line: field: message" leaving out the parts that are empty.
std::string format_location(const SourceLocation& where, const std::string& message);

/// Bad input data or value a user can fix. what() = "file:line: field: message".
class InputError : public Error {
public:
    InputError(SourceLocation where, const std::string& message)
        : Error(ExitCode::input, format_location(where, message)),
          where_(std::move(where)),
          message_(core::printable(message)) {}
    explicit InputError(const std::string& message)
        : Error(ExitCode::input, message), message_(core::printable(message)) {}
    const SourceLocation& where() const noexcept { return where_; }
    /// The message without its location.
    const std::string& message() const noexcept { return message_; }

private:
    SourceLocation where_;
    std::string message_;
};

/// A file could not be opened, read or written.
class IoError : public Error {
public:
    explicit IoError(const std::string& message) : Error(ExitCode::io, message) {}
};

/// A numerical method failed to converge or hit a limit.
class NumericalError : public Error {
public:
    explicit NumericalError(const std::string& message) : Error(ExitCode::numerical, message) {}
};

/// Always-on check of a user-reachable value: throws InputError naming where it came from,
/// the value and the allowed range.
void require_in_range(double value, double lo, double hi, const SourceLocation& where,
                      bool lo_inclusive = true, bool hi_inclusive = true);
/// Always-on check that value > 0 and finite.
void require_positive(double value, const SourceLocation& where);
/// Always-on check that value >= 0 and finite.
void require_non_negative(double value, const SourceLocation& where);

}  // namespace freestand
