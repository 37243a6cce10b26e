#pragma once
// One share of a batch (raytrace --all or --report with --shard I/N): the
// items whose index in the sorted list is I modulo N, so that N runs, on
// one machine or many, cover every item once between them.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace meshtrace {

struct Shard {
  std::size_t index = 0;
  std::size_t count = 1;

  bool owns(std::size_t item) const { return item % count == index; }
  std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
};

// "I/N" with 0 <= I < N; throws std::invalid_argument.
Shard parseShard(std::string_view text);

// A Slurm job array task's share: SLURM_ARRAY_TASK_ID -
// SLURM_ARRAY_TASK_MIN of SLURM_ARRAY_TASK_COUNT, or nothing outside an
// array. Throws std::invalid_argument if they are malformed.
std::optional<Shard> slurmArrayShard();

}  // namespace meshtrace
