#include "core/json_fields.hpp"

namespace freestand::core {

JsonFields::JsonFields(const nlohmann::json& j, SourceLocation at, std::string prefix,
                       std::string context)
    : j_(j), at_(std::move(at)), prefix_(std::move(prefix)), context_(std::move(context)) {
    if (j_.is_object()) return;
    const std::string place = prefix_.empty() ? "the line" : prefix_.substr(0, prefix_.size() - 1);
    throw InputError(SourceLocation{at_.file, at_.line, place},
                     context_ + ": expected a JSON object; got " + shown(j_));
}

SourceLocation JsonFields::at(const std::string& key) const {
    return SourceLocation{at_.file, at_.line, prefix_ + key};
}

void JsonFields::fail(const std::string& key, const std::string& what) const {
    throw InputError(at(key), context_ + ": " + what);
}

const nlohmann::json& JsonFields::node(const std::string& key) const {
    const auto it = j_.find(key);
    if (it == j_.end()) fail(key, "missing");
    return *it;
}

JsonFields JsonFields::object(const std::string& key) const {
    return JsonFields(node(key), at_, prefix_ + key + ".", context_);
}

std::string JsonFields::shown(const nlohmann::json& n) {
    std::string text = n.dump(-1, ' ', true, nlohmann::json::error_handler_t::replace);
    constexpr std::size_t max_chars = 80;
    if (text.size() > max_chars) text = text.substr(0, max_chars) + "...";
    return text;
}

}  // namespace freestand::core
