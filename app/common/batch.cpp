#include "common/batch.h"

#include <malloc.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <new>
#include <stdexcept>
#include <string>
#include <system_error>

#include "common/load_progress.h"
#include "common/progress.h"
#include "formats/openmesh_reader.h"
#include "meshtrace/io/image.h"
#include "meshtrace/io/input_error.h"
#include "meshtrace/io/mesh_reader.h"
#include "meshtrace/io/mesh_scene.h"
#include "meshtrace/io/output_file.h"
#include "meshtrace/io/scene_parser.h"

namespace meshtrace::app {

bool imageDestinationUsable(const std::filesystem::path& path) {
  try {
    checkImageDestination(path);
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return false;
  }
  return true;
}

ReportFolder::ReportFolder(const std::filesystem::path& dir) : dir_(dir) {
  std::error_code ec;
  // The outermost of the folders missing on the way to `dir` (none when a
  // folder on the way cannot be looked at).
  for (std::filesystem::path p = std::filesystem::absolute(dir, ec).lexically_normal();
       !ec && !p.empty(); p = p.parent_path()) {
    const bool there = std::filesystem::exists(p, ec);
    if (ec || there) break;
    topMade_ = p;
    if (p == p.parent_path()) break;
  }
  ec.clear();
  std::filesystem::create_directories(dir, ec);
  try {
    if (ec)
      throw std::runtime_error(dir.string() + ": cannot create the folder (" + ec.message() + ")");
    checkOutputDestination(dir / "report.md");
    usable_ = true;
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
  }
}

ReportFolder::~ReportFolder() {
  if (kept_ || topMade_.empty()) return;
  // Innermost first; remove() takes only an empty folder, so anything
  // written there since (by another process, too) stops it.
  std::error_code ec;
  std::filesystem::path p = std::filesystem::absolute(dir_, ec).lexically_normal();
  for (; !ec; p = p.parent_path()) {
    if (!std::filesystem::remove(p, ec) || p == topMade_) break;
  }
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

std::vector<std::filesystem::path> findScenes(const std::filesystem::path& dir,
                                              std::error_code& ec) {
  namespace fs = std::filesystem;
  std::vector<fs::path> scenes;
  fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec);
  for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (it->is_regular_file(ec) && it->path().extension() == ".sce") scenes.push_back(it->path());
  }
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

void fitWorkersToAddressSpace() {
  // Never destroyed: its destructor at exit would start TBB's thread
  // management, which aborts if it cannot make a thread.
  static const tbb::global_control* threads = nullptr;
  const int workers = workerThreadsTheAddressSpaceAllows();
  if (workers >= 0 && !threads) {
    threads = new tbb::global_control(tbb::global_control::max_allowed_parallelism,
                                      static_cast<std::size_t>(workers) + 1);
    // One malloc arena for every thread. A thread's first allocation
    // otherwise reserves an arena of its own (64 MiB of address space)
    // whenever the limit leaves room for it, and whether a worker allocates
    // before the main thread's plan is spent depends on scheduling: the
    // same run could then end in a refused allocation the plan did not
    // foresee, instead of rendering or being refused by the plan.
    mallopt(M_ARENA_MAX, 1);
  }
}

std::optional<std::uint64_t> memoryLimit(const std::string& option) {
  if (option.empty()) return defaultMemoryLimit();
  try {
    return parseByteSize(option);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "error: --max-memory: %s\n", e.what());
    return std::nullopt;
  }
}

std::uint64_t peakResidentBytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    unsigned long long kb = 0;
    if (std::sscanf(line.c_str(), "VmHWM: %llu kB", &kb) == 1) return kb * 1024;
  }
  return 0;
}

void printMemoryError(const std::filesystem::path& scene, const MemoryLimitError& e) {
  std::fprintf(stderr, "error: %s: %s (--max-memory sets the limit)\n", scene.string().c_str(),
               e.what());
}

std::uint64_t imageBytes(int width, int height) {
  return static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height) *
         (sizeof(Color) + 3);
}

namespace {
// ".off, .om, .ply": the mesh files the tools read.
std::string extensionList() {
  std::string out;
  for (const std::string& e : meshExtensions()) out += (out.empty() ? "" : ", ") + e;
  return out;
}
}  // namespace

std::optional<Scene> loadAndDescribe(const std::filesystem::path& file, MemoryBudget& budget) {
  const auto start = std::chrono::steady_clock::now();
  formats::registerOpenMeshFormats();
  try {
    Scene scene = [&] {
      // Its line is wiped before anything else is printed: "loaded ..." or
      // the error, which must not be glued onto a half-drawn line.
      LoadProgress progress;
      budget.setLoadObserver(&progress);
      const struct Unwatch {
        MemoryBudget& budget;
        ~Unwatch() { budget.setLoadObserver(nullptr); }
      } unwatch{budget};
      return isMeshFile(file) && !isSceneFile(file) ? loadMeshAsScene(file, budget)
                                                    : loadScene(file, budget);
    }();
    for (const std::string& w : scene.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    std::printf(
        "loaded %s: %zu objects (%zu spheres, %zu planes, %zu cylinders, %zu meshes), "
        "%zu triangles, %zu lights in %.1f ms\n",
        file.string().c_str(), scene.objectCount(), scene.spheres.size(), scene.planes.size(),
        scene.cylinders.size(), scene.meshes.size(), scene.triangleCount(), scene.lights.size(),
        millisecondsSince(start));
    return scene;
  } catch (const InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return std::nullopt;
  } catch (const MemoryLimitError& e) {
    printMemoryError(file, e);
    return std::nullopt;
  } catch (const std::bad_alloc&) {
    // What was planned when the allocation failed: the arrays loaded so far.
    printMemoryError(file, MemoryLimitError::outOfMemory("load", "the scene", budget.planned()));
    return std::nullopt;
  }
}

bool printMeshScene(const std::filesystem::path& mesh, std::uint64_t memoryLimit) {
  formats::registerOpenMeshFormats();
  MemoryBudget budget(memoryLimit);
  try {
    if (isSceneFile(mesh) || !isMeshFile(mesh))
      throw InputError::inFile(mesh, "not a mesh file (one of " + extensionList() + ")");
    std::fputs(meshSceneText(mesh, budget).c_str(), stdout);
    return true;
  } catch (const InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
  } catch (const MemoryLimitError& e) {
    printMemoryError(mesh, e);
  }
  return false;
}

int runOverFolder(const std::filesystem::path& dir, const std::filesystem::path& outDir,
                  const std::string& prefix, std::uint64_t memoryLimit,
                  const std::function<bool(const Scene&)>& wanted, const SceneJob& job,
                  const Shard& shard) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) {
    // A symlink loop or a missing folder is said as such, not as "not a folder".
    std::fprintf(stderr, "error: %s: %s\n", dir.string().c_str(),
                 ec ? ec.message().c_str() : "not a folder");
    return 1;
  }
  std::filesystem::create_directories(outDir, ec);
  if (ec) {
    std::fprintf(stderr, "error: %s: cannot create the output folder (%s)\n",
                 outDir.string().c_str(), ec.message().c_str());
    return 1;
  }
  const auto scenes = findScenes(dir, ec);
  if (ec) {
    std::fprintf(stderr, "error: %s: cannot list the folder (%s)\n", dir.string().c_str(),
                 ec.message().c_str());
    return 1;
  }
  if (scenes.empty()) {
    std::fprintf(stderr, "error: %s: no .sce files found\n", dir.string().c_str());
    return 1;
  }
  int failures = 0, done = 0;
  std::vector<std::filesystem::path> share;
  for (std::size_t i = 0; i < scenes.size(); ++i)
    if (shard.owns(i)) share.push_back(scenes[i]);
  Progress progress("scene", share.size());
  for (std::size_t i = 0; i < share.size(); ++i) {
    const auto& file = share[i];
    progress.update(i, file.filename().string());
    MemoryBudget budget(memoryLimit);
    std::optional<Scene> scene = loadAndDescribe(file, budget);
    if (!scene) {
      ++failures;
      continue;
    }
    if (!wanted(*scene)) continue;
    const auto out = outDir / (prefix + file.stem().string() + ".png");
    if (imageDestinationUsable(out) && job(*scene, out, budget))
      ++done;
    else
      ++failures;
  }
  std::printf("%d scenes written to %s, %d failed%s\n", done, outDir.string().c_str(), failures,
              shard.count > 1 ? (" (share " + shard.text() + " of " +
                                 std::to_string(scenes.size()) + " scenes)")
                                    .c_str()
                              : "");
  return failures == 0 ? 0 : 1;
}

}  // namespace meshtrace::app
