#include "report/regress.hpp"

#include <nlohmann/json.hpp>
#include <algorithm>
#include <cmath>

namespace freestand::report {

namespace {

using json = nlohmann::ordered_json;

void compare(const json& a, const json& b, const std::string& path, double rtol,
             std::vector<Difference>& out) {
    if (a.is_number() && b.is_number()) {
        const double x = a.get<double>();
        const double y = b.get<double>();
        if (std::abs(x - y) > rtol * std::max(std::abs(x), std::abs(y)))
            out.push_back({path, a.dump(), b.dump()});
        return;
    }
    if (a.type() != b.type()) {
        out.push_back({path, a.dump(), b.dump()});
        return;
    }
    if (a.is_object()) {
        for (const auto& [key, value] : a.items()) {
            const std::string p = path + "/" + key;
            if (path.empty() && key == "stamp") continue;
            if (!b.contains(key)) {
                out.push_back({p, value.dump(), "(missing)"});
            } else {
                compare(value, b.at(key), p, rtol, out);
            }
        }
        for (const auto& [key, value] : b.items()) {
            if (!a.contains(key) && !(path.empty() && key == "stamp"))
                out.push_back({path + "/" + key, "(missing)", value.dump()});
        }
        return;
    }
    if (a.is_array()) {
        if (a.size() != b.size()) {
            out.push_back({path + "/length", std::to_string(a.size()), std::to_string(b.size())});
            return;
        }
        for (std::size_t i = 0; i < a.size(); ++i)
            compare(a[i], b[i], path + "/" + std::to_string(i), rtol, out);
        return;
    }
    if (a != b) out.push_back({path, a.dump(), b.dump()});
}

}  // namespace

std::vector<Difference> compare_results(const json& golden, const json& fresh, double rtol) {
    std::vector<Difference> out;
    compare(golden, fresh, "", rtol, out);
    return out;
}

}  // namespace freestand::report
