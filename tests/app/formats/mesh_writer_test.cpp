// The meshes we write (make_scenes, the bench) in each format, read back by
// the readers the tools use.
#include "meshtrace/io/mesh_writer.h"

#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>

#include "app/formats/mesh_files.h"
#include "formats/openmesh_reader.h"
#include "meshtrace/geometry/mesh_generators.h"
#include "meshtrace/geometry/scene_meshes.h"
#include "meshtrace/io/mesh_reader.h"
#include "support/cli.h"
#include "support/files.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

MeshData readBack(const std::filesystem::path& file) {
  MemoryBudget budget(defaultMemoryLimit());
  return readMesh(file, budget);
}

// Each triangle's corners, position by position (STL lists corners, not
// shared vertices, so only positions can be compared across formats).
void expectSameTriangles(const MeshData& got, const MeshData& want, const std::string& what) {
  ASSERT_EQ(got.triangles.size(), want.triangles.size()) << what;
  for (std::size_t t = 0; t < want.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      ASSERT_EQ(got.vertices[got.triangles[t][k]], want.vertices[want.triangles[t][k]])
          << what << ": triangle " << t << " corner " << k;
}

void expectSameBits(const MeshData& got, const MeshData& want, const std::string& what) {
  ASSERT_EQ(got.vertices.size(), want.vertices.size()) << what;
  EXPECT_EQ(
      std::memcmp(got.vertices.data(), want.vertices.data(), want.vertices.size() * sizeof(Vec3)),
      0)
      << what;
  EXPECT_TRUE(got.triangles == want.triangles) << what;
}

class MeshWriter : public ::testing::Test {
 protected:
  void SetUp() override { formats::registerOpenMeshFormats(); }
};

TEST_F(MeshWriter, EveryFormatReadsBackAsTheSameTriangles) {
  const MeshData mesh = test::onFloatGrid(makeTorus(Vec3(0.2, 0.4, -0.1), 1.0, 0.3, 16, 8));
  const auto dir = test::scratchDir();
  for (const char* extension : {".off", ".ply", ".obj", ".stl"}) {
    const auto file = dir / (std::string("torus") + extension);
    writeMesh(mesh, file);
    expectSameTriangles(readBack(file), mesh, extension);
  }
}

// OFF, PLY (double coordinates) and ASCII PLY hold any double: the
// generators' meshes come back bit for bit, so a scene renders the same
// from any of them.
TEST_F(MeshWriter, OffAndPlyKeepEveryCoordinateExactly) {
  const MeshData mesh = makeTorusKnot(Vec3(0.1, 1.3, 0.0), 0.45, 2, 3, 0.42, 64, 12);
  const auto dir = test::scratchDir();
  for (const char* extension : {".off", ".ply"}) {
    const auto file = dir / (std::string("knot") + extension);
    writeMesh(mesh, file);
    expectSameBits(readBack(file), mesh, extension);
  }
  const auto ascii = dir / "knot-ascii.ply";
  writeAsciiPly(mesh, ascii);
  expectSameBits(readBack(ascii), mesh, "ASCII PLY");
}

// ASCII STL holds any double too: its corners weld back into the mesh's
// vertices, in the order the triangles first use them.
TEST_F(MeshWriter, AsciiStlKeepsEveryCornerExactly) {
  const MeshData mesh = makeTorusKnot(Vec3(0.1, 1.3, 0.0), 0.45, 2, 3, 0.42, 64, 12);
  const auto file = test::scratchDir() / "knot.stl";
  writeAsciiStl(mesh, file);
  const MeshData got = readBack(file);
  expectSameTriangles(got, mesh, "ASCII STL");
  EXPECT_EQ(got.vertices.size(), mesh.vertices.size());
}

TEST_F(MeshWriter, FloatPlyRoundsEachCoordinateToNearest) {
  const MeshData mesh = makeIcosphere(Vec3(0.3, 0.2, 0.1), 0.9, 1);
  const auto file = test::scratchDir() / "ball.ply";
  writeBinaryPly(mesh, file, PlyCoordinates::Float);
  const MeshData got = readBack(file);
  ASSERT_EQ(got.vertices.size(), mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(got.vertices[v][k], static_cast<double>(static_cast<float>(mesh.vertices[v][k])));
}

TEST_F(MeshWriter, AnUnknownExtensionIsRefusedAndNothingIsWritten) {
  const auto dir = test::scratchDir();
  EXPECT_THROW(writeMesh(makeGrid(Vec3(0.0), 1.0, 1), dir / "grid.xyz"), std::invalid_argument);
  EXPECT_TRUE(test::listFolder(dir).empty());
}

// make_scenes --format writes our scenes' meshes in another format; read
// back, each is the generator's mesh (PLY: bit for bit).
TEST_F(MeshWriter, MakeScenesWritesOurMeshesInTheFormatAsked) {
  const auto dir = test::scratchDir();
  const auto r = test::runTool(test::makeScenesTool(), {"--format", "ply", dir.string()}, dir);
  ASSERT_TRUE(r.exited && r.exitCode == 0) << test::describe(r);
  for (const SceneMesh& m : ourSceneMeshes()) {
    const auto file = (dir / m.path).replace_extension(".ply");
    ASSERT_TRUE(std::filesystem::exists(file)) << file;
    expectSameBits(readBack(file), m.make(), m.path);
  }
  const auto bad = test::runTool(test::makeScenesTool(), {"--format", "xyz", dir.string()}, dir);
  EXPECT_TRUE(bad.exited && bad.exitCode != 0) << test::describe(bad);
  EXPECT_NE(bad.err.find("xyz"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace meshtrace
