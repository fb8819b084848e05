// Fuzz target: a batch's equipment list, as CSV and as TOML (batch/list.hpp). Case paths are
// only resolved, never read; only freestand's own errors may escape.
#include <cstdint>
#include <string>

#include "batch/list.hpp"
#include "core/errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        freestand::batch::parse_csv_list(text, "/nonexistent-fuzz-dir/list.csv");
    } catch (const freestand::Error&) {
    }
    try {
        freestand::batch::parse_toml_list(text, "/nonexistent-fuzz-dir/list.toml");
    } catch (const freestand::Error&) {
    }
    return 0;
}
