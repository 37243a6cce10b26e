#pragma once
// A triangle mesh with its shading mode, normals and bounding box.
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string_view>
#include <vector>

#include "meshtrace/geometry/aabb.h"
#include "meshtrace/geometry/material.h"

namespace meshtrace {

enum class Shading : std::uint8_t { Flat, Phong };

// "FLAT", "PHONG", as the scene format writes them.
const char* toString(Shading shading);
// Throws std::invalid_argument for an unknown name.
Shading parseShading(std::string_view name);

using TriangleIndices = std::array<std::uint32_t, 3>;

// A face of the file that is not one triangle of the mesh: face number
// `face`, whose corners - 2 triangles start at firstTriangle. A polygon
// has four corners or more; a face of two (an STL facet whose corners
// weld into two points) has no triangle: it was left out, and the faces
// after it keep their numbers. (Triangle indices fit 32 bits.)
struct PolygonFace {
  std::uint32_t firstTriangle = 0;
  std::uint32_t corners = 0;
  std::uint32_t face = 0;

  std::uint32_t endTriangle() const { return firstTriangle + corners - 2; }
  // The face of triangle `t` at or past endTriangle() and before the next
  // polygon: each triangle there is a face of its own.
  std::uint32_t faceAfter(std::uint32_t t) const { return face + 1 + (t - endTriangle()); }
};

struct MeshData {
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;
  // The faces that are not one triangle each (polygons, faces left out),
  // in triangle order: what leads from a triangle back to its face in the
  // file (Mesh::faceOf). Empty for a mesh of triangles, each kept.
  std::vector<PolygonFace> polygons;
  // Faces of the file that no triangulation tiles (they cross themselves):
  // their triangles may cover area outside them (polygon.h).
  std::size_t untiledPolygons = 0;
};

// The face of the mesh's file a triangle was cut from, and its corners.
struct FaceOfTriangle {
  std::uint32_t face = 0;
  std::uint32_t corners = 3;
};

class Mesh {
 public:
  Mesh(std::filesystem::path file, MeshData data, Shading shading, const Material& material);

  const std::filesystem::path& file() const { return file_; }
  const Material& material() const { return material_; }
  Shading shading() const { return shading_; }
  const Aabb& bounds() const { return bounds_; }
  const std::vector<Vec3>& vertices() const { return data_->vertices; }
  const std::vector<TriangleIndices>& triangles() const { return data_->triangles; }
  // Triangle `tri`'s unit normal (triangleNormal of its corners), taken
  // where a ray meets it rather than kept for every triangle: a render
  // needs it only at hit points, and an array of them would take 24 bytes
  // a triangle, as much as a closed mesh's vertices and indices together.
  Vec3 flatNormal(std::uint32_t tri) const;
  // Empty until the mesh is PHONG shaded: a FLAT mesh never needs them.
  const std::vector<Vec3>& vertexNormals() const;

  // Switching to PHONG computes the vertex normals if they are missing.
  // The copy of a mesh shares its arrays, which never change, so a copy
  // switched to another mode costs only the normals it lacks.
  void setShading(Shading shading);

  FaceOfTriangle faceOf(std::uint32_t triangle) const;

  // The shading normal at barycentrics (beta, gamma) of triangle `tri`;
  // `flat` is its flatNormal, for a caller that has it already.
  Vec3 shadingNormal(std::uint32_t tri, double beta, double gamma, const Vec3& flat) const;
  Vec3 shadingNormal(std::uint32_t tri, double beta, double gamma) const {
    return shadingNormal(tri, beta, gamma, flatNormal(tri));
  }

 private:
  std::filesystem::path file_;
  std::shared_ptr<const MeshData> data_;
  Shading shading_;
  Material material_;
  Aabb bounds_;
  std::shared_ptr<const std::vector<Vec3>> vertexNormals_;  // null until computed
};

// Angle-weighted vertex normals, summed in triangle order (the same bits on
// any number of threads). A triangle listed more than once counts once; a
// vertex with no non-degenerate incident triangle gets the zero vector.
std::vector<Vec3> angleWeightedVertexNormals(const MeshData& mesh);

}  // namespace meshtrace
