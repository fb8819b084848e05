// Fuzz target: the TOML case reader. Target files and seed records it names resolve against a
// folder that does not exist, so no file is read; only freestand's own errors may escape.
#include <cstdint>
#include <string>

#include "assess/case.hpp"
#include "core/errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        freestand::assess::parse_case(text, "/nonexistent-fuzz-dir/case.toml");
    } catch (const freestand::Error&) {
    }
    return 0;
}
