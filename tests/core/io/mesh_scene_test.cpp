// A bare mesh rendered as a scene: framed and loaded from one reading of
// its file, with the arrays and the plan that reading it twice gave.
#include "meshtrace/io/mesh_scene.h"

#include <gtest/gtest.h>

#include <string>

#include "meshtrace/io/scene_parser.h"
#include "support/files.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

// A pyramid of 5 vertices and 6 triangles, with room to read.
std::string pyramidOff() {
  return "OFF\n5 6 0\n0 0 0\n1 0 0\n1 0 1\n0 0 1\n0.5 1 0.5\n"
         "3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n3 0 2 1\n3 0 3 2\n";
}

// The framed mesh's arrays go to its mesh line: the file is not read
// again (here it is gone by then).
TEST(MeshScene, TheFramedMeshLoadsWithoutReadingItsFileAgain) {
  const auto mesh = test::writeFile(test::scratchDir() / "pyramid.off", pyramidOff());
  MemoryBudget budget(defaultMemoryLimit());
  const FramedMesh framed = frameMesh(mesh, budget);
  const std::uint64_t arrays = budget.planned();
  EXPECT_GT(arrays, 0u) << "the arrays are planned in the caller's budget";
  std::filesystem::remove(mesh);
  const Scene scene = parseScene(framed.text, meshScenePath(mesh), budget, framed.meshes);
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].triangles().size(), 6u);
  EXPECT_EQ(scene.meshes[0].shading(), Shading::Phong);

  // The same scene, and the same plan, as the text parsed on its own,
  // which reads the mesh through its mesh line.
  test::writeFile(mesh, pyramidOff());
  MemoryBudget apart(defaultMemoryLimit());
  const Scene expected = parseScene(meshSceneText(mesh, apart), meshScenePath(mesh), apart);
  ASSERT_EQ(expected.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].vertices(), expected.meshes[0].vertices());
  EXPECT_EQ(scene.meshes[0].triangles(), expected.meshes[0].triangles());
  EXPECT_EQ(scene.camera.spec().eye, expected.camera.spec().eye);
  EXPECT_EQ(budget.planned(), apart.planned());

  MemoryBudget whole(defaultMemoryLimit());
  const Scene loaded = loadMeshAsScene(mesh, whole);
  EXPECT_EQ(loaded.meshes[0].triangles(), expected.meshes[0].triangles());
  EXPECT_EQ(whole.planned(), apart.planned());
}

// A scene given a source for one mesh still reads its other meshes.
TEST(MeshScene, TheSourceHandsOutOnlyTheFramedMesh) {
  const auto dir = test::scratchDir();
  const auto mesh = test::writeFile(dir / "pyramid.off", pyramidOff());
  const auto other = test::writeFile(dir / "other.off", pyramidOff());
  MemoryBudget budget(defaultMemoryLimit());
  const FramedMesh framed = frameMesh(mesh, budget);
  const std::string text =
      framed.text + "mesh other.off FLAT 0.2 0.2 0.2  0.7 0.6 0.5  0.5 0.5 0.5  40  0\n";
  const Scene scene = parseScene(text, meshScenePath(mesh), budget, framed.meshes);
  ASSERT_EQ(scene.meshes.size(), 2u);
  EXPECT_EQ(scene.meshes[0].triangles().size(), 6u);
  EXPECT_EQ(scene.meshes[1].triangles().size(), 6u);
  EXPECT_EQ(scene.meshes[1].file(), dir / "other.off");
}

}  // namespace
}  // namespace meshtrace
