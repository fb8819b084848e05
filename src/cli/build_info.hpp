#pragma once
/// Facts about the build that outputs are stamped with.
namespace freestand::cli {

/// Short commit of the source tree at build time ("unknown" outside git); written by
/// cmake/commit_stamp.cmake on every build.
extern const char* const build_commit;

}  // namespace freestand::cli
