// Fuzz target: the target-spectrum CSV reader. Only freestand's own errors may escape.
#include <cstdint>
#include <string>

#include "core/errors.hpp"
#include "spectra/spectrum.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        freestand::spectra::parse_spectrum_csv(text, "fuzz.csv");
    } catch (const freestand::Error&) {
    }
    return 0;
}
