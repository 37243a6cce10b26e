// debug_aabb: per pixel, how many mesh bounding boxes the primary ray meets.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/batch.h"
#include "common/progress.h"
#include "meshtrace/io/memory_budget.h"
#include "meshtrace/render/render.h"

using namespace meshtrace;

namespace {

bool writeDebugImage(const Scene& scene, const std::filesystem::path& out, MemoryBudget& budget) {
  const int w = scene.camera.width(), h = scene.camera.height();
  const std::string what =
      "the box counts of " + std::to_string(w) + "x" + std::to_string(h) + " pixels";
  // A count per pixel beside the image.
  const std::uint64_t bytes = app::imageBytes(w, h) + std::uint64_t{4} * w * h;
  try {
    budget.reserve(bytes, "render", what);
    int maxCount = 0;
    const Image8 pixels = withinMemory("render", what, bytes, [&] {
      const BoxHitCounts counts = countBoxHits(scene);
      maxCount = counts.maxCount;
      return quantize(debugAabbImage(counts));
    });
    withinMemory("write", out.string(), bytes, [&] { writeImage(pixels, out); });
    std::printf("wrote %s (at most %d boxes per pixel)\n", out.string().c_str(), maxCount);
  } catch (const MemoryLimitError& e) {
    app::printMemoryError(scene.file, e);
    return false;
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"Write the bounding-box debug image of .sce scenes."};
  bool all = false;
  std::vector<std::string> args;
  cli.add_flag(
      "--all", all,
      "Every scene with meshes under DIR (default scenes/) into OUTDIR (default results/)");
  cli.add_option("args", args, "SCENE.sce OUT.png, or with --all: [DIR] [OUTDIR]");
  std::string maxMemory;
  cli.add_option("--max-memory", maxMemory, app::kMaxMemoryHelp);
  bool quiet = false;
  cli.add_flag("--quiet", quiet, app::kQuietHelp);
  CLI11_PARSE(cli, argc, argv);
  if (quiet) app::setProgressShown(false);
  app::fitWorkersToAddressSpace();
  const std::optional<std::uint64_t> memoryLimit = app::memoryLimit(maxMemory);
  if (!memoryLimit) return 2;

  if (all) {
    if (args.size() > 2) {
      std::fprintf(stderr, "error: --all takes at most DIR and OUTDIR\n");
      return 2;
    }
    return app::runOverFolder(
        args.size() > 0 ? args[0] : "scenes", args.size() > 1 ? args[1] : "results", "debug_aabb_",
        *memoryLimit, [](const Scene& s) { return !s.meshes.empty(); }, writeDebugImage);
  }
  if (args.size() != 2) {
    std::fprintf(stderr, "error: expected SCENE.sce OUT.png (or --all)\n%s", cli.help().c_str());
    return 2;
  }
  if (!app::imageDestinationUsable(args[1])) return 1;
  MemoryBudget budget(*memoryLimit);
  const auto scene = app::loadAndDescribe(args[0], budget);
  if (!scene) return 1;
  return writeDebugImage(*scene, args[1], budget) ? 0 : 1;
}
