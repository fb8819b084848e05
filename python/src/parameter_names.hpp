#pragma once
/// The one place that maps a request field named in an InputError (api/) to the keyword a
/// Python caller typed, as cli/flag_names.hpp does for the command line.
#include <map>
#include <string>

#include "core/errors.hpp"

namespace freestand::python {

/// Request field -> keyword argument.
const std::map<std::string, std::string>& keyword_names();

/// The error as a Python caller should see it: a location-less field renamed to its keyword;
/// anything else unchanged.
InputError in_python(const InputError& e);

}  // namespace freestand::python
