// Every seed scene renders to exactly the same image (the same double per
// channel, not just the same bytes) with --accel bvh as with --accel none.
//
// Brute force checks every pixel of every scene but toon_faces, whose 57k
// triangles would take brute force about seven minutes on two cores, more
// than the rest of the suite: there it checks an evenly spread sample of
// about one pixel in seven. Built with the sanitizers, which make brute
// force several times slower, the budget is smaller and more scenes are
// sampled. Each scene says what it checked.
#include <gtest/gtest.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <cstdio>
#include <numeric>
#include <string>
#include <utility>

#include "meshtrace/io/scene_parser.h"
#include "meshtrace/render/integrator.h"
#include "meshtrace/render/render.h"
#include "support/paths.h"
#include "support/sanitizers.h"

namespace meshtrace {
namespace {

// Pixels times triangles (plus objects) that brute force renders in full;
// a costlier scene is sampled down to about this much work (under the
// sanitizers, the share sanitizerShare takes of rays).
constexpr double kBruteForceBudget = 3e9 / double(test::kSanitizerDivisor);

// Every stride-th pixel in storage order. A stride that shares no factor
// with the width moves the column from row to row, so the sample covers
// every column, not a few stripes.
std::size_t sampleStride(double cost, std::size_t width) {
  std::size_t stride = std::size_t(cost / kBruteForceBudget) + 1;
  while (stride > 1 && std::gcd(stride, width) != 1) ++stride;
  return stride;
}

const char* const kSeedScenes[] = {"combo",   "cube",       "cylinders",  "mask",
                                   "mirror",  "molecule",   "molecule2",  "rings",
                                   "spheres", "toon_faces", "solid_color"};

class BvhImages : public ::testing::TestWithParam<const char*> {};

TEST_P(BvhImages, IdenticalToBruteForce) {
  MESHTRACE_REQUIRE_SEED();
  const std::string name = GetParam();
  const Scene scene = loadScene(test::seedDir() / "scenes" / name / (name + ".sce"));
  const Image image = render(scene, {});  // the default: --accel bvh
  const SceneIntersector brute(scene, {.accel = AccelMethod::None});
  const Integrator integrator(brute);
  const std::size_t n = image.pixels.size();
  const double cost = double(n) * double(scene.triangleCount() + scene.objectCount());
  const std::size_t stride = sampleStride(cost, std::size_t(image.width));
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
  std::printf("[ figures  ] %-12s %zu of %zu pixels checked against brute force%s, %zu differ\n",
              name.c_str(), checked, n, stride > 1 ? " (a sample: brute force is slow here)" : "",
              differing);
  EXPECT_EQ(checked, (n + stride - 1) / stride);
  EXPECT_EQ(differing, 0u);
}

INSTANTIATE_TEST_SUITE_P(SeedScenes, BvhImages, ::testing::ValuesIn(kSeedScenes),
                         [](const auto& info) { return std::string(info.param); });

// Every seed scene is one of the cases above.
TEST(BvhImagesCoverage, EverySeedScene) {
  MESHTRACE_REQUIRE_SEED();
  std::size_t scenes = 0;
  for (const auto& dir : std::filesystem::directory_iterator(test::seedDir() / "scenes"))
    scenes += std::filesystem::exists(dir.path() / (dir.path().filename().string() + ".sce"));
  EXPECT_EQ(scenes, std::size(kSeedScenes));
}

}  // namespace
}  // namespace meshtrace
