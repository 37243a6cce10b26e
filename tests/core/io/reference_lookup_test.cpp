// findReference: a scene's stored reference image is found in an
// expected_results/ folder beside one of the scene's enclosing folders, in
// the seed's layout and in ours.
#include "meshtrace/io/reference_lookup.h"

#include <gtest/gtest.h>

#include "support/files.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

// Writes `path`, its folders first.
void place(const std::filesystem::path& path) {
  std::filesystem::create_directories(path.parent_path());
  test::writeFile(path, "");
}

TEST(ReferenceLookup, FindsExpectedResultsBesideTheSceneFolders) {
  const auto dir = test::scratchDir();
  place(dir / "scenes/demo/demo.sce");
  EXPECT_FALSE(findReference(dir / "scenes/demo/demo.sce"));
  place(dir / "expected_results/demo.jpg");
  EXPECT_EQ(findReference(dir / "scenes/demo/demo.sce"), dir / "expected_results/demo.jpg");
}

// Our checkout: scenes/<folder>/<stem>.sce, expected_results/<stem>.png at
// the root, the scene's stem not its folder's name.
TEST(ReferenceLookup, FindsOurStoredRenderByTheScenesStem) {
  const auto dir = test::scratchDir();
  place(dir / "scenes/shading_modes/shading_flat.sce");
  place(dir / "expected_results/shading_modes.png");
  EXPECT_FALSE(findReference(dir / "scenes/shading_modes/shading_flat.sce"));
  place(dir / "expected_results/shading_flat.png");
  EXPECT_EQ(findReference(dir / "scenes/shading_modes/shading_flat.sce"),
            dir / "expected_results/shading_flat.png");
}

TEST(ReferenceLookup, TheNearestFolderWins) {
  const auto dir = test::scratchDir();
  place(dir / "scenes/demo/demo.sce");
  place(dir / "expected_results/demo.png");
  place(dir / "scenes/expected_results/demo.jpg");
  EXPECT_EQ(findReference(dir / "scenes/demo/demo.sce"), dir / "scenes/expected_results/demo.jpg");
}

}  // namespace
}  // namespace meshtrace
