#include "meshtrace/util/shard.h"

#include <charconv>
#include <cstdlib>
#include <stdexcept>

namespace meshtrace {

namespace {
bool parseCount(std::string_view text, std::size_t& out) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc() && end == text.data() + text.size() && !text.empty();
}
// A Slurm array variable, or nothing if it is not set.
std::optional<std::size_t> slurmCount(const char* name) {
  const char* value = std::getenv(name);
  if (!value) return std::nullopt;
  std::size_t n = 0;
  if (!parseCount(value, n))
    throw std::invalid_argument(std::string(name) + " is '" + value + "', not a count");
  return n;
}
}  // namespace

Shard parseShard(std::string_view text) {
  const std::size_t slash = text.find('/');
  Shard s;
  if (slash == std::string_view::npos || !parseCount(text.substr(0, slash), s.index) ||
      !parseCount(text.substr(slash + 1), s.count) || s.count == 0 || s.index >= s.count)
    throw std::invalid_argument("'" + std::string(text) +
                                "' is not a share I/N with 0 <= I < N (e.g. 0/4)");
  return s;
}

std::optional<Shard> slurmArrayShard() {
  const auto id = slurmCount("SLURM_ARRAY_TASK_ID");
  const auto count = slurmCount("SLURM_ARRAY_TASK_COUNT");
  if (!id || !count) return std::nullopt;
  const std::size_t first = slurmCount("SLURM_ARRAY_TASK_MIN").value_or(0);
  if (*id < first || *id - first >= *count || *count == 0)
    throw std::invalid_argument("SLURM_ARRAY_TASK_ID " + std::to_string(*id) +
                                " is outside the array of " + std::to_string(*count) +
                                " tasks from " + std::to_string(first));
  return Shard{*id - first, *count};
}

}  // namespace meshtrace
