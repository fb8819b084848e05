#pragma once
/// SHA-256 (FIPS 180-4) of a byte string, for the report's input stamp. Hand-written (about 60
/// lines) because no hashing library is among the project's dependencies; the hex digest equals
/// `sha256sum CASE.toml`, so a reader can check a report against the case file.
#include <string>
#include <string_view>

namespace freestand::core {

/// Lower-case hex digest, 64 characters.
std::string sha256_hex(std::string_view bytes);

}  // namespace freestand::core
