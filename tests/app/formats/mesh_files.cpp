#include "app/formats/mesh_files.h"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace meshtrace::test {

namespace {
// A float's exact value as text: it reads back to the same double, and to
// the same float.
std::string floatText(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", static_cast<double>(static_cast<float>(v)));
  return buffer;
}

std::string pointText(const Vec3& p) {
  return floatText(p.x) + " " + floatText(p.y) + " " + floatText(p.z);
}

template <typename T>
void putLittleEndian(std::string& out, T value) {
  static_assert(std::endian::native == std::endian::little);
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

template <typename T>
void putInOrder(std::string& out, T value, bool bigEndian) {
  const std::size_t at = out.size();
  putLittleEndian(out, value);
  if (bigEndian) std::reverse(out.begin() + static_cast<std::ptrdiff_t>(at), out.end());
}

void putPoint(std::string& out, const Vec3& p) {
  for (int k = 0; k < 3; ++k) putLittleEndian(out, static_cast<float>(p[k]));
}

std::string plyHeader(const MeshData& mesh, const char* format) {
  return std::string("ply\nformat ") + format + " 1.0\ncomment written by the tests\n" +
         "element vertex " + std::to_string(mesh.vertices.size()) +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
         std::to_string(mesh.triangles.size()) +
         "\nproperty list uchar int vertex_indices\nend_header\n";
}

std::string omBytes(const MeshData& mesh) {
  OpenMesh::PolyMesh_ArrayKernelT<> om;
  std::vector<OpenMesh::VertexHandle> handles;
  for (const Vec3& v : mesh.vertices)
    handles.push_back(om.add_vertex(OpenMesh::Vec3f(
        static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z))));
  for (const TriangleIndices& t : mesh.triangles)
    if (!om.add_face(handles[t[0]], handles[t[1]], handles[t[2]]).is_valid())
      throw std::runtime_error("OM test meshes must be manifold");
  std::ostringstream out;
  if (!OpenMesh::IO::write_mesh(om, out, ".om", OpenMesh::IO::Options::Binary))
    throw std::runtime_error("OpenMesh cannot write OM");
  return out.str();
}

// A line per vertex, then "3 i j k" per triangle: OFF's body, and ASCII PLY's.
std::string offStyleBody(const MeshData& mesh) {
  std::string out;
  for (const Vec3& v : mesh.vertices) out += pointText(v) + "\n";
  for (const TriangleIndices& t : mesh.triangles)
    out += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) +
           "\n";
  return out;
}

std::string meshBytes(const MeshData& mesh, MeshFormat format) {
  std::string out;
  switch (format) {
    case MeshFormat::Off:
      return "OFF\n" + std::to_string(mesh.vertices.size()) + " " +
             std::to_string(mesh.triangles.size()) + " 0\n" + offStyleBody(mesh);
    case MeshFormat::PlyAscii: return plyHeader(mesh, "ascii") + offStyleBody(mesh);
    case MeshFormat::PlyBinary:
    case MeshFormat::PlyBinaryBigEndian: {
      const bool bigEndian = format == MeshFormat::PlyBinaryBigEndian;
      out = plyHeader(mesh, bigEndian ? "binary_big_endian" : "binary_little_endian");
      for (const Vec3& v : mesh.vertices)
        for (int k = 0; k < 3; ++k) putInOrder(out, static_cast<float>(v[k]), bigEndian);
      for (const TriangleIndices& t : mesh.triangles) {
        putInOrder(out, std::uint8_t{3}, bigEndian);
        for (std::uint32_t i : t) putInOrder(out, static_cast<std::int32_t>(i), bigEndian);
      }
      return out;
    }
    case MeshFormat::Obj:
      out = "# written by the tests\n";
      for (const Vec3& v : mesh.vertices) out += "v " + pointText(v) + "\n";
      for (const TriangleIndices& t : mesh.triangles)  // OBJ counts from 1
        out += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " +
               std::to_string(t[2] + 1) + "\n";
      return out;
    case MeshFormat::StlAscii:
      out = "solid tests\n";
      for (const TriangleIndices& t : mesh.triangles) {
        out += "  facet normal 0 0 0\n    outer loop\n";
        for (std::uint32_t i : t) out += "      vertex " + pointText(mesh.vertices[i]) + "\n";
        out += "    endloop\n  endfacet\n";
      }
      return out + "endsolid tests\n";
    case MeshFormat::Om: return omBytes(mesh);
    case MeshFormat::StlBinary:
      out.assign(80, ' ');
      putLittleEndian(out, static_cast<std::uint32_t>(mesh.triangles.size()));
      for (const TriangleIndices& t : mesh.triangles) {
        putPoint(out, Vec3(0.0));  // the facet normal, which readers recompute
        for (std::uint32_t i : t) putPoint(out, mesh.vertices[i]);
        putLittleEndian(out, std::uint16_t{0});
      }
      return out;
  }
  throw std::logic_error("unknown mesh format");
}
}  // namespace

const std::vector<MeshFormat>& allMeshFormats() {
  static const std::vector<MeshFormat> all = {
      MeshFormat::Off, MeshFormat::PlyAscii, MeshFormat::PlyBinary, MeshFormat::PlyBinaryBigEndian,
      MeshFormat::Obj, MeshFormat::StlAscii, MeshFormat::StlBinary};
  return all;
}

std::string formatName(MeshFormat format) {
  switch (format) {
    case MeshFormat::Off: return "off";
    case MeshFormat::PlyAscii: return "ply-ascii";
    case MeshFormat::PlyBinary: return "ply-binary";
    case MeshFormat::PlyBinaryBigEndian: return "ply-binary-big-endian";
    case MeshFormat::Obj: return "obj";
    case MeshFormat::StlAscii: return "stl-ascii";
    case MeshFormat::StlBinary: return "stl-binary";
    case MeshFormat::Om: return "om";
  }
  return "?";
}

std::string formatExtension(MeshFormat format) {
  switch (format) {
    case MeshFormat::Off: return ".off";
    case MeshFormat::PlyAscii:
    case MeshFormat::PlyBinary:
    case MeshFormat::PlyBinaryBigEndian: return ".ply";
    case MeshFormat::Obj: return ".obj";
    case MeshFormat::StlAscii:
    case MeshFormat::StlBinary: return ".stl";
    case MeshFormat::Om: return ".om";
  }
  return "";
}

void writeMeshFile(const MeshData& mesh, MeshFormat format, const std::filesystem::path& path) {
  const std::string bytes = meshBytes(mesh, format);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

MeshData onFloatGrid(MeshData mesh) {
  // In double arithmetic: GCC 12 at -O2 drops some double-float-double
  // round trips of vector components.
  for (Vec3& v : mesh.vertices) v = glm::round(v * 1024.0) / 1024.0;
  return mesh;
}

}  // namespace meshtrace::test
