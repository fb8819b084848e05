#pragma once
/// Where the tests find the project and the built tool. The paths live in one generated
/// translation unit (cmake/test_paths.cpp.in), so no other test object carries an absolute path
/// and a new clone's build reuses the compiler cache.
#include <string>

namespace freestand::test {

/// The project's root (cases/, spectra/, templates/).
const std::string& source_dir();
/// tests/data.
const std::string& data_dir();
/// The built freestand executable.
const std::string& exe();
/// ../shared beside the project (absent in a clone without it).
const std::string& shared_dir();

}  // namespace freestand::test
