// The ASCII PLY reader: the mesh OFF's reader reads from the same numbers,
// in double whatever type the header declares; properties in any order,
// lists and elements of other kinds around the mesh's; files of many
// pieces; and bad records refused with an InputError naming the file, the
// line and the element.
#include <gtest/gtest.h>

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "meshtrace/io/off_reader.h"
#include "meshtrace/io/ply_reader.h"
#include "support/files.h"
#include "support/input_errors.h"
#include "support/paths.h"
#include "support/polygon_files.h"

namespace meshtrace {
namespace {

using test::expectMentions;

std::string shortest(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

// The polygons' vertices moved off the float grid (x + 0.1 is no float), so
// that a reader in float would not give OFF's mesh.
test::PolygonMesh offGridMesh(int copies = 1) {
  test::PolygonMesh mesh = test::polygonMesh(copies);
  for (Vec3& v : mesh.vertices) v += Vec3(0.1, 1.0 / 3.0, -0.7);
  return mesh;
}

std::string offOf(const test::PolygonMesh& mesh) {
  std::string out = "OFF\n" + std::to_string(mesh.vertices.size()) + " " +
                    std::to_string(mesh.faces.size()) + " 0\n";
  for (const Vec3& v : mesh.vertices)
    out += shortest(v.x) + " " + shortest(v.y) + " " + shortest(v.z) + "\n";
  for (const auto& face : mesh.faces) {
    out += std::to_string(face.size());
    for (std::uint32_t i : face) {
      out += ' ';  // not " " + ...: GCC 12 warns (-Wrestrict) wrongly on that
      out += std::to_string(i);
    }
    out += "\n";
  }
  return out;
}

// The mesh as ASCII PLY: vertices "x y z", faces "n i j k...", the header's
// coordinate type `type`.
std::string asciiPlyOf(const test::PolygonMesh& mesh, const std::string& type = "float") {
  std::string out = "ply\nformat ascii 1.0\ncomment made by a test\nelement vertex " +
                    std::to_string(mesh.vertices.size()) + "\nproperty " + type + " x\nproperty " +
                    type + " y\nproperty " + type + " z\nelement face " +
                    std::to_string(mesh.faces.size()) +
                    "\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string off = offOf(mesh);
  return out + off.substr(off.find('\n', 4) + 1);  // the OFF body after its counts line
}

MeshData readOffText(const std::string& text) {
  return readOff(test::writeFile(test::scratchDir() / "mesh.off", text));
}

std::optional<MeshData> readAscii(const std::string& text) {
  MemoryBudget budget(defaultMemoryLimit());
  return readPly(test::writeFile(test::scratchDir() / "mesh.ply", text), budget);
}

std::string errorOf(const std::string& text) {
  const auto file = test::writeFile(test::scratchDir() / "mesh.ply", text);
  MemoryBudget budget(defaultMemoryLimit());
  return test::inputErrorOf([&] { readPly(file, budget); });
}

TEST(AsciiPly, ReadsTheMeshOffsReaderReadsFromTheSameNumbersInDouble) {
  const test::PolygonMesh polygons = offGridMesh();
  const MeshData off = readOffText(offOf(polygons));
  for (const char* type : {"float", "double", "float32"}) {
    SCOPED_TRACE(type);
    const std::optional<MeshData> ply = readAscii(asciiPlyOf(polygons, type));
    ASSERT_TRUE(ply.has_value());
    EXPECT_EQ(ply->vertices, off.vertices);
    EXPECT_EQ(ply->triangles, off.triangles);
    EXPECT_EQ(ply->triangles.size(), 2u + 1u + 4u + 1u + 3u + 2u + 4u);
    // Not the float the header's type would round the text to.
    EXPECT_EQ(ply->vertices[0].x, 0.1);
    EXPECT_NE(ply->vertices[0].x, static_cast<double>(0.1f));
  }
}

// Properties around the coordinates, lists of varying length among them,
// y before x, integer coordinates, the faces first, elements of other
// kinds (one with no properties, whose records take no line), blank lines
// and CRLF line ends.
TEST(AsciiPly, ReadsPropertiesInAnyOrderAndSkipsWhatIsNotTheMesh) {
  const std::string text =
      "ply\r\nformat ascii 1.0\r\n"
      "element face 2\r\nproperty uchar flags\r\nproperty list uchar uint vertex_indices\r\n"
      "property list uchar float texcoord\r\n"
      "element nothing 1000000\r\n"
      "element vertex 4\r\nproperty list uchar float weights\r\nproperty float y\r\n"
      "property int x\r\nproperty double z\r\nproperty uchar red\r\n"
      "element edge 1\r\nproperty int vertex1\r\nproperty int vertex2\r\nend_header\r\n"
      "7 3 0 1 2 0\r\n"
      "\r\n"
      "0 4 0 2 3 1 6 0 0 1 0 1 1\r\n"
      "0 0.5 -3 1e-300 255\r\n"
      "2 0.5 0.25 0.5 2147483647 0.1 0\r\n"
      "1 1 +1.5e1 -1 -2 7\r\n"
      "\t 0   2 -2147483648 0 1\r\n"
      "0 1\r\n";
  const std::optional<MeshData> mesh = readAscii(text);
  ASSERT_TRUE(mesh.has_value());
  EXPECT_EQ(mesh->vertices,
            (std::vector<Vec3>{
                {-3, 0.5, 1e-300}, {2147483647, 0.5, 0.1}, {-1, 15, -2}, {-2147483648.0, 2, 0}}));
  const MeshData off = readOffText(
      "OFF\n4 2 0\n-3 0.5 1e-300\n2147483647 0.5 0.1\n-1 15 -2\n-2147483648 2 0\n"
      "3 0 1 2\n4 0 2 3 1\n");
  EXPECT_EQ(mesh->vertices, off.vertices);
  EXPECT_EQ(mesh->triangles, off.triangles);
  EXPECT_EQ(mesh->triangles.size(), 3u);
}

// Several face elements all hold faces of the mesh, numbered on from one
// to the next.
TEST(AsciiPly, ReadsTheFacesOfEveryFaceElement) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
      "element edge 1\nproperty int a\nelement face 2\nproperty uchar flags\n"
      "property list uchar int vertex_indices\nend_header\n";
  const std::string body = "0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n7\n0 3 1 3 2\n";
  const std::optional<MeshData> mesh = readAscii(header + body + "0 4 0 1 3 2\n");
  ASSERT_TRUE(mesh.has_value());
  ASSERT_EQ(mesh->triangles.size(), 4u);
  EXPECT_EQ(mesh->triangles[0], (TriangleIndices{0, 1, 2}));
  EXPECT_EQ(mesh->triangles[1], (TriangleIndices{1, 3, 2}));
  ASSERT_EQ(mesh->polygons.size(), 1u);
  EXPECT_EQ(mesh->polygons[0].face, 2u);  // the quad: face 2 of the file
  expectMentions(errorOf(header + body + "0 4 0 1 3 9\n"),
                 {"mesh.ply:22", "face 2", "vertex index 9 out of range"});
}

// Many pieces, read in parallel: the mesh OFF's reader reads, and the first
// bad record named by its own line, however far into the file.
TEST(AsciiPly, ReadsAFileOfManyPiecesAndNamesTheLineOfItsFirstBadRecord) {
  const test::PolygonMesh polygons = offGridMesh(20000);
  const std::string text = asciiPlyOf(polygons, "double");
  ASSERT_GT(text.size(), std::size_t{8} << 20);
  const std::optional<MeshData> ply = readAscii(text);
  ASSERT_TRUE(ply.has_value());
  const MeshData off = readOffText(offOf(polygons));
  EXPECT_EQ(ply->vertices, off.vertices);
  EXPECT_EQ(ply->triangles, off.triangles);
  EXPECT_EQ(ply->polygons.size(), off.polygons.size());

  // Faces 100,000 and 120,000 broken: the first is named, by its line.
  const std::size_t headerLines = 10;
  const std::size_t vertices = polygons.vertices.size();
  std::string broken = text;
  for (std::size_t face : {std::size_t{120000}, std::size_t{100000}}) {
    std::size_t at = 0;
    for (std::size_t line = 0; line < headerLines + vertices + face; ++line)
      at = broken.find('\n', at) + 1;
    broken.replace(at, broken.find('\n', at) - at, "3 0 1 x");
  }
  expectMentions(errorOf(broken),
                 {"mesh.ply:" + std::to_string(headerLines + vertices + 100000 + 1), "face 100000",
                  "vertex_indices is 'x', not an integer"});
}

TEST(AsciiPly, RefusesABadRecordNamingItsLineAndElement) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
      "property uchar flags\nend_header\n";
  const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
  struct Bad {
    std::string body;
    std::vector<std::string> mentions;
  };
  const Bad bads[] = {
      {"0 0 0\n1 zero 0\n0 1 0\n3 0 1 2 0\n",
       {"mesh.ply:12", "vertex 1", "y is 'zero', not a number"}},
      {vertices + "3 0 1 2 1.5\n", {"mesh.ply:14", "face 0", "flags is '1.5', not an integer"}},
      {vertices + "3 0 1.0 2 0\n", {"mesh.ply:14", "face 0", "'1.0', not an integer"}},
      {"0 0 0\n1 0\n0 1 0\n3 0 1 2 0\n", {"mesh.ply:12", "vertex 1", "line ends at z"}},
      {vertices + "3 0 1 2\n", {"mesh.ply:14", "face 0", "line ends at flags"}},
      {"0 0 0 7\n1 0 0\n0 1 0\n3 0 1 2 0\n",
       {"mesh.ply:11", "vertex 0", "'7' after its 3 properties"}},
      {vertices + "3 0 1 2 0 0\n", {"mesh.ply:14", "face 0", "after its 2 properties"}},
      {vertices + "x 0 1 2 0\n", {"mesh.ply:14", "face 0", "bad list count 'x'"}},
      {vertices + "-3 0 1 2 0\n", {"mesh.ply:14", "face 0", "bad list count '-3'"}},
      {vertices + "2 0 1 0\n", {"mesh.ply:14", "face 0", "2 corners; at least 3"}},
      {vertices + "4 0 1 2 1 0\n",
       {"mesh.ply:14", "face 0", "4 corners, more than the 3 vertices"}},
      {vertices + "3 0 1 3 0\n", {"mesh.ply:14", "face 0", "vertex index 3 out of range"}},
      {vertices + "3 0 -1 2 0\n", {"mesh.ply:14", "face 0", "vertex index -1 out of range"}},
      {"0 0 0\n1 nan 0\n0 1 0\n3 0 1 2 0\n", {"mesh.ply:12", "vertex 1", "non-finite", "'nan'"}},
      {"0 0 0\n1 0 0\n0 1 -inf\n3 0 1 2 0\n", {"mesh.ply:13", "vertex 2", "non-finite"}},
      {"0 0 1e999\n1 0 0\n0 1 0\n3 0 1 2 0\n", {"mesh.ply:11", "vertex 0", "'1e999'"}},
      {"0 0 0\n1 0 0\n", {"mesh.ply", "file ends at vertex 2 of 3"}},
      {vertices, {"mesh.ply", "file ends at face 0 of 1"}},
      {"0 0 0\n1 0 0\n0 1", {"mesh.ply:13", "vertex 2", "line ends at z"}},
      {vertices + std::string("3 0 1\0 2 0\n", 11), {"mesh.ply:14", "NUL"}},
  };
  for (const Bad& bad : bads) {
    SCOPED_TRACE(bad.body);
    const std::string message = errorOf(header + bad.body);
    for (const std::string& part : bad.mentions)
      EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
  }
  const std::optional<MeshData> good = readAscii(header + vertices + "3 0 1 2 0\n");
  ASSERT_TRUE(good.has_value());
  EXPECT_EQ(good->triangles, (std::vector<TriangleIndices>{{0, 1, 2}}));
}

}  // namespace
}  // namespace meshtrace
