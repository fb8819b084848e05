// Fuzz target: the CSV record reader. Only freestand's own errors may escape.
#include <cstdint>
#include <string>

#include "core/errors.hpp"
#include "core/readers.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        freestand::core::parse_csv(text, "fuzz.csv");
    } catch (const freestand::Error&) {
    }
    return 0;
}
