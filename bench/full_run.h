#pragma once
// Whole runs (load, build, render, write), as `raytrace SCENE OUT.png` makes
// them, each in a process of its own. Run side by side in one process, the
// engines would share its memory state (a run finds the huge pages the one
// before it freed), so the figure would measure the order of the runs as
// much as the engines.
#include <filesystem>
#include <string>

namespace meshtrace::bench {

// "bvh", "aabb" or "none" for ours, or "embree".
using Engine = std::string;

// Milliseconds of a whole run of `scene` by `engine`, in a child process
// (this executable with --full-run), image written to `image`. Throws
// std::runtime_error if the child fails.
double fullRunMs(const Engine& engine, const std::filesystem::path& scene,
                 const std::filesystem::path& image, int threads);

// The child's side: the run itself, in this process, in milliseconds.
double fullRunHereMs(const Engine& engine, const std::filesystem::path& scene,
                     const std::filesystem::path& image, int threads);

}  // namespace meshtrace::bench
