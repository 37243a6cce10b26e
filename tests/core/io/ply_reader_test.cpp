// The binary PLY reader: the mesh OFF's reader reads from the same
// polygons, in either byte order and for every type a file may use, with
// integer coordinates and with lists beside them; the files it leaves to
// other readers; and bad files refused with an
// InputError naming the file and the element.
#include "meshtrace/io/ply_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "meshtrace/io/off_reader.h"
#include "support/files.h"
#include "support/input_errors.h"
#include "support/paths.h"
#include "support/polygon_files.h"

namespace meshtrace {
namespace {

using test::expectMentions;
using test::PlyLayout;

std::optional<MeshData> readPlyBytes(const std::string& bytes) {
  MemoryBudget budget(defaultMemoryLimit());
  return readPly(test::writeFile(test::scratchDir() / "mesh.ply", bytes), budget);
}

MeshData readOffOf(const test::PolygonMesh& mesh) {
  return readOff(test::writeFile(test::scratchDir() / "mesh.off", test::offText(mesh)));
}

class BinaryPlyLayouts : public ::testing::TestWithParam<PlyLayout> {};

TEST_P(BinaryPlyLayouts, ReadTheMeshOffsReaderReads) {
  const test::PolygonMesh polygons = test::polygonMesh();
  const MeshData off = readOffOf(polygons);
  const std::optional<MeshData> ply = readPlyBytes(test::binaryPly(polygons, GetParam()));
  ASSERT_TRUE(ply.has_value());
  EXPECT_EQ(ply->vertices, off.vertices);
  EXPECT_EQ(ply->triangles, off.triangles);
  EXPECT_EQ(ply->triangles.size(), 2u + 1u + 4u + 1u + 3u + 2u + 4u);
}

INSTANTIATE_TEST_SUITE_P(Layouts, BinaryPlyLayouts,
                         ::testing::Values(PlyLayout{false, "float", "uchar", "int", false},
                                           PlyLayout{true, "float", "uchar", "int", false},
                                           PlyLayout{false, "double", "int", "uint", true},
                                           PlyLayout{true, "double", "ushort", "ushort", true},
                                           PlyLayout{true, "float32", "char", "short", true},
                                           PlyLayout{false, "float64", "uint8", "uint32", true},
                                           PlyLayout{true, "float", "short", "int32", false},
                                           PlyLayout{false, "float", "uint", "uchar", true}),
                         [](const auto& info) {
                           const PlyLayout& l = info.param;
                           return std::string(l.bigEndian ? "big_" : "little_") + l.coordinateType +
                                  "_" + l.countType + "_" + l.indexType +
                                  (l.extras ? "_extras" : "");
                         });

// More than the reader's buffer holds: records are cut at its end.
TEST(BinaryPly, ReadsAFileLargerThanItsBufferAsOffDoes) {
  const test::PolygonMesh polygons = test::polygonMesh(20000);
  for (bool bigEndian : {false, true}) {
    const std::string bytes =
        test::binaryPly(polygons, PlyLayout{bigEndian, "double", "uchar", "int", true});
    ASSERT_GT(bytes.size(), std::size_t{3} << 20);
    const std::optional<MeshData> ply = readPlyBytes(bytes);
    ASSERT_TRUE(ply.has_value());
    const MeshData off = readOffOf(polygons);
    EXPECT_EQ(ply->vertices, off.vertices);
    EXPECT_EQ(ply->triangles, off.triangles);
  }
}

// Faces may come before the vertices they index: the header gives the
// vertex count that their indices are checked against.
TEST(BinaryPly, ReadsFacesListedBeforeTheirVertices) {
  const test::PolygonMesh polygons = test::polygonMesh();
  test::PlyValues values(false);
  for (const auto& face : polygons.faces) {
    values.put("uchar", static_cast<double>(face.size()));
    for (std::uint32_t i : face) values.put("int", i);
  }
  for (const Vec3& v : polygons.vertices)
    for (int k = 0; k < 3; ++k) values.put("double", v[k]);
  const std::string declarations = "element face " + std::to_string(polygons.faces.size()) +
                                   "\nproperty list uchar int vertex_indices\nelement vertex " +
                                   std::to_string(polygons.vertices.size()) +
                                   "\nproperty double x\nproperty double y\nproperty double z\n";
  const std::optional<MeshData> ply =
      readPlyBytes(test::plyHeader(PlyLayout{}, declarations) + values.bytes());
  ASSERT_TRUE(ply.has_value());
  const MeshData off = readOffOf(polygons);
  EXPECT_EQ(ply->vertices, off.vertices);
  EXPECT_EQ(ply->triangles, off.triangles);
}

TEST(BinaryPly, LeavesFloatCornersToOtherReaders) {
  const std::string vertices =
      " 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\n";
  for (const char* format : {"ascii", "binary_little_endian"}) {
    EXPECT_FALSE(readPlyBytes(std::string("ply\nformat ") + format + vertices +
                              "element face 0\nproperty list uchar float vertex_indices\n"
                              "end_header\n"))
        << format;
    EXPECT_TRUE(readPlyBytes(std::string("ply\nformat ") + format + vertices +
                             "element face 0\nproperty list uchar int vertex_indices\n"
                             "end_header\n"))
        << format;
  }
}

// Vertices with lists beside their coordinates (of sizes that differ from
// vertex to vertex) are read here too: OpenMesh's reader, which they went
// to, could not convert the integer coordinates such files may also have.
TEST(BinaryPly, ReadsVerticesWithListsBesideTheCoordinates) {
  for (bool bigEndian : {false, true}) {
    SCOPED_TRACE(bigEndian ? "big-endian" : "little-endian");
    test::PlyValues body(bigEndian);
    const double xyz[3][3] = {{0, 0, 5}, {1, 0, 5}, {0, 1, 7}};
    for (int i = 0; i < 3; ++i) {
      body.put("uchar", i);  // the list before x: i weights
      for (int k = 0; k < i; ++k) body.put("float", 0.5);
      body.put("float", xyz[i][0]);
      body.put("uchar", xyz[i][1]);
      body.put("short", 2 - i);  // the list after y: 2 - i shorts
      for (int k = 0; k < 2 - i; ++k) body.put("short", -1);
      body.put("double", xyz[i][2]);
    }
    body.put("uchar", 3);
    for (double c : {0, 1, 2}) body.put("int", c);
    const std::optional<MeshData> mesh = readPlyBytes(
        test::plyHeader({bigEndian, "float", "uchar", "int", false},
                        "element vertex 3\nproperty list uchar float weights\nproperty float x\n"
                        "property uchar y\nproperty list short short marks\nproperty double z\n"
                        "element face 1\nproperty list uchar int vertex_indices\n") +
        body.bytes());
    ASSERT_TRUE(mesh.has_value());
    ASSERT_EQ(mesh->vertices.size(), 3u);
    for (int i = 0; i < 3; ++i)
      EXPECT_EQ(mesh->vertices[i], Vec3(xyz[i][0], xyz[i][1], xyz[i][2])) << i;
    EXPECT_EQ(mesh->triangles, (std::vector<TriangleIndices>{{0, 1, 2}}));
  }
}

// Integer coordinates, which OpenMesh's reader cannot convert (it printed
// "unsupported conversion type to float" and read no faces), are read here
// exactly, for every PLY integer type at its least and greatest value, in
// either byte order.
TEST(BinaryPly, ReadsIntegerCoordinatesOfEveryType) {
  struct Type {
    const char* name;
    double least, greatest;
  };
  const Type types[] = {{"char", -128, 127},           {"uchar", 0, 255},
                        {"short", -32768, 32767},      {"ushort", 0, 65535},
                        {"int", -2147483648.0, 2147483647}, {"uint", 0, 4294967295.0},
                        {"int8", -128, 127},           {"uint32", 0, 4294967295.0}};
  for (bool bigEndian : {false, true})
    for (const Type& t : types) {
      SCOPED_TRACE(std::string(t.name) + (bigEndian ? ", big-endian" : ", little-endian"));
      // x, y and z all of the type: (least, greatest, 0), (greatest, 0,
      // least), (0, least, greatest).
      const double values[3][3] = {{t.least, t.greatest, 0},
                                   {t.greatest, 0, t.least},
                                   {0, t.least, t.greatest}};
      test::PlyValues body(bigEndian);
      for (const auto& v : values)
        for (double c : v) body.put(t.name, c);
      body.put("uchar", 3);
      for (double i : {0, 1, 2}) body.put("int", i);
      const std::string type = t.name;
      const std::optional<MeshData> mesh = readPlyBytes(
          test::plyHeader({bigEndian, "float", "uchar", "int", false},
                          "element vertex 3\nproperty " + type + " x\nproperty " + type +
                              " y\nproperty " + type + " z\nelement face 1\n" +
                              "property list uchar int vertex_indices\n") +
          body.bytes());
      ASSERT_TRUE(mesh.has_value());
      ASSERT_EQ(mesh->vertices.size(), 3u);
      for (int i = 0; i < 3; ++i)
        EXPECT_EQ(mesh->vertices[i], Vec3(values[i][0], values[i][1], values[i][2])) << i;
      EXPECT_EQ(mesh->triangles, (std::vector<TriangleIndices>{{0, 1, 2}}));
    }
}

// A mesh of three vertices and two faces, its bytes built value by value.
struct SmallPly {
  PlyLayout layout;
  test::PlyValues values;
  explicit SmallPly(bool bigEndian = false, const char* countType = "uchar",
                    const char* indexType = "int")
      : layout{bigEndian, "float", countType, indexType, false}, values(bigEndian) {}

  std::string header(int faces = 2) const {
    return test::plyHeader(
        layout,
        "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "element face " +
            std::to_string(faces) + "\nproperty list " + layout.countType + " " + layout.indexType +
            " vertex_indices\n");
  }
  SmallPly& vertices(double badValue = 0.0) {
    for (double v : {0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, badValue}) values.put("float", v);
    return *this;
  }
  SmallPly& face(std::vector<double> corners) {
    values.put(layout.countType, static_cast<double>(corners.size()));
    for (double c : corners) values.put(layout.indexType, c);
    return *this;
  }
  SmallPly& count(double n) {
    values.put(layout.countType, n);
    return *this;
  }
  std::string bytes(int faces = 2) { return header(faces) + values.bytes(); }
};

std::string plyErrorOf(const std::string& bytes, std::uint64_t memory = defaultMemoryLimit()) {
  const auto file = test::writeFile(test::scratchDir() / "mesh.ply", bytes);
  MemoryBudget budget(memory);
  return test::inputErrorOf([&] { readPly(file, budget); });
}

TEST(BinaryPly, ReadsTheSmallMeshTheBadOnesBreak) {
  for (bool bigEndian : {false, true}) {
    const auto mesh =
        readPlyBytes(SmallPly(bigEndian).vertices().face({0, 1, 2}).face({2, 1, 0}).bytes());
    ASSERT_TRUE(mesh.has_value());
    EXPECT_EQ(mesh->triangles, (std::vector<TriangleIndices>{{0, 1, 2}, {2, 1, 0}}));
  }
}

TEST(BinaryPly, RefusesNonFiniteCoordinatesNamingTheVertex) {
  for (double bad : {std::numeric_limits<double>::quiet_NaN(), HUGE_VAL, -HUGE_VAL})
    for (bool bigEndian : {false, true})
      expectMentions(plyErrorOf(SmallPly(bigEndian).vertices(bad).face({0, 1, 2}).bytes(1)),
                     {"mesh.ply", "vertex 2", "non-finite"});
}

TEST(BinaryPly, RefusesIndicesOutOfRangeNamingTheFace) {
  for (bool bigEndian : {false, true}) {
    expectMentions(
        plyErrorOf(SmallPly(bigEndian).vertices().face({0, 1, 2}).face({0, 3, 1}).bytes()),
        {"mesh.ply", "face 1", "vertex index 3 out of range", "3 vertices"});
    expectMentions(
        plyErrorOf(SmallPly(bigEndian).vertices().face({0, 1, 2}).face({0, -1, 1}).bytes()),
        {"mesh.ply", "face 1", "vertex index -1 out of range"});
  }
  expectMentions(plyErrorOf(SmallPly(false, "uchar", "uint")
                                .vertices()
                                .face({0, 1, 2})
                                .face({0, 4294967295.0, 1})
                                .bytes()),
                 {"mesh.ply", "face 1", "vertex index 4294967295 out of range"});
}

TEST(BinaryPly, RefusesCornerCountsBelowThreeOrAboveTheVerticesNamingTheFace) {
  expectMentions(plyErrorOf(SmallPly().vertices().face({0, 1, 2}).face({0, 1}).bytes()),
                 {"mesh.ply", "face 1", "2 corners; at least 3"});
  expectMentions(plyErrorOf(SmallPly(true, "char").vertices().face({0, 1, 2}).count(-3).bytes()),
                 {"mesh.ply", "face 1", "-3 corners"});
  // Absurd counts are refused before anything is read or reserved for them.
  for (bool bigEndian : {false, true})
    expectMentions(
        plyErrorOf(SmallPly(bigEndian, "uint").vertices().count(4000000000.0).bytes(1), 1 << 20),
        {"mesh.ply", "face 0", "4000000000 corners, more than the 3 vertices"});
  expectMentions(plyErrorOf(SmallPly(false, "int").vertices().count(-2147483648.0).bytes(1)),
                 {"mesh.ply", "face 0", "-2147483648 corners"});
  expectMentions(plyErrorOf(SmallPly(false, "ushort").vertices().count(4).bytes(1)),
                 {"mesh.ply", "face 0", "4 corners, more than the 3 vertices"});
}

TEST(BinaryPly, RefusesATruncatedFileNamingTheElementItEndsAt) {
  std::string bytes = SmallPly().vertices().face({0, 1, 2}).face({2, 1, 0}).bytes();
  expectMentions(plyErrorOf(bytes.substr(0, bytes.size() - 1)),
                 {"mesh.ply", "file ends at face 1 of 2"});
  expectMentions(plyErrorOf(bytes.substr(0, bytes.size() - 14)),
                 {"mesh.ply", "file ends at face 0 of 2"});
  expectMentions(
      plyErrorOf(SmallPly().vertices().bytes(0).substr(0, SmallPly().header(0).size() + 30)),
      {"mesh.ply", "file ends at vertex 2 of 3"});
}

// Counts in the header are checked against the file's size before
// anything is reserved: no MemoryLimitError, however small the budget.
TEST(BinaryPly, RefusesHeaderCountsTheFileCannotHoldBeforeReserving) {
  for (const char* element : {"vertex 2000000000", "face 1000000000"}) {
    const std::string declarations =
        std::string("element ") + (element[0] == 'v' ? element : "vertex 3") +
        "\nproperty float x\nproperty float y\nproperty float z\n" +
        (element[0] == 'f'
             ? std::string("element ") + element + "\nproperty list uchar int vertex_indices\n"
             : "");
    expectMentions(plyErrorOf(test::plyHeader({}, declarations) + std::string(64, '\0'), 1 << 20),
                   {"mesh.ply:", "can hold"});
  }
}

TEST(BinaryPly, RefusesAbsurdListsOfOtherElementsNamingThem) {
  const std::string declarations =
      "element vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
      "element region 1\nproperty list int uint members\n";
  for (double count : {2147483647.0, -5.0}) {
    test::PlyValues values(false);
    values.put("int", count);
    values.put("uint", 1);
    expectMentions(plyErrorOf(test::plyHeader({}, declarations) + values.bytes()),
                   {"mesh.ply", "region 0", count < 0 ? "-5 items" : "file ends at region 0"});
  }
}

TEST(BinaryPly, RefusesAnEmptyFileNamingIt) {
  expectMentions(plyErrorOf(""), {"mesh.ply", "empty file"});
}

// Several face elements all hold faces of the mesh, numbered on from one
// to the next (OpenMesh's reader, which they went to, kept only the last
// element's faces).
TEST(BinaryPly, ReadsTheFacesOfEveryFaceElement) {
  for (bool bigEndian : {false, true}) {
    SCOPED_TRACE(bigEndian ? "big-endian" : "little-endian");
    const std::string declarations =
        "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nelement edge 1\n"
        "property int a\nelement face 2\nproperty uchar flags\n"
        "property list uchar int vertex_indices\n";
    const auto bytes = [&](double lastCorner) {
      test::PlyValues body(bigEndian);
      for (double v : {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}) body.put("float", v);
      body.put("uchar", 3);
      for (double c : {0, 1, 2}) body.put("int", c);
      body.put("int", 7);  // the edge
      body.put("uchar", 0), body.put("uchar", 3);
      for (double c : {1, 3, 2}) body.put("int", c);
      body.put("uchar", 0), body.put("uchar", 4);
      for (double c : {0.0, 1.0, 3.0, lastCorner}) body.put("int", c);
      return test::plyHeader({bigEndian, "float", "uchar", "int", false}, declarations) +
             body.bytes();
    };
    const std::optional<MeshData> mesh = readPlyBytes(bytes(2));
    ASSERT_TRUE(mesh.has_value());
    // The quad (0 1 3 2), face 2 of the file, cut as OFF's reader cuts it.
    EXPECT_EQ(mesh->triangles,
              (std::vector<TriangleIndices>{{0, 1, 2}, {1, 3, 2}, {0, 1, 3}, {0, 3, 2}}));
    EXPECT_EQ(mesh->polygons.size() == 1 ? mesh->polygons[0].face : 0u, 2u);
    expectMentions(plyErrorOf(bytes(9)), {"mesh.ply", "face 2", "vertex index 9 out of range"});
  }
}

}  // namespace
}  // namespace meshtrace
