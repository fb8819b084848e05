#pragma once
/// The command line's own error: the libraries name request fields (InputError), only the
/// command line knows options and commands.
#include <string>

#include "core/errors.hpp"

namespace freestand {

/// Bad command line (unknown option, missing argument, options that exclude each other): exit 2.
class UsageError : public Error {
public:
    explicit UsageError(const std::string& message) : Error(ExitCode::usage, message) {}
};

}  // namespace freestand
