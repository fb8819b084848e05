#pragma once
/// The commit outputs are stamped with (freestand_build_commit, linked by the front-ends).

namespace freestand::api {

/// Short commit of the source tree at build time, "-dirty" appended when tracked files had
/// changed, "unknown" outside git; written by cmake/commit_stamp.cmake on every build.
extern const char* const build_commit;

}  // namespace freestand::api
