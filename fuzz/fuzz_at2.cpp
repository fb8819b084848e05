// Fuzz target: the PEER NGA .AT2 reader. Only freestand's own errors may escape.
#include <cstdint>
#include <string>

#include "core/errors.hpp"
#include "core/readers.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        freestand::core::parse_at2(text, "fuzz.AT2");
    } catch (const freestand::Error&) {
    }
    return 0;
}
