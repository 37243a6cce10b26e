// The OBJ reader: the statements exporters write, which it must read or
// skip, and bad files it must refuse with an InputError naming the file and
// the line.
#include "meshtrace/io/obj_reader.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "meshtrace/geometry/polygon.h"
#include "meshtrace/io/off_reader.h"
#include "support/files.h"
#include "support/input_errors.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

using test::expectMentions;

MeshData readObjText(std::string_view text) {
  MemoryBudget budget(defaultMemoryLimit());
  return readObj(test::writeFile(test::scratchDir() / "mesh.obj", text), budget);
}

std::string objErrorOf(std::string_view text) {
  const auto file = test::writeFile(test::scratchDir() / "mesh.obj", text);
  return test::inputErrorOf([&] {
    MemoryBudget budget(defaultMemoryLimit());
    readObj(file, budget);
  });
}

TEST(ObjReader, ReadsEveryFormOfCornerAndRelativeIndices) {
  const MeshData mesh = readObjText(
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
      "f 1/1 2/2/2 3//3\n"  // with texture and normal indices
      "f -4 -2 -1\n");      // back from the last vertex above
  ASSERT_EQ(mesh.vertices.size(), 4u);
  EXPECT_EQ(mesh.vertices[2], Vec3(1, 1, 0));
  ASSERT_EQ(mesh.triangles.size(), 2u);
  EXPECT_EQ(mesh.triangles[0], (TriangleIndices{0, 1, 2}));
  EXPECT_EQ(mesh.triangles[1], (TriangleIndices{0, 2, 3}));
}

TEST(ObjReader, SkipsOtherStatementsCommentsAndCrlf) {
  const MeshData mesh = readObjText(
      "# exported by some tool\r\nmtllib missing.mtl\r\no thing\r\ng part\r\n"
      "v -1 -1 0 1.0\r\n"         // w
      "v 1 -1 0 0.5 0.5 0.5\r\n"  // a colour
      "vt 0 0\r\nvn 0 0 1\r\nvp 0.5\r\n\r\n  \t\r\n"
      "v 0 1 0 # a comment\r\n"
      "usemtl red\r\ns 1\r\nl 1 2\r\np 3\r\nf 1/1/1 2/1/1 3/1/1 # the face\r\n");
  ASSERT_EQ(mesh.vertices.size(), 3u);
  EXPECT_EQ(mesh.vertices[0], Vec3(-1, -1, 0));
  EXPECT_EQ(mesh.vertices[2], Vec3(0, 1, 0));
  ASSERT_EQ(mesh.triangles.size(), 1u);
  EXPECT_EQ(mesh.triangles[0], (TriangleIndices{0, 1, 2}));
}

// Every digit of a coordinate is kept: OpenMesh's reader, which read OBJ
// before, rounded them to float.
TEST(ObjReader, KeepsCoordinatesInDoublePrecision) {
  const MeshData mesh = readObjText(
      "v 0.1 1e-300 3.141592653589793\nv 1 0 0\nv -0.013166238617716368 1 0\nf 1 2 3\n");
  EXPECT_EQ(mesh.vertices[0], Vec3(0.1, 1e-300, 3.141592653589793));
  EXPECT_EQ(mesh.vertices[2].x, -0.013166238617716368);
}

// A polygon becomes the triangles an OFF face of the same corners does,
// and one that is not convex is cut again by ear clipping.
TEST(ObjReader, TriangulatesPolygonsAsOffDoes) {
  const std::string vertices =
      "0 0 0\n4 0 0\n4 4 0\n2 1 0\n0 4 0\n"  // an arrow, not convex at (2 1)
      "5 0 0\n6 0 0\n6 1 0\n5 1 0\n";        // a square
  std::string obj, off = "OFF\n9 3 0\n" + vertices + "5 0 1 2 3 4\n4 5 6 7 8\n3 0 1 2\n";
  for (std::size_t at = 0; at < vertices.size();) {
    const std::size_t end = vertices.find('\n', at);
    obj += "v " + vertices.substr(at, end + 1 - at);
    at = end + 1;
  }
  obj += "f 1 2 3 4 5\nf 6 7 8 9\nf 1 2 3\n";
  const MeshData fromObj = readObjText(obj);
  const MeshData fromOff = readOff(test::writeFile(test::scratchDir() / "mesh.off", off));
  EXPECT_EQ(fromObj.vertices, fromOff.vertices);
  EXPECT_EQ(fromObj.triangles, fromOff.triangles);
  ASSERT_EQ(fromObj.polygons.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(fromObj.polygons[k].face, fromOff.polygons[k].face);
    EXPECT_EQ(fromObj.polygons[k].firstTriangle, fromOff.polygons[k].firstTriangle);
    EXPECT_EQ(fromObj.polygons[k].corners, fromOff.polygons[k].corners);
  }
}

// A file of many pieces, as exporters write them: each object's vertices,
// then its faces, by indices counted back from its last vertex; quads
// among the triangles, comments and blank lines here and there. `faceLine`
// is the line each face is on.
struct LargeObj {
  std::string text;
  MeshData expected;
  std::vector<std::size_t> faceLine;
};

LargeObj largeObj(std::uint32_t parts) {
  LargeObj obj;
  std::size_t line = 0;
  std::vector<PolygonFace> quads;
  for (std::uint32_t part = 0; part < parts; ++part) {
    obj.text += "o part" + std::to_string(part) + "\n", ++line;
    const auto first = static_cast<std::uint32_t>(obj.expected.vertices.size());
    for (std::uint32_t v = 0; v < 20; ++v) {
      const Vec3 p(part + 0.01 * v, -1.0 * (v % 7), v / 7.0 + part / 3.0);
      char buffer[96];
      std::snprintf(buffer, sizeof buffer, "v %.17g %.17g %.17g\n", p.x, p.y, p.z);
      obj.text += buffer, ++line;
      obj.expected.vertices.push_back(p);
    }
    if (part % 13 == 0) obj.text += "# a comment\n\n", line += 2;
    for (std::uint32_t f = 0; f < 30; ++f) {
      const std::uint32_t a = f % 20, b = (f * 7 + 1) % 20, c = (f * 13 + 2) % 20;
      const auto back = [](std::uint32_t v) { return static_cast<int>(v) - 20; };
      char buffer[96];
      if (f % 5 == 0) {
        const std::uint32_t d = (f * 17 + 3) % 20;
        std::snprintf(buffer, sizeof buffer, "f %d %d %d %d\n", back(a), back(b), back(c), back(d));
        obj.text += buffer;
        std::uint32_t corners[] = {first + a, first + b, first + c, first + d};
        appendPolygonTriangles(corners, obj.expected.triangles, &quads);
      } else {
        std::snprintf(buffer, sizeof buffer, "f %d/1 %d/1 %d/1\n", back(a), back(b), back(c));
        obj.text += buffer;
        obj.expected.triangles.push_back({first + a, first + b, first + c});
      }
      obj.faceLine.push_back(++line);
    }
  }
  tileNonConvexPolygons(obj.expected.vertices, quads, obj.expected.triangles);
  return obj;
}

TEST(ObjReader, ReadsAFileOfManyPiecesAsWritten) {
  const LargeObj obj = largeObj(12000);
  ASSERT_GT(obj.text.size(), std::size_t{4} << 20) << "several pieces";
  const MeshData mesh = readObjText(obj.text);
  EXPECT_EQ(mesh.vertices, obj.expected.vertices);
  EXPECT_EQ(mesh.triangles, obj.expected.triangles);
  // Every fifth face is a quad, each piece numbering its own from its first
  // face: the file's face numbers must come out whole.
  ASSERT_EQ(mesh.polygons.size(), 12000u * 30 / 5);
  for (std::uint32_t k = 0; k < mesh.polygons.size(); ++k) ASSERT_EQ(mesh.polygons[k].face, 5 * k);
}

// Of two bad lines in different pieces, the first in the file is reported,
// with its own line number, as a reader going line by line would.
TEST(ObjReader, NamesTheFirstBadLineOfALargeFile) {
  LargeObj obj = largeObj(12000);
  const auto breakFace = [&](std::size_t face, std::string_view with) {
    std::size_t at = 0;
    for (std::size_t l = 1; l < obj.faceLine[face]; ++l) at = obj.text.find('\n', at) + 1;
    obj.text = obj.text.substr(0, at + 1).append(with).append(obj.text, at + 1);  // after "f"
  };
  breakFace(300000, " 0");           // a corner naming no vertex
  breakFace(200000, " -999999999");  // further back than the file's first vertex
  expectMentions(objErrorOf(obj.text), {"mesh.obj:" + std::to_string(obj.faceLine[200000]),
                                        "face 200000", "'-999999999'"});
}

TEST(ObjReader, RefusesCornersNamingNoVertexAboveThem) {
  const std::string three = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expectMentions(objErrorOf(three + "f 1 2 0\n"), {"mesh.obj:4", "face 0", "'0'", "above"});
  expectMentions(objErrorOf(three + "f 1 2 4\n"), {"mesh.obj:4", "'4'", "3 vertices"});
  expectMentions(objErrorOf(three + "f 1 2 -4\n"), {"mesh.obj:4", "'-4'"});
  expectMentions(objErrorOf(three + "f 1 2 99999999999999999999\n"),
                 {"mesh.obj:4", "'99999999999999999999'"});
  expectMentions(objErrorOf(three + "f 1 2 x/1\n"), {"mesh.obj:4", "'x/1'"});
  expectMentions(objErrorOf("v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n"), {"mesh.obj:3", "'3'"});
}

TEST(ObjReader, RefusesFacesOfTooFewOrTooManyCorners) {
  expectMentions(objErrorOf("v 0 0 0\nv 1 0 0\nf 1 2\n"), {"mesh.obj:3", "face 0", "2 corners"});
  expectMentions(objErrorOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 1\n"),
                 {"mesh.obj:4", "face 0", "4 corners"});
}

TEST(ObjReader, RefusesVerticesWithoutThreeFiniteNumbers) {
  expectMentions(objErrorOf("v 0 0\n"), {"mesh.obj:1", "vertex 0", "fewer than 3 coordinates"});
  expectMentions(objErrorOf("v 0 0 0\nv 1 nan 0\n"), {"mesh.obj:2", "vertex 1", "non-finite"});
  expectMentions(objErrorOf("v 0 0 0\nv 1 inf 0\n"), {"mesh.obj:2", "non-finite"});
  expectMentions(objErrorOf("v 0 zero 0\n"), {"mesh.obj:1", "'zero'"});
}

TEST(ObjReader, RefusesAFileWithoutVertices) {
  expectMentions(objErrorOf(""), {"mesh.obj", "no vertex"});
  expectMentions(objErrorOf("# nothing\nvt 0 0\ng group\n"), {"mesh.obj", "no vertex"});
}

TEST(ObjReader, RefusesBinaryDataNamingTheLineOfTheNul) {
  expectMentions(objErrorOf(std::string("v 0 0 0\nv 1 0 0\n\0", 17)), {"mesh.obj:3", "NUL"});
}

// The arrays are planned before they are allocated: a budget too small
// refuses the mesh, naming it.
TEST(ObjReader, RefusesArraysBeyondItsMemoryBudget) {
  const LargeObj obj = largeObj(12000);
  const auto file = test::writeFile(test::scratchDir() / "mesh.obj", obj.text);
  MemoryBudget budget(1 << 20);  // the vertices alone need 5.8 MB
  try {
    readObj(file, budget);
    FAIL() << "the mesh was read within 1 MB";
  } catch (const MemoryLimitError& e) {
    expectMentions(e.what(), {"mesh.obj", "limit of 1.0 MB"});
  }
  MemoryBudget enough(64 << 20);
  EXPECT_EQ(readObj(file, enough).triangles.size(), obj.expected.triangles.size());
  EXPECT_GE(enough.planned(), obj.expected.vertices.size() * sizeof(Vec3));
}

}  // namespace
}  // namespace meshtrace
