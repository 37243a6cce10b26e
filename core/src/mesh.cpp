#include "meshtrace/mesh.h"

#include <algorithm>
#include <unordered_set>

#include "meshtrace/triangle.h"

namespace meshtrace {

const char* toString(Shading shading) { return shading == Shading::Flat ? "FLAT" : "PHONG"; }

std::vector<Vec3> angleWeightedVertexNormals(const MeshData& mesh,
                                             const std::vector<Vec3>& triangleNormals) {
  std::vector<Vec3> normals(mesh.vertices.size(), Vec3(0.0));
  // A triangle listed twice (the same three vertices, in any order) counts
  // once, so duplicates in a file do not tilt the normals of their corners.
  const auto hash = [](const TriangleIndices& t) {
    return std::hash<std::uint64_t>()((std::uint64_t{t[0]} << 42) ^ (std::uint64_t{t[1]} << 21) ^ t[2]);
  };
  std::unordered_set<TriangleIndices, decltype(hash)> seen(mesh.triangles.size(), hash);
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const TriangleIndices& tri = mesh.triangles[i];
    if (triangleNormals[i] == Vec3(0.0)) continue;  // degenerate: no direction to give
    TriangleIndices sorted = tri;
    std::sort(sorted.begin(), sorted.end());
    if (!seen.insert(sorted).second) continue;
    const Vec3 w = cornerAngles(mesh.vertices[tri[0]], mesh.vertices[tri[1]],
                                mesh.vertices[tri[2]]);
    for (int k = 0; k < 3; ++k) normals[tri[k]] += w[k] * triangleNormals[i];
  }
  for (Vec3& n : normals) {
    const double len = glm::length(n);
    n = len > 0.0 ? n / len : Vec3(0.0);
  }
  return normals;
}

Mesh::Mesh(std::filesystem::path file, MeshData data, Shading shading, const Material& material)
    : file_(std::move(file)), data_(std::move(data)), shading_(Shading::Flat), material_(material) {
  for (const Vec3& v : data_.vertices) bounds_.extend(v);
  triangleNormals_.reserve(data_.triangles.size());
  for (const TriangleIndices& t : data_.triangles) {
    triangleNormals_.push_back(
        triangleNormal(data_.vertices[t[0]], data_.vertices[t[1]], data_.vertices[t[2]]));
  }
  setShading(shading);
}

void Mesh::setShading(Shading shading) {
  shading_ = shading;
  if (shading == Shading::Phong && vertexNormals_.empty() && !data_.vertices.empty()) {
    vertexNormals_ = angleWeightedVertexNormals(data_, triangleNormals_);
  }
}

Vec3 Mesh::shadingNormal(std::uint32_t tri, double beta, double gamma) const {
  const Vec3& flat = triangleNormals_[tri];
  if (shading_ == Shading::Flat) return flat;
  const TriangleIndices& t = data_.triangles[tri];
  const Vec3 n = (1.0 - beta - gamma) * vertexNormals_[t[0]] + beta * vertexNormals_[t[1]] +
                 gamma * vertexNormals_[t[2]];
  const double len = glm::length(n);
  // Opposing vertex normals (a knife-edge fold) can cancel; the face normal is
  // then the only meaningful direction.
  return len > 1e-12 ? n / len : flat;
}

}  // namespace meshtrace
