#include "parameter_names.hpp"

namespace freestand::python {

const std::map<std::string, std::string>& keyword_names() {
    static const std::map<std::string, std::string> names{
        // api::ClassifyRequest
        {"mu_s", "mu"},
        {"a_h_g", "a_g"},
        {"av_g", "av_g"},
        // api::FragilityRequest (its pga_g is the binding's to name: fragility's keyword is pga)
        {"samples", "samples"},
        {"pool", "pool"},
        {"seed", "seed"},
        {"threads", "threads"},
        {"cache", "cache"},
        // sliding::BoxSpec, behind block= , cg= and inertia=
        {"b (half-width, m)", "block['b']"},
        {"h (half-height, m)", "block['h']"},
        {"m", "block['m']"},
        {"cg x", "cg['x']"},
        {"cg h", "cg['h']"},
        {"inertia", "inertia"},
    };
    return names;
}

InputError in_python(const InputError& e) {
    const SourceLocation& w = e.where();
    if (!w.file.empty() || w.line != 0) return e;
    const auto it = keyword_names().find(w.field);
    if (it == keyword_names().end()) return e;
    return InputError(SourceLocation{"", 0, it->second}, e.message());
}

}  // namespace freestand::python
