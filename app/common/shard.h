#pragma once
// The share of a batch this run takes (meshtrace/util/shard.h): from
// --shard, or from a Slurm job array task.
#include <optional>
#include <string>

#include "meshtrace/util/shard.h"

namespace meshtrace::app {

// The share to run: --shard's value if given, else a Slurm job array
// task's (SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN of
// SLURM_ARRAY_TASK_COUNT), else all of it. Prints the error and returns
// nothing if either is malformed.
std::optional<Shard> shardToRun(const std::string& option);

}  // namespace meshtrace::app
