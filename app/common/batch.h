#pragma once
// What the command-line tools share: finding scenes, loading one with a
// summary, and running a job over a folder of scenes.
#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "common/shard.h"
#include "meshtrace/geometry/scene.h"
#include "meshtrace/io/memory_budget.h"

namespace meshtrace::app {

// The help text of --max-memory, the same in every tool.
inline constexpr const char* kMaxMemoryHelp =
    "Memory one scene may use, e.g. 4G or 512M; refused beyond it before allocating "
    "(default: 3/4 of physical memory, less under ulimit -v)";

// Under an address-space limit (ulimit -v), caps TBB's worker threads to
// those whose stacks the limit leaves room for
// (workerThreadsTheAddressSpaceAllows): a thread TBB cannot create ends
// the process. Call before any parallel work and before memoryLimit(),
// whose default counts the workers' address space.
void fitWorkersToAddressSpace();

// The limit --max-memory gives ("" for defaultMemoryLimit()); prints the
// error and returns nothing if it is not a size.
std::optional<std::uint64_t> memoryLimit(const std::string& option);

// The most resident memory the process has had (the kernel's VmHWM), or 0
// where the kernel does not say. Unlike a parent's rusage of its child,
// it counts the tool alone: a forked child's ru_maxrss also holds the
// parent's resident memory at the fork.
std::uint64_t peakResidentBytes();

// Prints the error of a scene that needs more memory than it may use.
void printMemoryError(const std::filesystem::path& scene, const MemoryLimitError& e);

// What an image of width x height takes from its render to its file: the
// colours (24 bytes a pixel) and their 8-bit copy (3); the encoded file
// (up to 9 with the growth of its buffer) comes once the colours are freed.
std::uint64_t imageBytes(int width, int height);

// Every .sce file below `dir`, sorted by path. Unreadable subfolders are
// skipped; `ec` reports a folder that could not be listed at all.
std::vector<std::filesystem::path> findScenes(const std::filesystem::path& dir,
                                              std::error_code& ec);

// Loads a scene within `budget` (a mesh file is framed as one:
// loadMeshAsScene), prints its warnings and a one-line summary
// with the load time. Prints the error and returns nothing on bad input or
// when the scene needs more memory than the budget allows.
std::optional<Scene> loadAndDescribe(const std::filesystem::path& file, MemoryBudget& budget);

// Prints the .sce text a bare mesh file is rendered as (meshSceneText),
// to be saved beside it. Prints the error and returns false on bad input.
bool printMeshScene(const std::filesystem::path& mesh, std::uint64_t memoryLimit);

// What a tool does with one loaded scene, within the scene's budget.
using SceneJob =
    std::function<bool(const Scene&, const std::filesystem::path& out, MemoryBudget& budget)>;

// Runs `job` for each scene under `dir` that `wanted` accepts, each with a
// budget of its own of `memoryLimit` bytes, writing to
// outDir/<prefix><stem>.png once that path is known to be writable
// (imageDestinationUsable). Returns the process exit code: 0 if every scene
// succeeded.
// Only the scenes of `shard` (by their index in the sorted list) are run.
int runOverFolder(const std::filesystem::path& dir, const std::filesystem::path& outDir,
                  const std::string& prefix, std::uint64_t memoryLimit,
                  const std::function<bool(const Scene&)>& wanted, const SceneJob& job,
                  const Shard& shard = {});

// Whether an image could be written to `path` (checkImageDestination);
// prints the error if not. Tools call it before loading and rendering, so
// that neither is spent on an output that cannot be written.
bool imageDestinationUsable(const std::filesystem::path& path);

// The folder `raytrace --report` or `--report-merge` writes into, made at
// once so that an unusable destination is refused (the error printed)
// before the measurements. A run that fails before its report is written
// leaves no trace: unless kept, the folders this made are removed again
// while they are empty.
class ReportFolder {
 public:
  explicit ReportFolder(const std::filesystem::path& dir);
  ~ReportFolder();
  ReportFolder(const ReportFolder&) = delete;
  ReportFolder& operator=(const ReportFolder&) = delete;

  bool usable() const { return usable_; }
  // The report is written: the folder stays.
  void keep() { kept_ = true; }

 private:
  std::filesystem::path dir_;
  std::filesystem::path topMade_;  // the outermost folder this made, or empty
  bool usable_ = false, kept_ = false;
};

// Milliseconds since `start`, for timing lines.
double millisecondsSince(std::chrono::steady_clock::time_point start);

}  // namespace meshtrace::app
