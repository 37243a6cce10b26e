#include "meshtrace/io/memory_budget.h"

#include <sys/resource.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>

namespace meshtrace {

namespace {

// The part of physical memory, or of the address space left, a run takes
// by default.
constexpr double kDefaultShare = 0.75;
// The address space each worker thread takes besides what the plan counts:
// its stack (8 MiB by default) and some room for its allocations. (Under
// an address-space limit the tools keep every thread in the main malloc
// arena: see app::fitWorkersToAddressSpace.)
constexpr std::uint64_t kAddressSpacePerThread = std::uint64_t{16} << 20;

std::uint64_t addressSpaceInUse() {
  std::ifstream statm("/proc/self/statm");
  std::uint64_t pages = 0;
  statm >> pages;
  return pages * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
}

}  // namespace

MemoryLimitError MemoryLimitError::outOfMemory(std::string_view phase, const std::string& what,
                                               std::uint64_t bytes) {
  const std::string planned = bytes > 0 ? " (planned at about " + formatBytes(bytes) + ")" : "";
  return MemoryLimitError("not enough memory to " + std::string(phase) + " " + what + planned +
                          ": the system refused an allocation");
}

void MemoryBudget::reserve(std::uint64_t bytes, std::string_view phase, const std::string& what) {
  std::uint64_t planned = planned_.load();
  do {
    if (bytes > limit_ || planned > limit_ - bytes) {
      const std::uint64_t total = bytes > ~planned ? ~std::uint64_t{0} : planned + bytes;
      throw MemoryLimitError("cannot " + std::string(phase) + " " + what + ": it needs about " +
                             formatBytes(bytes) + " more, " + formatBytes(total) +
                             " in all, over the limit of " + formatBytes(limit_));
    }
  } while (!planned_.compare_exchange_weak(planned, planned + bytes));
}

void MemoryBudget::release(std::uint64_t bytes) {
  std::uint64_t planned = planned_.load();
  while (!planned_.compare_exchange_weak(planned, planned - std::min(planned, bytes))) {
  }
}

std::uint64_t physicalMemoryBytes() {
  std::uint64_t bytes = static_cast<std::uint64_t>(::sysconf(_SC_PHYS_PAGES)) *
                        static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
  std::ifstream cgroup("/sys/fs/cgroup/memory.max");  // "max" when unlimited
  std::uint64_t cgroupLimit = 0;
  if (cgroup >> cgroupLimit && cgroupLimit > 0) bytes = std::min(bytes, cgroupLimit);
  return bytes;
}

std::uint64_t defaultMemoryLimit() {
  auto limit =
      static_cast<std::uint64_t>(kDefaultShare * static_cast<double>(physicalMemoryBytes()));
  rlimit as{};
  if (::getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) {
    const auto workers = static_cast<std::uint64_t>(tbb::this_task_arena::max_concurrency() - 1);
    const std::uint64_t used = addressSpaceInUse() + workers * kAddressSpacePerThread;
    const std::uint64_t left = as.rlim_cur > used ? as.rlim_cur - used : 0;
    limit = std::min(limit, static_cast<std::uint64_t>(kDefaultShare * static_cast<double>(left)));
  }
  return limit;
}

int workerThreadsTheAddressSpaceAllows() {
  rlimit as{};
  if (::getrlimit(RLIMIT_AS, &as) != 0 || as.rlim_cur == RLIM_INFINITY) return -1;
  const std::uint64_t used = addressSpaceInUse();
  const std::uint64_t left = as.rlim_cur > used ? as.rlim_cur - used : 0;
  return static_cast<int>(std::min<std::uint64_t>(left / 2 / kAddressSpacePerThread, 1024));
}

std::string formatBytes(std::uint64_t bytes) {
  char buffer[32];
  const double mib = static_cast<double>(bytes) / (1 << 20);
  if (mib >= 1024.0)
    std::snprintf(buffer, sizeof buffer, "%.1f GB", mib / 1024.0);
  else if (mib >= 10.0)
    std::snprintf(buffer, sizeof buffer, "%.0f MB", mib);
  else
    std::snprintf(buffer, sizeof buffer, "%.1f MB", mib);
  return buffer;
}

std::uint64_t parseByteSize(std::string_view text) {
  const auto bad = [&] {
    throw std::invalid_argument("'" + std::string(text) +
                                "' is not a size (examples: 2G, 512M, 800MiB, 123456)");
  };
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || !(value >= 0.0)) bad();
  std::string unit(end, text.data() + text.size());
  for (char& c : unit) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (unit.size() >= 2 && unit.substr(unit.size() - 2) == "IB")
    unit.resize(unit.size() - 2);
  else if (unit.size() >= 2 && unit.back() == 'B')
    unit.pop_back();
  int shift = 0;
  if (unit == "K")
    shift = 10;
  else if (unit == "M")
    shift = 20;
  else if (unit == "G")
    shift = 30;
  else if (unit == "T")
    shift = 40;
  else if (!unit.empty() && unit != "B")
    bad();
  const double bytes = std::ldexp(value, shift);
  if (!(bytes < 0x1p63)) bad();
  return static_cast<std::uint64_t>(bytes);
}

}  // namespace meshtrace
