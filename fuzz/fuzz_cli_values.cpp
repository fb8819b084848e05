// Fuzz target: the command-line value parsers (number lists, numbers, key=value lists). The
// first byte picks the parser; only freestand's own errors may escape.
#include <cstdint>
#include <string>

#include "cli/options.hpp"
#include "core/errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    try {
        switch (data[0] % 3) {
            case 0:
                freestand::cli::parse_double_list(text, "--fuzz");
                break;
            case 1:
                freestand::cli::parse_double(text, "--fuzz");
                break;
            default:
                freestand::cli::parse_key_values(text, "--fuzz", {"b", "h", "m"});
                break;
        }
    } catch (const freestand::Error&) {
    }
    return 0;
}
