// Renders every seed scene and compares with the reference images "within
// JPEG noise": our render, encoded as JPEG q95 4:4:4 and decoded, must reach
// RMSE <= 0.6 with at most 0.05% of pixels off by more than 32.
#include <gtest/gtest.h>

#include <cstdio>

#include "meshtrace/io/scene_parser.h"
#include "meshtrace/render/render.h"
#include "meshtrace/report/image_compare.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

constexpr double kMaxRmse = 0.6;
constexpr double kMaxFractionOver32 = 0.0005;

struct SeedCase {
  std::string scene;
  bool debugAabb;
};

class SeedConformance : public ::testing::TestWithParam<SeedCase> {};

void expectWithinJpegNoise(const Image& render, const std::filesystem::path& reference,
                           const std::string& label) {
  const Image8 ours = jpegRoundTrip(quantize(render), 95);
  const ImageDifference d = compareImages(ours, readImage(reference));
  std::printf("[ figures  ] %-26s RMSE %.3f  PSNR %.1f dB  pixels off >32: %.4f%%  max %d\n",
              label.c_str(), d.rmse, d.psnr, 100.0 * d.fractionOver32, d.maxDifference);
  EXPECT_LE(d.rmse, kMaxRmse) << label;
  EXPECT_LE(d.fractionOver32, kMaxFractionOver32) << label;
}

TEST_P(SeedConformance, MatchesReferenceWithinJpegNoise) {
  MESHTRACE_REQUIRE_SEED();
  const SeedCase& c = GetParam();
  const Scene scene = loadScene(test::seedDir() / "scenes" / c.scene / (c.scene + ".sce"));
  const auto refDir = test::seedDir() / "expected_results";
  if (c.debugAabb) {
    expectWithinJpegNoise(debugAabbImage(countBoxHits(scene)),
                          refDir / ("debug_aabb_" + c.scene + ".jpg"), "debug_aabb_" + c.scene);
  } else {
    expectWithinJpegNoise(render(scene, {}), refDir / (c.scene + ".jpg"), c.scene);
  }
}

INSTANTIATE_TEST_SUITE_P(SeedScenes, SeedConformance,
                         ::testing::Values(SeedCase{"combo", false}, SeedCase{"cube", false},
                                           SeedCase{"cylinders", false}, SeedCase{"mask", false},
                                           SeedCase{"mirror", false}, SeedCase{"molecule", false},
                                           SeedCase{"molecule2", false}, SeedCase{"rings", false},
                                           SeedCase{"spheres", false},
                                           SeedCase{"toon_faces", false}, SeedCase{"mask", true},
                                           SeedCase{"rings", true}, SeedCase{"toon_faces", true}),
                         [](const auto& info) {
                           return (info.param.debugAabb ? "debug_aabb_" : "") + info.param.scene;
                         });

// Every reference image in the seed is covered by a case above.
TEST(SeedConformance, CoversEveryReferenceImage) {
  MESHTRACE_REQUIRE_SEED();
  int references = 0;
  for (const auto& e : std::filesystem::directory_iterator(test::seedDir() / "expected_results"))
    references += e.path().extension() == ".jpg";
  EXPECT_EQ(references, 13);
}

}  // namespace
}  // namespace meshtrace
