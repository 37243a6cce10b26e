#include "support/polygon_files.h"

#include <algorithm>
#include <cstring>
#include <initializer_list>
#include <stdexcept>
#include <utility>

namespace meshtrace::test {

PolygonMesh polygonMesh(int copies) {
  PolygonMesh mesh;
  for (int c = 0; c < copies; ++c) {
    const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
    // A strip of points on two rows, then two apexes above it.
    for (int i = 0; i < 6; ++i) {
      mesh.vertices.emplace_back(c * 8.0 + i, 0.0, 0.125 * i);
      mesh.vertices.emplace_back(c * 8.0 + i, 1.0, -0.25 * i);
    }
    mesh.vertices.emplace_back(c * 8.0 + 1.5, 2.0, 0.5);
    mesh.vertices.emplace_back(c * 8.0 + 3.5, 2.5, -0.375);
    // An L, in a plane of its own: not convex, so its first ears would
    // reach across the notch and every reader must cut it again alike.
    for (const auto& [x, y] :
         std::initializer_list<std::pair<int, int>>{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}})
      mesh.vertices.emplace_back(c * 8.0 + x, 3.0 + 0.5 * y, 1.0 + 0.25 * x);
    const auto f = [&](std::vector<std::uint32_t> corners) {
      for (std::uint32_t& k : corners) k += base;
      mesh.faces.push_back(std::move(corners));
    };
    f({0, 2, 3, 1});        // a quad
    f({2, 4, 3});           // a triangle
    f({4, 6, 8, 9, 7, 5});  // a hexagon
    f({1, 3, 12});          // a triangle
    f({3, 5, 7, 13, 12});   // a pentagon
    f({8, 10, 11, 9});      // a quad
    f({14, 15, 16, 17, 18, 19});  // the L
  }
  return mesh;
}

std::string describe(const PlyLayout& layout) {
  return std::string(layout.bigEndian ? "big-endian " : "little-endian ") + layout.coordinateType +
         ", " + layout.countType + " counts, " + layout.indexType + " indices" +
         (layout.extras ? ", with extras" : "");
}

std::string offText(const PolygonMesh& mesh) {
  // Appended piece by piece: GCC 12 warns (-Wrestrict) wrongly on
  // "literal" + std::to_string(...).
  std::string out = "OFF\n";
  const auto number = [&](auto value, char after) {
    out += std::to_string(value);
    out += after;
  };
  number(mesh.vertices.size(), ' ');
  number(mesh.faces.size(), ' ');
  number(0, '\n');
  for (const Vec3& v : mesh.vertices) number(v.x, ' '), number(v.y, ' '), number(v.z, '\n');
  for (const auto& face : mesh.faces) {
    number(face.size(), ' ');
    for (std::size_t k = 0; k < face.size(); ++k) number(face[k], k + 1 < face.size() ? ' ' : '\n');
  }
  return out;
}

std::string objText(const PolygonMesh& mesh) {
  std::string out = "# polygons\nvt 0 0\nvn 0 0 1\n";
  const auto number = [&](auto value, const char* after) {
    out += std::to_string(value);
    out += after;
  };
  for (const Vec3& v : mesh.vertices) {
    out += "v ";
    number(v.x, " "), number(v.y, " "), number(v.z, "\n");
  }
  const auto vertices = static_cast<std::int64_t>(mesh.vertices.size());
  // The corner forms in turn: plain, with a texture index, with a normal
  // index, with both, and counted back from the last vertex.
  static const char* const kAfter[] = {"", "/1", "//1", "/1/1", ""};
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    out += "f";
    const std::size_t form = f % 5;
    for (const std::uint32_t corner : mesh.faces[f]) {
      out += ' ';
      number(form == 4 ? static_cast<std::int64_t>(corner) - vertices
                       : static_cast<std::int64_t>(corner) + 1,
             kAfter[form]);
    }
    out += '\n';
  }
  return out;
}

namespace {
template <typename T>
void append(std::string& out, T value, bool bigEndian) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if (bigEndian) std::reverse(bytes, bytes + sizeof(T));
  out.append(bytes, sizeof(T));
}
}  // namespace

void PlyValues::put(const std::string& type, double value) {
  if (type == "char" || type == "int8")
    append(bytes_, static_cast<std::int8_t>(value), bigEndian_);
  else if (type == "uchar" || type == "uint8")
    append(bytes_, static_cast<std::uint8_t>(value), bigEndian_);
  else if (type == "short" || type == "int16")
    append(bytes_, static_cast<std::int16_t>(value), bigEndian_);
  else if (type == "ushort" || type == "uint16")
    append(bytes_, static_cast<std::uint16_t>(value), bigEndian_);
  else if (type == "int" || type == "int32")
    append(bytes_, static_cast<std::int32_t>(value), bigEndian_);
  else if (type == "uint" || type == "uint32")
    append(bytes_, static_cast<std::uint32_t>(value), bigEndian_);
  else if (type == "float" || type == "float32")
    append(bytes_, static_cast<float>(value), bigEndian_);
  else if (type == "double" || type == "float64")
    append(bytes_, value, bigEndian_);
  else
    throw std::invalid_argument("no PLY type " + type);
}

std::string plyHeader(const PlyLayout& layout, const std::string& declarations) {
  return std::string("ply\nformat ") +
         (layout.bigEndian ? "binary_big_endian" : "binary_little_endian") +
         " 1.0\ncomment written by the tests\n" + declarations + "end_header\n";
}

std::string binaryPly(const PolygonMesh& mesh, const PlyLayout& layout) {
  const std::string coordinate = layout.coordinateType;
  std::string declarations;
  // Extras: an element before the vertices, properties before and after
  // the ones read, and a list element after the faces.
  if (layout.extras)
    declarations += "element camera 2\nproperty float view_px\nproperty uchar flags\n";
  declarations += "element vertex " + std::to_string(mesh.vertices.size()) + "\n";
  if (layout.extras) declarations += "property uchar confidence\n";
  declarations += "property " + coordinate + " x\nproperty " + coordinate + " y\nproperty " +
                  coordinate + " z\n";
  if (layout.extras) declarations += "property float nx\nproperty short label\n";
  declarations += "element face " + std::to_string(mesh.faces.size()) + "\n";
  if (layout.extras) declarations += "property list uchar float texcoord\n";
  declarations += std::string("property list ") + layout.countType + " " + layout.indexType +
                  " vertex_indices\n";
  if (layout.extras)
    declarations += "property uchar red\nelement region 2\nproperty list int uint members\n";
  PlyValues values(layout.bigEndian);
  if (layout.extras)
    for (int c = 0; c < 2; ++c) values.put("float", 0.5 * c), values.put("uchar", c);
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (layout.extras) values.put("uchar", 200);
    for (int k = 0; k < 3; ++k) values.put(coordinate, mesh.vertices[i][k]);
    if (layout.extras) values.put("float", -1.0), values.put("short", -7);
  }
  for (const auto& face : mesh.faces) {
    if (layout.extras) {
      values.put("uchar", 2 * face.size());
      for (std::size_t k = 0; k < 2 * face.size(); ++k) values.put("float", 0.25 * k);
    }
    values.put(layout.countType, static_cast<double>(face.size()));
    for (std::uint32_t i : face) values.put(layout.indexType, i);
    if (layout.extras) values.put("uchar", 255);
  }
  if (layout.extras)
    for (int r = 0; r < 2; ++r) {
      values.put("int", 3);
      for (int k = 0; k < 3; ++k) values.put("uint", k + r);
    }
  return plyHeader(layout, declarations) + values.bytes();
}

}  // namespace meshtrace::test
