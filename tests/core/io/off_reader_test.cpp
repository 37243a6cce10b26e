// The OFF reader: real-world files it must accept, and bad files it must
// refuse with an InputError naming the file and the line or element.
#include "meshtrace/io/off_reader.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "meshtrace/geometry/polygon.h"
#include "support/files.h"
#include "support/input_errors.h"
#include "support/paths.h"
#include "support/scene_snippets.h"

namespace meshtrace {
namespace {

using test::expectMentions;

// Writes `text` as mesh.off in the test's scratch folder and reads it.
MeshData readOffText(std::string_view text) {
  return readOff(test::writeFile(test::scratchDir() / "mesh.off", text));
}

// The message of the error reading `text` as mesh.off raises.
std::string offErrorOf(std::string_view text) {
  const auto file = test::writeFile(test::scratchDir() / "mesh.off", text);
  return test::inputErrorOf([&] { readOff(file); });
}

TEST(OffReader, ReadsVerticesAndTriangles) {
  const MeshData mesh = readOffText(test::kTriangleOff);
  ASSERT_EQ(mesh.vertices.size(), 3u);
  EXPECT_EQ(mesh.vertices[2], Vec3(0, 1, 0));
  ASSERT_EQ(mesh.triangles.size(), 1u);
  EXPECT_EQ(mesh.triangles[0], (TriangleIndices{0, 1, 2}));
}

TEST(OffReader, AcceptsCommentsBlankLinesAndCrlf) {
  const MeshData mesh = readOffText(
      "# exported by some tool\r\nOFF\r\n\r\n# counts\r\n3 1 0\r\n-1 -1 0 # first\r\n"
      "\r\n1 -1 0\r\n0 1 0\r\n  \t\r\n3 0 1 2\r\n");
  ASSERT_EQ(mesh.vertices.size(), 3u);
  EXPECT_EQ(mesh.vertices[0], Vec3(-1, -1, 0));
  EXPECT_EQ(mesh.vertices[2], Vec3(0, 1, 0));
  ASSERT_EQ(mesh.triangles.size(), 1u);
  EXPECT_EQ(mesh.triangles[0], (TriangleIndices{0, 1, 2}));
}

TEST(OffReader, AcceptsCountsOnTheOffLine) {
  const MeshData mesh = readOffText("OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(mesh.vertices.size(), 3u);
  EXPECT_EQ(mesh.triangles.size(), 1u);
}

TEST(OffReader, AcceptsALastLineWithoutNewline) {
  const MeshData mesh = readOffText("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2");
  EXPECT_EQ(mesh.triangles.size(), 1u);
}

TEST(OffReader, TriangulatesPolygonsByCuttingEars) {
  // A quad and a pentagon: n corners give n - 2 triangles keeping the
  // polygon's winding; the quad as a fan from its first corner, the
  // pentagon as two ears and the triangle they leave (polygon.h).
  const MeshData mesh = readOffText(
      "OFF\n7 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n3 1 0\n2 2 0\n"
      "4 0 1 2 3\n5 1 4 5 6 2\n");
  ASSERT_EQ(mesh.triangles.size(), 2u + 3u);
  EXPECT_EQ(mesh.triangles[0], (TriangleIndices{0, 1, 2}));
  EXPECT_EQ(mesh.triangles[1], (TriangleIndices{0, 2, 3}));
  EXPECT_EQ(mesh.triangles[2], (TriangleIndices{1, 4, 5}));
  EXPECT_EQ(mesh.triangles[3], (TriangleIndices{5, 6, 2}));
  EXPECT_EQ(mesh.triangles[4], (TriangleIndices{1, 5, 2}));
}

// An L-shaped hexagon whose first ears would cut across its notch: read,
// its four triangles lie inside it and cover it (each turns its way, and
// their areas add up to its 3 square units).
TEST(OffReader, CutsANonConvexFaceIntoTrianglesInsideIt) {
  const MeshData mesh =
      readOffText("OFF\n6 1 0\n0 0 0\n2 0 0\n2 1 0\n1 1 0\n1 2 0\n0 2 0\n6 0 1 2 3 4 5\n");
  ASSERT_EQ(mesh.triangles.size(), 4u);
  double area = 0.0;
  for (const TriangleIndices& t : mesh.triangles) {
    const Vec3 doubled = glm::cross(mesh.vertices[t[1]] - mesh.vertices[t[0]],
                                    mesh.vertices[t[2]] - mesh.vertices[t[0]]);
    EXPECT_GT(doubled.z, 0.0);
    area += 0.5 * doubled.z;
  }
  EXPECT_DOUBLE_EQ(area, 3.0);
  EXPECT_EQ(mesh.untiledPolygons, 0u);
}

// The polygons' records stay with the mesh (the inspector names a
// triangle's face from them), so the memory plan counts them with the
// vertices and triangles: exactly the arrays' room, nothing unplanned.
TEST(OffReader, PlansThePolygonRecordsItKeeps) {
  std::string text = "OFF\n2002 1000 0\n";
  for (int i = 0; i <= 1000; ++i)
    text += std::to_string(i) + " 0 0\n" + std::to_string(i) + " 1 0\n";
  for (int i = 0; i < 1000; ++i)
    text += "4 " + std::to_string(2 * i) + " " + std::to_string(2 * i + 2) + " " +
            std::to_string(2 * i + 3) + " " + std::to_string(2 * i + 1) + "\n";
  MemoryBudget budget(std::uint64_t{1} << 30);
  const MeshData mesh = readOff(test::writeFile(test::scratchDir() / "quads.off", text), budget);
  ASSERT_EQ(mesh.polygons.size(), 1000u);
  EXPECT_EQ(budget.planned(), mesh.vertices.capacity() * sizeof(Vec3) +
                                  mesh.triangles.capacity() * sizeof(TriangleIndices) +
                                  mesh.polygons.capacity() * sizeof(PolygonFace));
}

TEST(OffReader, IgnoresPerFaceColourValuesAfterTheIndices) {
  const MeshData mesh = readOffText(
      "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2 255 0 0\n3 0 2 3 0.5 0.5 0.5 1.0\n");
  ASSERT_EQ(mesh.triangles.size(), 2u);
  EXPECT_EQ(mesh.triangles[1], (TriangleIndices{0, 2, 3}));
}

// A CR alone ends a line, as editors show it: a CRLF file with one bare CR
// reads as the same mesh, never as vertices run together.
TEST(OffReader, TakesALoneCrAsALineEnd) {
  const MeshData mesh = readOffText("OFF\r\n3 1 0\r\n-1 -1 0\r1 -1 0\r\n0 1 0\r\n3 0 1 2\r\n");
  ASSERT_EQ(mesh.vertices.size(), 3u);
  EXPECT_EQ(mesh.vertices[0], Vec3(-1, -1, 0));
  EXPECT_EQ(mesh.vertices[1], Vec3(1, -1, 0));
  EXPECT_EQ(mesh.vertices[2], Vec3(0, 1, 0));
  ASSERT_EQ(mesh.triangles.size(), 1u);
  const MeshData oldMac = readOffText("OFF\r3 1 0\r-1 -1 0\r1 -1 0\r0 1 0\r3 0 1 2\r");
  EXPECT_EQ(oldMac.vertices, mesh.vertices);
  EXPECT_EQ(oldMac.triangles, mesh.triangles);
}

// A bare CR inside a vertex line splits it: the vertex has too few
// coordinates, and the lines after it are counted with the CR as a line end.
TEST(OffReader, NamesTheLineOfAVertexABareCrCutShort) {
  expectMentions(offErrorOf("OFF\r\n3 1 0\r\n0 0 0\r\n1 0\r0\r\n0 1 0\r\n3 0 1 2\r\n"),
                 {"mesh.off:4", "vertex 1", "fewer than 3"});
  expectMentions(offErrorOf("OFF\r3 1 0\r\r0 0 0\n1 0 0\r\n0 1 0\r3 0 1 9\r"),
                 {"mesh.off:7", "face 0", "9"});
}

// A file of several megabytes is read in chunks of lines, in parallel.
// This one mixes the cases a chunk boundary can fall between: comments,
// blank lines, CRLF, quads, and it is built so that line L holds element
// L - 3 (vertex or face) wherever no blank line or comment was put in.
struct LargeOff {
  std::string text;
  MeshData expected;
  std::vector<std::size_t> faceLine;  // the line each face is on
  std::size_t quadsRecut = 0;         // quads that are not convex
};

LargeOff largeOff(std::uint32_t vertices, std::uint32_t faces) {
  LargeOff off;
  off.text = "OFF\n" + std::to_string(vertices) + " " + std::to_string(faces) + " 0\n";
  std::vector<PolygonFace> quads;
  std::size_t line = 2;
  for (std::uint32_t v = 0; v < vertices; ++v) {
    if (v % 997 == 0) off.text += "# a comment line\n", ++line;
    if (v % 1499 == 0) off.text += "\r\n", ++line;
    const Vec3 p(v * 0.5, -1.0 * (v % 101), v / 7.0);
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "%.17g %.17g %.17g%s\n", p.x, p.y, p.z,
                  v % 3 == 0 ? "\r" : "");
    off.text += buffer, ++line;
    off.expected.vertices.push_back(p);
  }
  for (std::uint32_t f = 0; f < faces; ++f) {
    const std::uint32_t a = f % vertices, b = (f * 7 + 1) % vertices, c = (f * 13 + 2) % vertices;
    if (f % 5 == 0) {
      const std::uint32_t d = (f * 17 + 3) % vertices;
      off.text += "4 " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) +
                  " " + std::to_string(d) + " # a quad\n";
      std::uint32_t corners[] = {a, b, c, d};
      appendPolygonTriangles(corners, off.expected.triangles, &quads);
    } else {
      off.text += "3 " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) +
                  " 255 0 0\n";
      off.expected.triangles.push_back({a, b, c});
    }
    off.faceLine.push_back(++line);
  }
  // The quads join vertices at random, so many are not convex and are cut
  // again: here face by face in one list, in the reader chunk by chunk.
  off.quadsRecut =
      tileNonConvexPolygons(off.expected.vertices, quads, off.expected.triangles).recut;
  return off;
}

TEST(OffReader, ReadsAFileOfManyChunksAsWritten) {
  const LargeOff off = largeOff(60000, 120000);
  ASSERT_GT(off.text.size(), std::size_t{4} << 20) << "several chunks";
  ASSERT_GT(off.quadsRecut, 1000u);
  const MeshData mesh = readOffText(off.text);
  EXPECT_EQ(mesh.vertices, off.expected.vertices);
  EXPECT_EQ(mesh.triangles, off.expected.triangles);
  // Every fifth face is a quad, each chunk numbering its own from its first
  // face: the file's face numbers must come out whole.
  ASSERT_EQ(mesh.polygons.size(), 120000u / 5);
  for (std::uint32_t k = 0; k < mesh.polygons.size(); ++k) {
    ASSERT_EQ(mesh.polygons[k].face, 5 * k);
    ASSERT_EQ(mesh.polygons[k].corners, 4u);
  }
}

// Of two bad lines in different chunks, the first in the file is reported,
// with its own line number, as a reader going line by line would.
TEST(OffReader, NamesTheFirstBadLineOfALargeFile) {
  LargeOff off = largeOff(60000, 120000);
  const auto breakFace = [&](std::uint32_t face, std::string_view with) {
    std::size_t at = 0;
    for (std::size_t l = 1; l < off.faceLine[face]; ++l) at = off.text.find('\n', at) + 1;
    off.text = off.text.substr(0, at).append(with).append(off.text, at);
  };
  breakFace(110000, "x");  // "x3 ...": not a corner count
  breakFace(70000, "-");   // "-3 ...": fewer than three corners
  expectMentions(offErrorOf(off.text),
                 {"mesh.off:" + std::to_string(off.faceLine[70000]), "face 70000", "corners"});
}

TEST(OffReader, NamesTheMissingFaceOfALargeFile) {
  LargeOff off = largeOff(60000, 120000);
  off.text.replace(off.text.find(" 120000 0"), 9, " 120001 0");
  expectMentions(offErrorOf(off.text), {"mesh.off", "face 120000 of 120001"});
}

TEST(OffReader, RejectsAMissingFileNamingIt) {
  const auto file = test::scratchDir() / "nowhere.off";
  expectMentions(test::inputErrorOf([&] { readOff(file); }), {"nowhere.off", "not found"});
}

TEST(OffReader, RejectsADirectoryNamingIt) {
  const auto dir = test::scratchDir() / "folder.off";
  std::filesystem::create_directory(dir);
  expectMentions(test::inputErrorOf([&] { readOff(dir); }), {"folder.off", "directory"});
}

// A named pipe has no size and might never end: refuse it rather than wait.
TEST(OffReader, RejectsANamedPipeWithoutWaiting) {
  const auto fifo = test::scratchDir() / "pipe.off";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expectMentions(test::inputErrorOf([&] { readOff(fifo); }), {"pipe.off"});
}

TEST(OffReader, RejectsAnEmptyFile) {
  expectMentions(offErrorOf(""), {"mesh.off", "empty"});
  expectMentions(offErrorOf("  \n# only a comment\n\n"), {"mesh.off", "empty"});
}

TEST(OffReader, RejectsABadHeaderNamingTheLine) {
  expectMentions(offErrorOf("# comment\nPLY\n3 1 0\n"), {"mesh.off:2", "header", "PLY"});
}

TEST(OffReader, RejectsMissingCounts) {
  expectMentions(offErrorOf("OFF\n"), {"mesh.off", "counts"});
}

TEST(OffReader, RejectsAWordWhereACountBelongs) {
  expectMentions(offErrorOf("OFF\nthree 1 0\n"), {"mesh.off:2", "count", "three"});
}

TEST(OffReader, RejectsANegativeCount) {
  expectMentions(offErrorOf("OFF\n-3 1 0\n0 0 0\n"), {"mesh.off:2", "negative"});
}

TEST(OffReader, RejectsTooFewVertexLinesNamingTheVertex) {
  // The header promises 4 vertices but the file ends after 3: the error
  // names the missing element.
  expectMentions(offErrorOf("OFF\n4 0 0\n0 0 0\n1 0 0\n0 1 0\n"), {"mesh.off", "vertex 3 of 4"});
}

TEST(OffReader, RejectsTooFewFaceLinesNamingTheFace) {
  expectMentions(offErrorOf("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
                 {"mesh.off", "face 1 of 2"});
}

TEST(OffReader, RejectsAVertexWithTooFewCoordinates) {
  expectMentions(offErrorOf("OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n"),
                 {"mesh.off:4", "vertex 1", "coordinates"});
}

TEST(OffReader, RejectsIndexOutOfRangeNamingTheFace) {
  expectMentions(offErrorOf("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 3\n"),
                 {"mesh.off:7", "face 1", "index 3", "out of range"});
}

TEST(OffReader, RejectsNegativeIndexNamingTheFace) {
  expectMentions(offErrorOf("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n"),
                 {"mesh.off:6", "face 0", "-1", "out of range"});
}

TEST(OffReader, RejectsAWordWhereAnIndexBelongs) {
  expectMentions(offErrorOf("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 one 2\n"),
                 {"mesh.off:6", "face 0", "one"});
}

TEST(OffReader, RejectsAFaceWithFewerThanThreeCorners) {
  expectMentions(offErrorOf("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n"),
                 {"mesh.off:6", "face 0", "corners"});
}

TEST(OffReader, RejectsAFaceListingFewerIndicesThanItsCornerCount) {
  expectMentions(offErrorOf("OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n4 0 1 2\n"),
                 {"mesh.off:7", "face 0", "announces 4 corners"});
}

TEST(OffReader, RejectsAHugeCornerCountWithoutLooping) {
  const auto start = std::chrono::steady_clock::now();
  expectMentions(offErrorOf("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n"),
                 {"mesh.off:6", "face 0"});
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
}

// A polygon lists each corner once: a face of more corners than the mesh
// has vertices repeats them, and would fan into as many triangles.
TEST(OffReader, RejectsAFaceOfMoreCornersThanTheMeshHasVertices) {
  expectMentions(offErrorOf("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2 0\n"),
                 {"mesh.off:6", "face 0", "4 corners", "3 vertices"});
}

// The arrays are planned before they are allocated: a budget too small for
// them refuses the mesh, naming it.
TEST(OffReader, RefusesArraysBeyondItsMemoryBudget) {
  const LargeOff off = largeOff(60000, 120000);
  const auto file = test::writeFile(test::scratchDir() / "mesh.off", off.text);
  MemoryBudget budget(1 << 20);  // the vertices alone need 1.4 MB
  try {
    readOff(file, budget);
    FAIL() << "the mesh was read within 1 MB";
  } catch (const MemoryLimitError& e) {
    expectMentions(e.what(), {"cannot load the 60000 vertices of mesh.off", "limit of 1.0 MB"});
  }
  MemoryBudget enough(16 << 20);
  EXPECT_EQ(readOff(file, enough).triangles.size(), off.expected.triangles.size());
  EXPECT_GE(enough.planned(), 60000 * sizeof(Vec3) + off.expected.triangles.size() * 12);
}

TEST(OffReader, RejectsANanVertexNamingTheLine) {
  expectMentions(offErrorOf("OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n"),
                 {"mesh.off:4", "vertex 1", "non-finite"});
}

TEST(OffReader, RejectsAnInfiniteVertexNamingTheLine) {
  expectMentions(offErrorOf("OFF\n3 1 0\n0 0 0\n1 0 0\n0 -inf 0\n3 0 1 2\n"),
                 {"mesh.off:5", "vertex 2", "non-finite"});
}

TEST(OffReader, RejectsAWordWhereACoordinateBelongs) {
  expectMentions(offErrorOf("OFF\n3 1 0\n0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n"),
                 {"mesh.off:4", "vertex 1", "'x'", "not a number"});
}

// Counts that a file of this size cannot hold are refused by comparing with
// the file size, before anything is reserved: no bad_alloc, no waiting.
TEST(OffReader, RejectsCountsInTheBillionsBeforeReserving) {
  const auto start = std::chrono::steady_clock::now();
  expectMentions(offErrorOf("OFF\n3000000000 6000000000 0\n0 0 0\n"),
                 {"mesh.off", "3000000000 vertices", "byte"});
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
}

// Counts chosen so that count * (bytes per line) wraps around 2^64 to a small
// number: the size check must not overflow.
TEST(OffReader, RejectsCountsWhoseByteEstimateWouldOverflow) {
  expectMentions(offErrorOf("OFF\n3074457345618258603 0 0\n0 0 0\n"), {"mesh.off", "vertices"});
  expectMentions(offErrorOf("OFF\n0 2305843009213693952 0\n0 0 0\n"), {"mesh.off", "faces"});
  expectMentions(offErrorOf("OFF\n9223372036854775807 9223372036854775807 0\n"),
                 {"mesh.off", "vertices"});
}

TEST(OffReader, RejectsCountsTooLargeForAnInteger) {
  expectMentions(offErrorOf("OFF\n99999999999999999999 1 0\n"), {"mesh.off:2", "count"});
}

TEST(OffReader, RejectsBinaryGarbageWithNulBytes) {
  const std::string garbage(
      "\x7f"
      "ELF\x02\x01\x01\0\0\0\0\0\0\0\0\0\x03\0>\0",
      20);
  expectMentions(offErrorOf(garbage), {"mesh.off", "binary"});
}

// The file is checked for NUL bytes piece by piece as it streams: the first
// in the file is the one reported, with its line, wherever the pieces fall.
TEST(OffReader, NamesTheLineOfTheFirstNulByteOfALargeFile) {
  LargeOff off = largeOff(60000, 120000);
  ASSERT_GT(off.text.size(), std::size_t{4} << 20) << "several pieces";
  const std::size_t first = (std::size_t{3} << 20) + 5;
  off.text[off.text.size() - 10] = '\0';
  off.text[first + 1] = '\0';
  off.text[first] = '\0';
  const auto line = 1 + std::count(off.text.begin(), off.text.begin() + first, '\n');
  expectMentions(offErrorOf(off.text), {"mesh.off:" + std::to_string(line) + ":", "binary"});
}

// A 2 GB file (sparse: it costs no disk) with a NUL byte at offset 10 is
// refused at once, with the line of the NUL, without reading the rest.
TEST(OffReader, FindsANulNearTheStartOfAHugeFileAtOnce) {
  const auto file =
      test::writeFile(test::scratchDir() / "mesh.off", std::string("OFF\n3 1 0\n", 10));
  std::filesystem::resize_file(file, std::uintmax_t{2} << 30);  // zeros from offset 10 on
  const auto start = std::chrono::steady_clock::now();
  const std::string message = test::inputErrorOf([&] { readOff(file); });
  const auto seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start);
  std::filesystem::remove(file);
  expectMentions(message, {"mesh.off:3:", "binary", "NUL"});
  // Reading the file whole took 7.5 s; one piece takes microseconds.
  EXPECT_LT(seconds.count(), 1.0);
}

TEST(OffReader, SaysASymlinkLoopIsOne) {
  const auto dir = test::scratchDir();
  std::filesystem::create_symlink("b.off", dir / "a.off");
  std::filesystem::create_symlink("a.off", dir / "b.off");
  const std::string message = test::inputErrorOf([&] { readOff(dir / "a.off"); });
  expectMentions(message, {"a.off", "symbolic links"});
  EXPECT_EQ(message.find("not found"), std::string::npos) << message;
}

TEST(OffReader, SaysASymlinkPointsNowhere) {
  const auto dir = test::scratchDir();
  std::filesystem::create_symlink("gone.off", dir / "link.off");
  expectMentions(test::inputErrorOf([&] { readOff(dir / "link.off"); }),
                 {"link.off", "symlink to a file that does not exist"});
}

TEST(OffReader, RejectsBinaryGarbageWithoutNulBytes) {
  expectMentions(offErrorOf("\x89PNG\r\n\x1a\n\xff\xfe\xfd\x80\x81"), {"mesh.off:1", "header"});
}

}  // namespace
}  // namespace meshtrace
