#include "meshtrace/io/mesh_writer.h"

#include <bit>
#include <charconv>
#include <cstring>
#include <stdexcept>
#include <string>

#include "meshtrace/io/output_file.h"

namespace meshtrace {

namespace {
// The shortest text that reads back as exactly `x`.
void appendExact(std::string& out, double x) {
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, x);
  out.append(buf, res.ptr);
}

template <typename T>
void appendLittleEndian(std::string& out, T value) {
  static_assert(std::endian::native == std::endian::little, "the formats are little-endian");
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

void appendPoint(std::string& out, const Vec3& p, const char* separator) {
  for (int k = 0; k < 3; ++k) {
    appendExact(out, p[k]);
    out += k < 2 ? separator : "\n";
  }
}

// The vertex and face lines of OFF and of ASCII PLY: "x y z", then
// "3 a b c".
void appendVerticesAndFaces(std::string& out, const MeshData& mesh) {
  for (const Vec3& v : mesh.vertices) appendPoint(out, v, " ");
  for (const auto& [a, b, c] : mesh.triangles)
    out += "3 " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + "\n";
}

std::string objText(const MeshData& mesh) {
  std::string out;
  for (const Vec3& v : mesh.vertices) {
    out += "v ";
    appendPoint(out, v, " ");
  }
  for (const auto& [a, b, c] : mesh.triangles)  // OBJ counts vertices from 1
    out += "f " + std::to_string(a + 1) + " " + std::to_string(b + 1) + " " +
           std::to_string(c + 1) + "\n";
  return out;
}

// The unit normal STL lists with a facet (zero for a facet without area).
Vec3 facetNormal(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = glm::cross(b - a, c - a);
  const double length = glm::length(n);
  return length > 0 ? n / length : Vec3(0.0);
}

std::string binaryStl(const MeshData& mesh) {
  std::string out(80, '\0');
  std::memcpy(out.data(), "binary STL", 10);  // the header's text is free
  appendLittleEndian(out, static_cast<std::uint32_t>(mesh.triangles.size()));
  for (const TriangleIndices& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    for (const Vec3& p : {facetNormal(a, b, c), a, b, c})
      for (int k = 0; k < 3; ++k) appendLittleEndian(out, static_cast<float>(p[k]));
    appendLittleEndian(out, std::uint16_t{0});  // attribute byte count
  }
  return out;
}
}  // namespace

void writeOff(const MeshData& mesh, const std::filesystem::path& path) {
  std::string out = "OFF\n" + std::to_string(mesh.vertices.size()) + " " +
                    std::to_string(mesh.triangles.size()) + " 0\n";
  appendVerticesAndFaces(out, mesh);
  writeFileAtomically(path, out);
}

void writeAsciiPly(const MeshData& mesh, const std::filesystem::path& path) {
  std::string out = "ply\nformat ascii 1.0\nelement vertex " +
                    std::to_string(mesh.vertices.size()) +
                    "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
                    std::to_string(mesh.triangles.size()) +
                    "\nproperty list uchar int vertex_indices\nend_header\n";
  appendVerticesAndFaces(out, mesh);
  writeFileAtomically(path, out);
}

void writeAsciiStl(const MeshData& mesh, const std::filesystem::path& path) {
  std::string out = "solid " + path.stem().string() + "\n";
  for (const TriangleIndices& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    out += "facet normal ";
    appendPoint(out, facetNormal(a, b, c), " ");
    out += "outer loop\n";
    for (const Vec3& p : {a, b, c}) {
      out += "vertex ";
      appendPoint(out, p, " ");
    }
    out += "endloop\nendfacet\n";
  }
  out += "endsolid " + path.stem().string() + "\n";
  writeFileAtomically(path, out);
}

void writeBinaryPly(const MeshData& mesh, const std::filesystem::path& path,
                    PlyCoordinates coordinates) {
  const bool asDouble = coordinates == PlyCoordinates::Double;
  const std::string type = asDouble ? "double" : "float";
  std::string out = "ply\nformat binary_little_endian 1.0\nelement vertex " +
                    std::to_string(mesh.vertices.size()) + "\nproperty " + type + " x\nproperty " +
                    type + " y\nproperty " + type + " z\nelement face " +
                    std::to_string(mesh.triangles.size()) +
                    "\nproperty list uchar int vertex_indices\nend_header\n";
  out.reserve(out.size() + mesh.vertices.size() * (asDouble ? 24 : 12) +
              mesh.triangles.size() * 13);
  for (const Vec3& v : mesh.vertices)
    for (int k = 0; k < 3; ++k) {
      if (asDouble)
        appendLittleEndian(out, v[k]);
      else
        appendLittleEndian(out, static_cast<float>(v[k]));
    }
  for (const TriangleIndices& t : mesh.triangles) {
    appendLittleEndian(out, std::uint8_t{3});
    for (const std::uint32_t i : t) appendLittleEndian(out, static_cast<std::int32_t>(i));
  }
  writeFileAtomically(path, out);
}

void writeMesh(const MeshData& mesh, const std::filesystem::path& path) {
  const std::string extension = path.extension().string();
  if (extension == ".off")
    writeOff(mesh, path);
  else if (extension == ".ply")
    writeBinaryPly(mesh, path, PlyCoordinates::Double);
  else if (extension == ".obj")
    writeFileAtomically(path, objText(mesh));
  else if (extension == ".stl")
    writeFileAtomically(path, binaryStl(mesh));
  else
    throw std::invalid_argument(path.string() + ": cannot write meshes as '" + extension +
                                "' (only .off, .ply, .obj, .stl)");
}

}  // namespace meshtrace
