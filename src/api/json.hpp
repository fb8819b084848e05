#pragma once
/// The documents results are shown as: `COMMAND --json` prints them, the Python module turns
/// them into dicts without a text round trip, and the report renderers read them. Key order is
/// the order fields are set, so documents are byte-stable.
#include <nlohmann/json.hpp>
#include <optional>

namespace freestand::api {

using json = nlohmann::ordered_json;

/// A number, or null when absent.
inline json number_or_null(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

}  // namespace freestand::api
