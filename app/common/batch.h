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

#include "meshtrace/geometry/scene.h"

namespace meshtrace::app {

// Every .sce file below `dir`, sorted by path. Unreadable subfolders are
// skipped; `ec` reports a folder that could not be listed at all.
std::vector<std::filesystem::path> findScenes(const std::filesystem::path& dir,
                                              std::error_code& ec);

// Loads a scene, prints its warnings and a one-line summary with the load
// time. Prints the error and returns nothing on bad input.
std::optional<Scene> loadAndDescribe(const std::filesystem::path& file);

// Runs `job(scene, outputPath)` for each scene under `dir` that `wanted`
// accepts, writing to outDir/<prefix><stem>.png once that path is known to
// be writable (imageDestinationUsable). Returns the process exit code: 0 if
// every scene succeeded.
int runOverFolder(const std::filesystem::path& dir, const std::filesystem::path& outDir,
                  const std::string& prefix, const std::function<bool(const Scene&)>& wanted,
                  const std::function<bool(const Scene&, const std::filesystem::path&)>& job);

// Whether an image could be written to `path` (checkImageDestination);
// prints the error if not. Tools call it before loading and rendering, so
// that neither is spent on an output that cannot be written.
bool imageDestinationUsable(const std::filesystem::path& path);

// Whether `raytrace --report` could write into `dir` (created if missing);
// prints the error if not, before the measurements.
bool reportDestinationUsable(const std::filesystem::path& dir);

// Milliseconds since `start`, for timing lines.
double millisecondsSince(std::chrono::steady_clock::time_point start);

}  // namespace meshtrace::app
