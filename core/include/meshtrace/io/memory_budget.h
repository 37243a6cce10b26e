#pragma once
// Memory as a checked resource. A run plans what each phase will allocate
// (the mesh arrays while they load, the BVH before it is built, the image
// before it is rendered) against a limit, and refuses with a message that
// names the phase and the sizes before it allocates beyond it. Running out
// anyway (the plan is an estimate) is caught per phase as well:
// MemoryLimitError::outOfMemory turns a std::bad_alloc into the same kind
// of message.
#include <atomic>
#include <cstdint>
#include <new>
#include <stdexcept>
#include <string>
#include <string_view>

namespace meshtrace {

class LoadObserver;

class MemoryLimitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;

  // What to say when `phase` ("load", "build", "render", "write") ran out
  // of memory doing `what`, planned at about `bytes`.
  static MemoryLimitError outOfMemory(std::string_view phase, const std::string& what,
                                      std::uint64_t bytes);
};

class MemoryBudget {
 public:
  explicit MemoryBudget(std::uint64_t limitBytes) : limit_(limitBytes) {}

  std::uint64_t limit() const { return limit_; }
  std::uint64_t planned() const { return planned_.load(); }

  // Adds `bytes` to the plan for what `phase` ("load", "build", "render",
  // "write": a verb) does to `what` (e.g. "the BVH of 1000000 triangles"). Throws MemoryLimitError
  // naming them, the plan and the limit if the plan would then exceed the limit (and plans
  // nothing). Safe to call from several threads: meshes load side by side.
  void reserve(std::uint64_t bytes, std::string_view phase, const std::string& what);
  // Takes back what was reserved for memory that is freed.
  void release(std::uint64_t bytes);

  // The budget goes wherever a load goes, down to each mesh reader, so it
  // also carries who watches the load's progress: `observer` (not owned;
  // nullptr for none, the default) from now on.
  void setLoadObserver(LoadObserver* observer) { observer_ = observer; }
  LoadObserver* loadObserver() const { return observer_; }

 private:
  std::uint64_t limit_;
  LoadObserver* observer_ = nullptr;
  std::atomic<std::uint64_t> planned_{0};
};

// Runs `step`, what `phase` does to `what` (planned at about `bytes`), and
// turns running out of memory in it into MemoryLimitError::outOfMemory.
template <typename Step>
decltype(auto) withinMemory(std::string_view phase, const std::string& what, std::uint64_t bytes,
                            Step&& step) {
  try {
    return step();
  } catch (const std::bad_alloc&) {
    throw MemoryLimitError::outOfMemory(phase, what, bytes);
  } catch (const std::length_error&) {  // a container asked for more than it can hold
    throw MemoryLimitError::outOfMemory(phase, what, bytes);
  }
}

// The physical memory of the machine, or the memory limit of its cgroup if
// that is smaller.
std::uint64_t physicalMemoryBytes();
// What a run may use unless told otherwise: three quarters of physical
// memory (the rest is the system's and other programs'), and under an
// address-space limit (ulimit -v) at most three quarters of what this
// process has left of it (its threads, stacks and allocator arenas take
// address space the plan does not count).
std::uint64_t defaultMemoryLimit();

// Under an address-space limit (ulimit -v), how many worker threads (each
// with its stack) fit in half of what this process has left of it; -1
// without a limit. A thread that cannot be created ends the process, so
// the tools cap their parallelism to this before any parallel work.
int workerThreadsTheAddressSpaceAllows();

// "512 MB", "1.5 GB": bytes for messages, in units of 2^20 and 2^30.
std::string formatBytes(std::uint64_t bytes);
// Reads a size such as "2G", "512M", "1.5GB", "800MiB", "64k" or "123456"
// (bytes; K, M, G, T in powers of 1024). Throws std::invalid_argument.
std::uint64_t parseByteSize(std::string_view text);

}  // namespace meshtrace
