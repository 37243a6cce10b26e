#pragma once
// Our angle-weighted vertex normals checked against a second, independent
// computation through OpenMesh's half-edge structure: for each vertex, the sum
// over its incoming non-boundary half-edges h of
// calc_sector_angle(h) * normalized(calc_sector_normal(h)), normalised.
// (OpenMesh's own update_vertex_normals() is unweighted, so it is not used.)
#include <cstdint>
#include <vector>

#include "meshtrace/geometry/mesh.h"

namespace meshtrace::crosscheck {

struct VertexDeviation {
  std::uint32_t vertex = 0;
  double degrees = 0.0;
};

struct NormalsReport {
  std::size_t vertices = 0;
  std::size_t compared = 0;         // vertices with a normal on both sides
  std::size_t facesRejected = 0;    // faces OpenMesh refused (non-manifold or repeated corners)
  std::size_t verticesSkipped = 0;  // next to a refused face, or with no normal on either side
  double maxDegrees = 0.0;
  double meanDegrees = 0.0;
  std::vector<VertexDeviation> worst;   // largest first
  std::vector<float> perVertexDegrees;  // -1 where not compared
};

struct OpenMeshNormals {
  std::vector<Vec3> normals;   // zero where no face contributes
  std::vector<bool> complete;  // false where a face at the vertex could not enter OpenMesh
  std::size_t facesRejected = 0;
};

// The reference normals through OpenMesh's half-edge structure.
OpenMeshNormals openMeshAngleWeightedNormals(const MeshData& mesh);

// Compares `ours` (one normal per vertex) with OpenMesh's.
NormalsReport crossCheckNormals(const MeshData& mesh, const std::vector<Vec3>& ours,
                                std::size_t worstCount = 10);

// Compares the mesh's own angle-weighted normals (computed here if the mesh
// is FLAT and holds none).
NormalsReport crossCheckNormals(const Mesh& mesh, std::size_t worstCount = 10);

// The angle between two unit vectors, accurate near 0: atan2(|a x b|, a . b).
double angleBetweenDegrees(const Vec3& a, const Vec3& b);

}  // namespace meshtrace::crosscheck
