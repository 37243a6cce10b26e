#pragma once
// A small polygon mesh (triangles, quads, a pentagon and a hexagon sharing
// vertices, and an L) written as OFF and OBJ text and as binary PLY of several layouts, built
// value by value from the PLY spec, for tests of the mesh readers.
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "meshtrace/geometry/mesh.h"

namespace meshtrace::test {

struct PolygonMesh {
  std::vector<Vec3> vertices;
  std::vector<std::vector<std::uint32_t>> faces;
};

// The layout of a binary PLY file: the byte order, the type of the
// coordinates, of the corner lists' counts and of their indices, and
// whether other elements and properties surround the ones a mesh needs.
struct PlyLayout {
  bool bigEndian = false;
  const char* coordinateType = "float";
  const char* countType = "uchar";
  const char* indexType = "int";
  bool extras = false;
};
// "big-endian double, int counts, uint indices, with extras", for test names and failures.
std::string describe(const PlyLayout& layout);
// How gtest prints a layout that a test fails with.
inline void PrintTo(const PlyLayout& layout, std::ostream* out) { *out << describe(layout); }

// Vertices on a 1/8 grid (exact as floats), polygons of 3 to 6 corners, one
// of them (an L) not convex.
// `copies` side by side grow it to any size.
PolygonMesh polygonMesh(int copies = 1);

std::string offText(const PolygonMesh& mesh);
// The same as OBJ, after all the vertices, its faces' corners in every form
// (i, i/t, i//n, i/t/n, and counted back from the last vertex).
std::string objText(const PolygonMesh& mesh);

// Values of a PLY type named as a header names it ("uchar", "float"), in
// the byte order of the file being built.
class PlyValues {
 public:
  explicit PlyValues(bool bigEndian) : bigEndian_(bigEndian) {}
  void put(const std::string& type, double value);
  std::string& bytes() { return bytes_; }

 private:
  bool bigEndian_;
  std::string bytes_;
};

// "ply", the format line for `layout`'s byte order, and `declarations`
// (element and property lines, each ending with a newline), end_header.
std::string plyHeader(const PlyLayout& layout, const std::string& declarations);

std::string binaryPly(const PolygonMesh& mesh, const PlyLayout& layout);

}  // namespace meshtrace::test
