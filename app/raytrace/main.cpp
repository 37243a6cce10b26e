// raytrace: render one scene, or every scene in a folder.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "../common/batch.h"
#include "meshtrace/left_out.h"
#include "meshtrace/render.h"

using namespace meshtrace;

namespace {

struct Options {
  RenderOptions render;
  bool stats = false;
};

bool renderToFile(const Scene& scene, const std::filesystem::path& out, const Options& options) {
  Counters counters;
  const auto start = std::chrono::steady_clock::now();
  const Image image = render(scene, options.render, &counters);
  const double renderMs = app::millisecondsSince(start);
  std::printf("rendered %dx%d with --accel %s in %.1f ms\n", image.width, image.height,
              toString(options.render.trace.accel), renderMs);
  if (options.stats) {
    std::printf("%s", counters.describe().c_str());
    std::printf("vertex normals computed: %zu\n", vertexNormalsComputed(scene));
    for (const std::string& s : leftOut(scene)) std::printf("left out: %s\n", s.c_str());
  }
  try {
    const auto writeStart = std::chrono::steady_clock::now();
    writeImage(quantize(image), out);
    std::printf("wrote %s in %.1f ms\n", out.string().c_str(), app::millisecondsSince(writeStart));
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"Render .sce scenes to images (PNG, BMP or PPM by extension)."};
  Options options;
  bool all = false;
  std::string accel = "aabb";
  std::vector<std::string> args;
  cli.add_flag("--all", all,
               "Render every scene under DIR (default scenes/) into OUTDIR (default results/)");
  cli.add_option("--accel", accel, "Acceleration: none or aabb")->capture_default_str();
  cli.add_option("--threads", options.render.threads, "Worker threads (0: all cores)")
      ->check(CLI::NonNegativeNumber);
  cli.add_flag("--stats", options.stats, "Print work counters and what the scene left out");
  cli.add_option("args", args, "SCENE.sce OUT.png, or with --all: [DIR] [OUTDIR]");
  CLI11_PARSE(cli, argc, argv);

  try {
    options.render.trace.accel = parseAccelMethod(accel);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  if (all) {
    if (args.size() > 2) {
      std::fprintf(stderr, "error: --all takes at most DIR and OUTDIR\n");
      return 2;
    }
    const std::filesystem::path dir = args.size() > 0 ? args[0] : "scenes";
    const std::filesystem::path outDir = args.size() > 1 ? args[1] : "results";
    return app::runOverFolder(
        dir, outDir, "", [](const Scene&) { return true; },
        [&](const Scene& scene, const std::filesystem::path& out) {
          return renderToFile(scene, out, options);
        });
  }
  if (args.size() != 2) {
    std::fprintf(stderr, "error: expected SCENE.sce OUT.png (or --all)\n%s", cli.help().c_str());
    return 2;
  }
  const auto scene = app::loadAndDescribe(args[0]);
  if (!scene) return 1;
  return renderToFile(*scene, args[1], options) ? 0 : 1;
}
