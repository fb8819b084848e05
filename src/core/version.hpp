#pragma once
/// freestand's version and the build's identity, compiled into one generated translation unit
/// (cmake/version.cpp.in), so a new version or build setting rebuilds that file only.

namespace freestand::core {

/// "MAJOR.MINOR.PATCH".
const char* version();

/// What the build's floating-point results depend on besides the sources: the compiler and its
/// version, the processor, the build type with its flags, and whether the sanitizers are in.
/// Two builds with different identities may round differently (another compiler's complex
/// division, say), so the history cache keeps their sets apart.
const char* build_identity();

}  // namespace freestand::core
