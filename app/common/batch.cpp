#include "common/batch.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <new>
#include <stdexcept>
#include <system_error>

#include "meshtrace/io/image.h"
#include "meshtrace/io/input_error.h"
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

bool reportDestinationUsable(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  try {
    if (ec)
      throw std::runtime_error(dir.string() + ": cannot create the folder (" + ec.message() + ")");
    checkOutputDestination(dir / "report.md");
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return false;
  }
  return true;
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

std::optional<Scene> loadAndDescribe(const std::filesystem::path& file) {
  const auto start = std::chrono::steady_clock::now();
  try {
    Scene scene = loadScene(file);
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
  } catch (const std::bad_alloc&) {
    // Files within the size limits can still need more memory than the
    // machine has: say so rather than abort.
    std::fprintf(stderr, "error: %s: not enough memory to load the scene\n", file.string().c_str());
    return std::nullopt;
  }
}

int runOverFolder(const std::filesystem::path& dir, const std::filesystem::path& outDir,
                  const std::string& prefix, const std::function<bool(const Scene&)>& wanted,
                  const std::function<bool(const Scene&, const std::filesystem::path&)>& job) {
  if (!std::filesystem::is_directory(dir)) {
    std::fprintf(stderr, "error: %s: not a folder\n", dir.string().c_str());
    return 1;
  }
  std::error_code ec;
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
  for (const auto& file : scenes) {
    std::optional<Scene> scene = loadAndDescribe(file);
    if (!scene) {
      ++failures;
      continue;
    }
    if (!wanted(*scene)) continue;
    const auto out = outDir / (prefix + file.stem().string() + ".png");
    if (imageDestinationUsable(out) && job(*scene, out))
      ++done;
    else
      ++failures;
  }
  std::printf("%d scenes written to %s, %d failed\n", done, outDir.string().c_str(), failures);
  return failures == 0 ? 0 : 1;
}

}  // namespace meshtrace::app
