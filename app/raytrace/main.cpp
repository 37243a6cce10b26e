// raytrace: render one scene, or every scene in a folder.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/batch.h"
#include "meshtrace/render/render.h"
#include "meshtrace/report/left_out.h"
#include "meshtrace/report/report.h"
#include "meshtrace/report/stability.h"

using namespace meshtrace;

namespace {

struct Options {
  RenderOptions render;
  bool stats = false;
};

bool renderToFile(const Scene& scene, const std::filesystem::path& out, const Options& options) {
  Counters counters;
  const auto buildStart = std::chrono::steady_clock::now();
  const SceneIntersector intersector(scene, options.render.trace);
  const double buildMs = app::millisecondsSince(buildStart);
  const auto start = std::chrono::steady_clock::now();
  const Image image = render(intersector, options.render.threads, &counters);
  const double renderMs = app::millisecondsSince(start);
  if (const SceneBvhStats* bvh = intersector.bvhStats()) {
    const std::size_t meshes = bvh->meshesWithBvh, top = bvh->topLevelObjects;
    std::printf("built the BVH (%zu mesh%s in the triangle BVH, %zu object%s on top) in %.1f ms\n",
                meshes, meshes == 1 ? "" : "es", top, top == 1 ? "" : "s", buildMs);
  }
  const TraceOptions& trace = options.render.trace;
  std::printf("rendered %dx%d with --accel %s --triangle %s --precision %s in %.1f ms\n",
              image.width, image.height, toString(trace.accel), toString(trace.triangle.test),
              toString(trace.triangle.precision), renderMs);
  if (options.stats) {
    std::printf("%s", counters.describe().c_str());
    std::printf("vertex normals computed: %zu\n", vertexNormalsComputed(scene));
    for (const std::string& s : leftOut(scene)) std::printf("left out: %s\n", s.c_str());
    if (const SceneBvhStats* bvh = intersector.bvhStats())
      for (const std::string& s : bvh->leftOut) std::printf("left out: %s\n", s.c_str());
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
  CLI::App cli{"Render .sce scenes to images (PNG, BMP, PPM or JPEG by extension)."};
  Options options;
  bool all = false;
  std::string accel = toString(TraceOptions{}.accel);
  std::string triangle = toString(TriangleKernel{}.test);
  std::string precision = "double";
  std::vector<std::string> args;
  cli.add_flag("--all", all,
               "Render every scene under DIR (default scenes/) into OUTDIR (default results/)");
  cli.add_option("--accel", accel, "Acceleration: bvh, aabb (a box per mesh) or none")
      ->capture_default_str();
  cli.add_option("--triangle", triangle, "Triangle test: cramer, mt or watertight")
      ->capture_default_str();
  cli.add_option("--precision", precision, "Triangle arithmetic: double or single")
      ->capture_default_str();
  cli.add_option("--threads", options.render.threads, "Worker threads (0: all cores)")
      ->check(CLI::NonNegativeNumber);
  std::string reportDir;
  cli.add_option("--report", reportDir,
                 "Time SCENE... under many configurations and write report.md, report.csv and "
                 "error-against-time plots into DIR");
  cli.add_flag("--stats", options.stats, "Print work counters and what the scene left out");
  cli.add_option("args", args, "SCENE.sce OUT.png, or with --all: [DIR] [OUTDIR]");
  CLI11_PARSE(cli, argc, argv);

  try {
    options.render.trace.accel = parseAccelMethod(accel);
    options.render.trace.triangle = {parseTriangleTest(triangle), parsePrecision(precision)};
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  if (!reportDir.empty()) {
    if (args.empty()) {
      std::fprintf(stderr, "error: --report DIR needs at least one SCENE.sce\n");
      return 2;
    }
    if (!app::reportDestinationUsable(reportDir)) return 1;
    std::vector<SceneReport> reports;
    for (const std::string& file : args) {
      const auto scene = app::loadAndDescribe(file);
      if (!scene) return 1;
      reports.push_back(measureScene(*scene, options.render.threads));
      std::printf("measured %zu configurations of %s\n", reports.back().rows.size(), file.c_str());
    }
    try {
      writeReport(reportDir, reports, stabilityMarkdown(measureStabilityTable(300)));
    } catch (const std::runtime_error& e) {
      std::fprintf(stderr, "error: %s\n", e.what());
      return 1;
    }
    std::printf("wrote %s/report.md, report.csv and plots\n", reportDir.c_str());
    return 0;
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
  if (!app::imageDestinationUsable(args[1])) return 1;
  const auto scene = app::loadAndDescribe(args[0]);
  if (!scene) return 1;
  return renderToFile(*scene, args[1], options) ? 0 : 1;
}
