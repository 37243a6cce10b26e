// Renders every seed scene and compares with the reference images "within
// JPEG noise" as the scene format's page defines it
// (support/image_agreement.h): RMSE 0.2 after our render's own JPEG round
// trip, at most a handful of pixels off by more than 32. (Measured: RMSE
// at most 0.076, and one pixel off by more than 32, on combo.)
#include <gtest/gtest.h>

#include "meshtrace/io/scene_parser.h"
#include "meshtrace/render/render.h"
#include "support/image_agreement.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

struct SeedCase {
  std::string scene;
  bool debugAabb;
};

class SeedConformance : public ::testing::TestWithParam<SeedCase> {};

TEST_P(SeedConformance, MatchesReferenceWithinJpegNoise) {
  MESHTRACE_REQUIRE_SEED();
  const SeedCase& c = GetParam();
  const Scene scene = loadScene(test::seedDir() / "scenes" / c.scene / (c.scene + ".sce"));
  const auto refDir = test::seedDir() / "expected_results";
  if (c.debugAabb) {
    test::expectWithinJpegNoise(quantize(debugAabbImage(countBoxHits(scene))),
                                refDir / ("debug_aabb_" + c.scene + ".jpg"),
                                "debug_aabb_" + c.scene);
  } else {
    test::expectWithinJpegNoise(quantize(render(scene, {})), refDir / (c.scene + ".jpg"), c.scene);
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
