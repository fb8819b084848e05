#pragma once
/// The shard file's writer, as `batch --shard` takes it from the command line's headers: one
/// implementation, the library's (fragility/shard_file.hpp).
#include "fragility/shard_file.hpp"

namespace freestand::cli {

using fragility::write_shard;

}  // namespace freestand::cli
