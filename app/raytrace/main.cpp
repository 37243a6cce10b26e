// raytrace: render one scene, or every scene in a folder.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/batch.h"
#include "common/progress.h"
#include "meshtrace/io/exr.h"
#include "meshtrace/io/memory_budget.h"
#include "meshtrace/render/layers.h"
#include "meshtrace/render/render.h"
#include "meshtrace/report/left_out.h"
#include "meshtrace/report/merge.h"
#include "meshtrace/report/report.h"
#include "meshtrace/report/stability.h"

using namespace meshtrace;

namespace {

struct Options {
  RenderOptions render;
  bool stats = false;
};

// "the BVH of 1000 triangles in 2 meshes and 3 objects"
std::string bvhName(const Scene& scene) {
  return "the BVH of " + std::to_string(scene.triangleCount()) + " triangles and " +
         std::to_string(scene.objectCount()) + " objects";
}

std::string imageName(const Scene& scene) {
  return "the image of " + std::to_string(scene.camera.width()) + "x" +
         std::to_string(scene.camera.height()) + " pixels";
}

// Builds, renders and writes, each phase planned in `budget` before it
// allocates and its running out of memory reported by name.
bool renderToFile(const Scene& scene, const std::filesystem::path& out, const Options& options,
                  MemoryBudget& budget) {
  const TraceOptions& trace = options.render.trace;
  const int w = scene.camera.width(), h = scene.camera.height();
  try {
    const std::uint64_t bvhBytes = accelerationBytes(scene, trace);
    // An EXR's 15 channels of 4 bytes a pixel, and their encoding.
    const std::uint64_t pixelBytes =
        app::imageBytes(w, h) + (isExrPath(out) ? std::uint64_t{120} * w * h : 0);
    budget.reserve(bvhBytes, "build", bvhName(scene));
    budget.reserve(pixelBytes, "render", imageName(scene));
    Counters counters;
    const auto buildStart = std::chrono::steady_clock::now();
    const SceneIntersector intersector = withinMemory(
        "build", bvhName(scene), bvhBytes, [&] { return SceneIntersector(scene, trace); });
    const double buildMs = app::millisecondsSince(buildStart);
    const auto start = std::chrono::steady_clock::now();
    if (isExrPath(out)) {
      const ExrImage layers = withinMemory("render", imageName(scene), pixelBytes, [&] {
        return renderLayers(intersector, options.render.threads);
      });
      std::printf("rendered %dx%d with its layers in %.1f ms\n", w, h,
                  app::millisecondsSince(start));
      withinMemory("write", out.string(), pixelBytes, [&] { writeExr(layers, out); });
      std::printf("wrote %s\n", out.string().c_str());
      return true;
    }
    // The colours are freed once quantized: the file is encoded without them.
    const Image8 pixels = withinMemory("render", imageName(scene), pixelBytes, [&] {
      return quantize(render(intersector, options.render.threads, &counters));
    });
    const double renderMs = app::millisecondsSince(start);
    if (const SceneBvhStats* bvh = intersector.bvhStats()) {
      const std::size_t meshes = bvh->meshesWithBvh, top = bvh->topLevelObjects;
      std::printf(
          "built the BVH (%zu mesh%s in the triangle BVH, %zu object%s on top) in %.1f ms\n",
          meshes, meshes == 1 ? "" : "es", top, top == 1 ? "" : "s", buildMs);
    }
    std::printf("rendered %dx%d with --accel %s --triangle %s --precision %s in %.1f ms\n", w, h,
                toString(trace.accel), toString(trace.triangle.test),
                toString(trace.triangle.precision), renderMs);
    if (options.stats) {
      std::printf("%s", counters.describe().c_str());
      std::printf("vertex normals computed: %zu\n", vertexNormalsComputed(scene));
      std::printf("memory planned: %s of the %s allowed (the BVH's build %s, the image %s)\n",
                  formatBytes(budget.planned()).c_str(), formatBytes(budget.limit()).c_str(),
                  formatBytes(bvhBytes).c_str(), formatBytes(pixelBytes).c_str());
      if (const std::uint64_t peak = app::peakResidentBytes())
        std::printf("peak resident memory so far: %s\n", formatBytes(peak).c_str());
      for (const std::string& s : leftOut(scene)) std::printf("left out: %s\n", s.c_str());
      if (const SceneBvhStats* bvh = intersector.bvhStats())
        for (const std::string& s : bvh->leftOut) std::printf("left out: %s\n", s.c_str());
    }
    const auto writeStart = std::chrono::steady_clock::now();
    withinMemory("write", out.string(), pixelBytes, [&] { writeImage(pixels, out); });
    std::printf("wrote %s in %.1f ms\n", out.string().c_str(), app::millisecondsSince(writeStart));
  } catch (const MemoryLimitError& e) {
    app::printMemoryError(scene.file, e);
    return false;
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return false;
  }
  return true;
}

// What --report plans for a scene: it keeps up to three BVHs (the default
// one, a configuration's, and its primary hits') and per pixel an image,
// its 8-bit copies and two hit records.
std::uint64_t reportBytes(const Scene& scene) {
  return 3 * accelerationBytes(scene, TraceOptions{}) +
         std::uint64_t{128} * scene.camera.width() * scene.camera.height();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{
      "Render .sce scenes to images (PNG, BMP, PPM, JPEG, or multi-layer OpenEXR by extension)."};
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
  cli.add_flag("--stats", options.stats,
               "Print work counters, the memory planned and what the scene left out");
  std::string maxMemory;
  cli.add_option("--max-memory", maxMemory, app::kMaxMemoryHelp);
  std::string shardOption;
  cli.add_option("--shard", shardOption,
                 "With --all or --report: only share I/N of the scenes (those whose index in the "
                 "sorted list is I mod N); default: a Slurm array task's share");
  std::string mergeDir;
  cli.add_option("--report-merge", mergeDir,
                 "Merge the --report folders of every share of a run (given as args) into one "
                 "report in DIR");
  bool quiet = false;
  cli.add_flag("--quiet", quiet, app::kQuietHelp);
  bool printScene = false;
  cli.add_flag("--print-scene", printScene,
               "Print the .sce a bare MESH file renders as (save it beside the mesh to edit it)");
  cli.add_option("args", args,
                 "SCENE.sce OUT.png (or a mesh file: .off, .ply, .obj, .stl, .om, framed), or "
                 "with --all: [DIR] [OUTDIR]");
  CLI11_PARSE(cli, argc, argv);

  try {
    options.render.trace.accel = parseAccelMethod(accel);
    options.render.trace.triangle = {parseTriangleTest(triangle), parsePrecision(precision)};
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  if (quiet) app::setProgressShown(false);
  app::fitWorkersToAddressSpace();
  const std::optional<std::uint64_t> memoryLimit = app::memoryLimit(maxMemory);
  if (!memoryLimit) return 2;
  if (!shardOption.empty() && !all && reportDir.empty()) {
    std::fprintf(stderr, "error: --shard works with --all or --report\n");
    return 2;
  }
  if (!mergeDir.empty()) {
    if (args.empty()) {
      std::fprintf(stderr, "error: --report-merge DIR needs the shares' report folders\n");
      return 2;
    }
    app::ReportFolder folder(mergeDir);
    if (!folder.usable()) return 1;
    try {
      mergeReports(mergeDir, {args.begin(), args.end()});
      folder.keep();
    } catch (const std::runtime_error& e) {
      std::fprintf(stderr, "error: --report-merge: %s\n", e.what());
      return 1;
    }
    std::printf("merged %zu shares into %s/report.md, report.csv and plots\n", args.size(),
                mergeDir.c_str());
    return 0;
  }
  if (printScene) {
    if (args.size() != 1) {
      std::fprintf(stderr, "error: --print-scene takes one MESH file\n");
      return 2;
    }
    return app::printMeshScene(args[0], *memoryLimit) ? 0 : 1;
  }
  if (!reportDir.empty()) {
    if (args.empty()) {
      std::fprintf(stderr, "error: --report DIR needs at least one SCENE.sce\n");
      return 2;
    }
    const std::optional<Shard> shard = app::shardToRun(shardOption);
    if (!shard) return 2;
    app::ReportFolder folder(reportDir);
    if (!folder.usable()) return 1;
    // Sorted, as --all's scenes are: every share deals the same list.
    std::sort(args.begin(), args.end());
    const ReportShare share{*shard, {args.begin(), args.end()}};
    std::vector<SceneReport> reports;
    for (std::size_t i = 0; i < args.size(); ++i) {
      if (!shard->owns(i)) continue;
      const std::string& file = args[i];
      MemoryBudget budget(*memoryLimit);
      const auto scene = app::loadAndDescribe(file, budget);
      if (!scene) return 1;
      try {
        const std::uint64_t bytes = reportBytes(*scene);
        budget.reserve(bytes, "measure", "the configurations of " + file);
        std::optional<app::Progress> progress;
        const auto showProgress = [&](std::size_t done, std::size_t total,
                                      const std::string& next) {
          if (!progress) progress.emplace("measuring " + file + ":", total);
          progress->update(done, next);
        };
        reports.push_back(withinMemory("measure", "the configurations of " + file, bytes, [&] {
          return measureScene(*scene, options.render.threads, showProgress);
        }));
      } catch (const MemoryLimitError& e) {
        app::printMemoryError(file, e);
        return 1;
      }
      std::printf("measured %zu configurations of %s\n", reports.back().rows.size(), file.c_str());
    }
    try {
      withinMemory("write", "the report into " + reportDir, 0, [&] {
        // The suite does not depend on the scenes: share 0 measures it, and
        // --report-merge takes it from there.
        const std::string stability =
            shard->index == 0 ? stabilityMarkdown(measureStabilityTable(300))
                              : "Measured by share 0/" + std::to_string(shard->count) +
                                    " of this run (--report-merge takes it from there).\n";
        writeReport(reportDir, reports, stability, share);
      });
      folder.keep();
    } catch (const std::runtime_error& e) {
      std::fprintf(stderr, "error: %s\n", e.what());
      return 1;
    }
    if (shard->count > 1)
      std::printf(
          "wrote share %s (%zu of %zu scenes) into %s: merge the shares' folders with "
          "--report-merge\n",
          shard->text().c_str(), reports.size(), args.size(), reportDir.c_str());
    else
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
    const std::optional<Shard> shard = app::shardToRun(shardOption);
    if (!shard) return 2;
    return app::runOverFolder(
        dir, outDir, "", *memoryLimit, [](const Scene&) { return true; },
        [&](const Scene& scene, const std::filesystem::path& out, MemoryBudget& budget) {
          return renderToFile(scene, out, options, budget);
        },
        *shard);
  }
  if (args.size() != 2) {
    std::fprintf(stderr, "error: expected SCENE.sce OUT.png (or --all)\n%s", cli.help().c_str());
    return 2;
  }
  if (!app::imageDestinationUsable(args[1])) return 1;
  MemoryBudget budget(*memoryLimit);
  const auto scene = app::loadAndDescribe(args[0], budget);
  if (!scene) return 1;
  return renderToFile(*scene, args[1], options, budget) ? 0 : 1;
}
