// debug_aabb: per pixel, how many mesh bounding boxes the primary ray meets.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/batch.h"
#include "meshtrace/render/render.h"

using namespace meshtrace;

namespace {

bool writeDebugImage(const Scene& scene, const std::filesystem::path& out) {
  const BoxHitCounts counts = countBoxHits(scene);
  try {
    writeImage(quantize(debugAabbImage(counts)), out);
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return false;
  }
  std::printf("wrote %s (at most %d boxes per pixel)\n", out.string().c_str(), counts.maxCount);
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
  CLI11_PARSE(cli, argc, argv);

  if (all) {
    if (args.size() > 2) {
      std::fprintf(stderr, "error: --all takes at most DIR and OUTDIR\n");
      return 2;
    }
    return app::runOverFolder(
        args.size() > 0 ? args[0] : "scenes", args.size() > 1 ? args[1] : "results", "debug_aabb_",
        [](const Scene& s) { return !s.meshes.empty(); }, writeDebugImage);
  }
  if (args.size() != 2) {
    std::fprintf(stderr, "error: expected SCENE.sce OUT.png (or --all)\n%s", cli.help().c_str());
    return 2;
  }
  if (!app::imageDestinationUsable(args[1])) return 1;
  const auto scene = app::loadAndDescribe(args[0]);
  if (!scene) return 1;
  return writeDebugImage(*scene, args[1]) ? 0 : 1;
}
