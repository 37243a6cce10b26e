// Every seed scene renders to exactly the same image (the same double per
// channel, not just the same bytes) with --accel bvh as with --accel none.
//
// Brute force over the toon faces alone costs minutes of CPU, so brute force
// renders every pixel of scenes up to a work budget and an evenly spread
// sample of the pixels of costlier ones. MESHTRACE_FULL_IMAGE_CHECK=1 checks
// every pixel of every scene (about ten minutes on two cores).
#include <gtest/gtest.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <cstdio>
#include <cstdlib>

#include "meshtrace/io/scene_parser.h"
#include "meshtrace/render/integrator.h"
#include "meshtrace/render/render.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

// Pixels times triangles (plus objects) that brute force renders in full.
constexpr double kFullBudget = 4e8;

TEST(BvhImages, IdenticalToBruteForceOnEverySeedScene) {
  MESHTRACE_REQUIRE_SEED();
  const char* full = std::getenv("MESHTRACE_FULL_IMAGE_CHECK");
  const bool checkAll = full && std::string(full) == "1";
  std::vector<std::filesystem::path> scenes;
  for (const auto& dir : std::filesystem::directory_iterator(test::seedDir() / "scenes")) {
    const auto file = dir.path() / (dir.path().filename().string() + ".sce");
    if (std::filesystem::exists(file)) scenes.push_back(file);
  }
  std::sort(scenes.begin(), scenes.end());
  ASSERT_GE(scenes.size(), 10u);
  for (const auto& file : scenes) {
    const Scene scene = loadScene(file);
    const Image image = render(scene, {});  // the default: --accel bvh
    const SceneIntersector brute(scene, {.accel = AccelMethod::None});
    const Integrator integrator(brute);
    const std::size_t n = image.pixels.size();
    const double cost = double(n) * double(scene.triangleCount() + scene.objectCount());
    const std::size_t stride = checkAll ? 1 : std::max<std::size_t>(1, cost / kFullBudget + 1);
    // Every stride-th pixel in storage order; an odd-ish stride walks across
    // rows and columns alike.
    const auto [checked, differing] = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, (n + stride - 1) / stride, 64),
        std::pair<std::size_t, std::size_t>{0, 0},
        [&](const tbb::blocked_range<std::size_t>& r, std::pair<std::size_t, std::size_t> acc) {
          Counters c;
          for (std::size_t k = r.begin(); k < r.end(); ++k) {
            const std::size_t i = k * stride;
            const int x = static_cast<int>(i % image.width);
            const int row = static_cast<int>(i / image.width);
            ++acc.first;
            acc.second += integrator.pixel(x, flippedRow(row, image.height), c) != image.pixels[i];
          }
          return acc;
        },
        [](auto a, auto b) {
          return std::pair{a.first + b.first, a.second + b.second};
        });
    std::printf("[ figures  ] %-12s %zu of %zu pixels checked against brute force, %zu differ\n",
                file.stem().string().c_str(), checked, n, differing);
    EXPECT_EQ(differing, 0u) << file;
  }
}

}  // namespace
}  // namespace meshtrace
