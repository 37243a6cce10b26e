#include "common/shard.h"

#include <cstdio>
#include <stdexcept>

namespace meshtrace::app {

std::optional<Shard> shardToRun(const std::string& option) {
  try {
    if (!option.empty()) return parseShard(option);
    return slurmArrayShard().value_or(Shard{});
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "error: --shard: %s\n", e.what());
    return std::nullopt;
  }
}

}  // namespace meshtrace::app
