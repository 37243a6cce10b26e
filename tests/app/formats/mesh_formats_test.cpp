// The formats read through OpenMesh: the same mesh as OFF, PLY (ASCII and
// binary), OBJ and STL (ASCII and binary) must load to the same triangles
// and render the same image.
#include <gtest/gtest.h>

#include <string>

#include "app/formats/mesh_files.h"
#include "formats/openmesh_reader.h"
#include "meshtrace/geometry/mesh_generators.h"
#include "meshtrace/io/image.h"
#include "meshtrace/io/mesh_reader.h"
#include "meshtrace/io/ply_reader.h"
#include "meshtrace/io/scene_parser.h"
#include "meshtrace/render/render.h"
#include "support/files.h"
#include "support/paths.h"
#include "support/polygon_files.h"

namespace meshtrace {
namespace {

using test::MeshFormat;

// A torus (PHONG normals at every vertex depend on the shared vertices)
// and an icosphere beside it, in floats so that every format holds them exactly.
MeshData testMesh() {
  MeshData mesh = makeTorus(Vec3(0.3, 0.35, 0.0), 1.0, 0.35, 24, 12);
  const MeshData ball = makeIcosphere(Vec3(-1.6, 0.8, 0.4), 0.7, 2);
  const auto offset = static_cast<std::uint32_t>(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), ball.vertices.begin(), ball.vertices.end());
  for (TriangleIndices t : ball.triangles) {
    for (std::uint32_t& i : t) i += offset;
    mesh.triangles.push_back(t);
  }
  return test::onFloatGrid(std::move(mesh));
}

// A scene with `mesh` PHONG shaded, looked at from above and aside.
std::filesystem::path sceneWith(const std::filesystem::path& mesh) {
  return test::writeFile(mesh.parent_path() / (mesh.stem().string() + ".sce"),
                         "camera 0 2 4.2  -0.3 0.5 0.1  0 1 0  40  160 100\n"
                         "background 0.1 0.1 0.1\nambience 0.2 0.2 0.2\n"
                         "light -4 6 5  0.8 0.8 0.8\n"
                         "mesh " +
                             mesh.filename().string() +
                             " PHONG 0.2 0.1 0.1  0.7 0.4 0.3  0.6 0.6 0.6  40 0\n");
}

class MeshFormats : public ::testing::Test {
 protected:
  void SetUp() override { formats::registerOpenMeshFormats(); }
};

TEST_F(MeshFormats, EveryExtensionHasAReader) {
  for (const char* name : {"a.off", "b.ply", "c.PLY", "d.obj", "e.stl", "f.om"})
    EXPECT_TRUE(isMeshFile(name)) << name;
  EXPECT_FALSE(isMeshFile("g.sce"));
}

TEST_F(MeshFormats, EveryFormatLoadsTheSameIndexedMesh) {
  const MeshData mesh = testMesh();
  const auto scratch = test::scratchDir();
  for (MeshFormat format : test::allMeshFormats()) {
    SCOPED_TRACE(test::formatName(format));
    const auto file = scratch / ("mesh" + test::formatExtension(format));
    test::writeMeshFile(mesh, format, file);
    MemoryBudget budget(defaultMemoryLimit());
    const MeshData read = readMesh(file, budget);
    // STL repeats each corner per triangle: merged, it has the indexed
    // mesh's vertices (in the order of first use, which is theirs here).
    ASSERT_EQ(read.vertices.size(), mesh.vertices.size());
    ASSERT_EQ(read.triangles.size(), mesh.triangles.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      for (int k = 0; k < 3; ++k)
        ASSERT_EQ(read.vertices[read.triangles[t][k]], mesh.vertices[mesh.triangles[t][k]])
            << "triangle " << t << " corner " << k;
  }
}

// Binary PLY, read by OpenMesh before the core had a reader of its own,
// loads to the mesh OpenMesh's reader makes of it: polygons triangulated
// alike, in either byte order. (OpenMesh's reader takes a face's first list
// for its corners whatever its name, and reads no uint or ushort counts:
// files with those, which the core reads, are left out here.)
TEST_F(MeshFormats, BinaryPlyLoadsThePolygonsOpenMeshLoads) {
  const test::PolygonMesh polygons = test::polygonMesh(3);
  const auto file = test::scratchDir() / "polygons.ply";
  for (const test::PlyLayout& layout : {test::PlyLayout{false, "float", "uchar", "int", false},
                                        test::PlyLayout{true, "float", "uchar", "int", false},
                                        test::PlyLayout{true, "double", "int", "uint", false}}) {
    SCOPED_TRACE(test::describe(layout));
    test::writeFile(file, test::binaryPly(polygons, layout));
    MemoryBudget budget(defaultMemoryLimit());
    const std::optional<MeshData> ours = readPly(file, budget);
    ASSERT_TRUE(ours.has_value());
    const MeshData openMesh = formats::readOpenMeshFile(file, budget);
    EXPECT_EQ(ours->vertices, openMesh.vertices);
    EXPECT_EQ(ours->triangles, openMesh.triangles);
    EXPECT_EQ(readMesh(file, budget).triangles, openMesh.triangles);
  }
}

// The mesh of `file`, polygons among its faces, by our reader and by
// OpenMesh's: the same vertices and triangles.
void expectOurReaderLoadsWhatOpenMeshLoads(const std::filesystem::path& file) {
  MemoryBudget budget(defaultMemoryLimit());
  const MeshData ours = readMesh(file, budget);
  const MeshData openMesh = formats::readOpenMeshFile(file, budget);
  ASSERT_GT(ours.polygons.size(), 3u);
  EXPECT_EQ(ours.vertices, openMesh.vertices);
  EXPECT_EQ(ours.triangles, openMesh.triangles);
}

// ASCII PLY, read by OpenMesh before the core had a reader of its own,
// loads to the mesh OpenMesh's reader makes of it when its coordinates are
// exact in float (OpenMesh reads them in float), polygons triangulated
// alike, with other properties and an element of another kind around them.
TEST_F(MeshFormats, AsciiPlyLoadsThePolygonsOpenMeshLoads) {
  const test::PolygonMesh polygons = test::polygonMesh(3);
  std::string text = "ply\nformat ascii 1.0\nelement vertex " +
                     std::to_string(polygons.vertices.size()) +
                     "\nproperty float x\nproperty float y\nproperty float z\n"
                     "property uchar red\nelement face " +
                     std::to_string(polygons.faces.size()) +
                     "\nproperty list uchar int vertex_indices\nproperty float quality\n"
                     "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n";
  // Appended piece by piece: GCC 12 warns (-Wrestrict) wrongly on
  // "literal" + std::to_string(...).
  const auto number = [&](auto value, const char* after) {
    text += std::to_string(value);
    text += after;
  };
  for (const Vec3& v : polygons.vertices) number(v.x, " "), number(v.y, " "), number(v.z, " 200\n");
  for (const auto& face : polygons.faces) {
    number(face.size(), " ");
    for (std::uint32_t i : face) number(i, " ");
    text += "0.5\n";
  }
  text += "0 1\n";
  expectOurReaderLoadsWhatOpenMeshLoads(
      test::writeFile(test::scratchDir() / "polygons.ply", text));
}

// STL, read by OpenMesh before the core had a reader of its own, loads to
// the mesh OpenMesh's reader makes of it (coordinates exact in float):
// corners welded into the same vertices in the same order, and a facet
// with two corners at one point left out as OpenMesh's reader leaves it.
TEST_F(MeshFormats, StlLoadsTheMeshOpenMeshLoads) {
  MeshData mesh = testMesh();
  mesh.triangles.insert(mesh.triangles.begin() + 5, TriangleIndices{7, 9, 7});
  for (MeshFormat format : {MeshFormat::StlAscii, MeshFormat::StlBinary}) {
    SCOPED_TRACE(test::formatName(format));
    const auto file = test::scratchDir() / "mesh.stl";
    test::writeMeshFile(mesh, format, file);
    MemoryBudget budget(defaultMemoryLimit());
    const MeshData ours = readMesh(file, budget);
    const MeshData openMesh = formats::readOpenMeshFile(file, budget);
    EXPECT_EQ(ours.vertices, openMesh.vertices);
    EXPECT_EQ(ours.triangles, openMesh.triangles);
    EXPECT_EQ(ours.triangles.size(), mesh.triangles.size() - 1);
  }
}

// OBJ, read by OpenMesh before the core had a reader of its own, loads to
// the mesh OpenMesh's reader makes of it (its coordinates exact in float),
// polygons triangulated alike, with every form of corner.
TEST_F(MeshFormats, ObjLoadsThePolygonsOpenMeshLoads) {
  expectOurReaderLoadsWhatOpenMeshLoads(
      test::writeFile(test::scratchDir() / "polygons.obj", test::objText(test::polygonMesh(3))));
}

// The PLY files of the tests above are read by the core's reader.
TEST_F(MeshFormats, PlyOfEveryEncodingIsReadByTheCoreReader) {
  const auto scratch = test::scratchDir();
  for (MeshFormat format :
       {MeshFormat::PlyBinary, MeshFormat::PlyBinaryBigEndian, MeshFormat::PlyAscii}) {
    const auto file = scratch / (test::formatName(format) + ".ply");
    test::writeMeshFile(testMesh(), format, file);
    MemoryBudget budget(defaultMemoryLimit());
    EXPECT_TRUE(readPly(file, budget).has_value()) << test::formatName(format);
  }
}

TEST_F(MeshFormats, EveryFormatRendersTheSameImage) {
  const MeshData mesh = testMesh();
  Image8 offImage;
  const auto scratch = test::scratchDir();
  for (MeshFormat format : test::allMeshFormats()) {
    SCOPED_TRACE(test::formatName(format));
    const auto dir = scratch / test::formatName(format);
    std::filesystem::create_directories(dir);
    const auto file = dir / ("mesh" + test::formatExtension(format));
    test::writeMeshFile(mesh, format, file);
    const Image8 image = quantize(render(loadScene(sceneWith(file)), {}));
    if (format == MeshFormat::Off) {
      offImage = image;
      // The mesh covers a good part of the image.
      std::size_t lit = 0;
      for (std::size_t i = 0; i < image.rgb.size(); i += 3) lit += image.rgb[i] > 60;
      EXPECT_GT(lit, image.rgb.size() / 3 / 5);
      continue;
    }
    ASSERT_EQ(image.width, offImage.width);
    EXPECT_TRUE(image.rgb == offImage.rgb) << "differs from the OFF render";
  }
}

}  // namespace
}  // namespace meshtrace
