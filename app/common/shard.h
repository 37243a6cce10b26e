#pragma once
// One share of a batch (raytrace --all --shard I/N): the items whose index
// in the sorted list is I modulo N, so that N runs, on one machine or
// many, cover every item once between them.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace meshtrace::app {

struct Shard {
  std::size_t index = 0;
  std::size_t count = 1;

  bool owns(std::size_t item) const { return item % count == index; }
  std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
};

// "I/N" with 0 <= I < N; throws std::invalid_argument.
Shard parseShard(std::string_view text);

// The share to run: --shard's value if given, else a Slurm job array
// task's (SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN of
// SLURM_ARRAY_TASK_COUNT), else all of it. Prints the error and returns
// nothing if either is malformed.
std::optional<Shard> shardToRun(const std::string& option);

}  // namespace meshtrace::app
