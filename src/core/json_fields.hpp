#pragma once
/// Reading the values of a JSON object that came from a file (a shard line, say), each refused
/// as an InputError at the file and line, naming its key: nlohmann's own exceptions name
/// neither, and its conversions accept what a reader must not (0.5 as an integer, -1 as an
/// unsigned count).
#include <cmath>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <type_traits>
#include <vector>

#include "core/errors.hpp"

namespace freestand::core {

class JsonFields {
  public:
    /// j must be an object. at: its file and line; prefix: its place, prepended to every key
    /// ("row." names "row.exit_code"); context: the first words of every message ("malformed
    /// batch shard").
    JsonFields(const nlohmann::json& j, SourceLocation at, std::string prefix, std::string context);

    /// Where key's value stands: at's file and line, field prefix + key.
    SourceLocation at(const std::string& key) const;
    /// Throws InputError at(key): "<context>: <what>".
    [[noreturn]] void fail(const std::string& key, const std::string& what) const;
    /// The value of key; InputError when it is missing.
    const nlohmann::json& node(const std::string& key) const;
    bool is_null(const std::string& key) const { return node(key).is_null(); }
    /// The object at key, read with the same location and context.
    JsonFields object(const std::string& key) const;

    /// key's value as T: a string, a finite number (double), an integer that T holds (never
    /// a fraction, never negative for an unsigned T), a bool, or a list of strings or of
    /// finite numbers.
    template <class T>
    T get(const std::string& key) const {
        const nlohmann::json& n = node(key);
        if (!holds<T>(n)) fail(key, "expected " + expected<T>() + "; got " + shown(n));
        return n.get<T>();
    }

  private:
    template <class T>
    static bool holds(const nlohmann::json& n) {
        if constexpr (std::is_same_v<T, bool>) {
            return n.is_boolean();
        } else if constexpr (std::is_integral_v<T>) {
            if (n.is_number_unsigned())
                return n.get<std::uint64_t>() <=
                       static_cast<std::uint64_t>(std::numeric_limits<T>::max());
            if (!n.is_number_integer() || std::is_unsigned_v<T>) return false;
            const auto v = n.get<std::int64_t>();
            return v >= static_cast<std::int64_t>(std::numeric_limits<T>::min()) &&
                   v <= static_cast<std::int64_t>(std::numeric_limits<T>::max());
        } else if constexpr (std::is_same_v<T, double>) {
            return n.is_number() && std::isfinite(n.get<double>());
        } else if constexpr (std::is_same_v<T, std::string>) {
            return n.is_string();
        } else {
            if (!n.is_array()) return false;
            for (const auto& e : n)
                if (!holds<typename T::value_type>(e)) return false;
            return true;
        }
    }
    template <class T>
    static std::string expected() {
        if constexpr (std::is_same_v<T, bool>) return "true or false";
        else if constexpr (std::is_integral_v<T>)
            return std::is_unsigned_v<T> ? "a whole number >= 0" : "a whole number";
        else if constexpr (std::is_same_v<T, double>) return "a finite number";
        else if constexpr (std::is_same_v<T, std::string>) return "a string";
        else return "a list, each " + expected<typename T::value_type>();
    }
    /// n as JSON text, at most 80 characters of it.
    static std::string shown(const nlohmann::json& n);

    const nlohmann::json& j_;
    SourceLocation at_;
    std::string prefix_;
    std::string context_;
};

}  // namespace freestand::core
