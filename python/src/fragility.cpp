// fragility: typed arguments to api::FragilityRequest, the result as fragility.json's tree.
#include <pybind11/stl.h>

#include <array>
#include <optional>

#include "api/fragility.hpp"
#include "bindings.hpp"
#include "api/build_commit.hpp"
#include "convert.hpp"
#include "core/content_store.hpp"
#include "core/errors.hpp"

namespace freestand::python {

namespace fragility_binding {

/// The levels the caller named, fragility::Config's "pga_g" named `pga`, the keyword.
InputError as_pga(const InputError& e) {
    if (e.where().field != "pga_g" || !e.where().file.empty()) return e;
    return InputError(SourceLocation{"", 0, "pga"}, e.message());
}

api::FragilityRequest request(const std::string& case_file, const std::vector<double>& pga_g,
                              const std::optional<std::array<double, 3>>& pga_range, int samples,
                              int pool, std::optional<long long> seed,
                              const std::vector<std::string>& records, int threads,
                              const std::optional<std::string>& cache, bool no_cache,
                              bool case_models) {
    api::FragilityRequest r;
    r.case_file = case_file;
    r.pga_g = pga_range ? api::pga_range((*pga_range)[0], (*pga_range)[1], (*pga_range)[2])
                        : pga_g;
    r.samples = samples;
    r.pool = pool;
    if (seed) {
        // The command line's range for a seed: whole numbers a double holds exactly.
        require_in_range(static_cast<double>(*seed), 0.0, 9.0e15, SourceLocation{"", 0, "seed"});
        r.seed = static_cast<std::uint64_t>(*seed);
    }
    r.record_files = records;
    r.case_models = case_models;
    r.threads = threads;
    if (cache && no_cache)
        throw InputError(SourceLocation{"", 0, "cache"}, "a cache folder with no_cache=True");
    if (cache) r.cache_dir = *cache;
    else if (!no_cache) r.cache_dir = core::default_cache_dir();
    r.commit = api::build_commit;
    return r;
}

}  // namespace fragility_binding

void bind_fragility(py::module_& m) {
    m.def(
        "fragility",
        [](const std::string& case_file, const std::vector<double>& pga_g,
           const std::optional<std::array<double, 3>>& pga_range, int samples, int pool,
           std::optional<long long> seed, const std::vector<std::string>& records, int threads,
           const std::optional<std::string>& cache, bool no_cache, bool case_models) {
            api::FragilityResult result;
            try {
                const api::FragilityRequest request = fragility_binding::request(
                    case_file, pga_g, pga_range, samples, pool, seed, records, threads, cache,
                    no_cache, case_models);
                py::gil_scoped_release unlocked;
                result = api::fragility(request);
            } catch (const InputError& e) {
                throw fragility_binding::as_pga(e);
            }
            return to_python(api::to_json(result), Arrays::lists);
        },
        py::arg("case_file"), py::arg("pga_g"), py::arg("pga_range"), py::arg("samples"),
        py::arg("pool"), py::arg("seed"), py::arg("records"), py::arg("threads"),
        py::arg("cache"), py::arg("no_cache"), py::arg("case_models"));
}

}  // namespace freestand::python
