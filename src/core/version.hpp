#pragma once
/// freestand's version: CMake's project(VERSION), compiled into one generated translation unit
/// (cmake/version.cpp.in), so a new version rebuilds that file only.

namespace freestand::core {

/// "MAJOR.MINOR.PATCH".
const char* version();

}  // namespace freestand::core
