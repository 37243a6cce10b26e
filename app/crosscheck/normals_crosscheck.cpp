#include "crosscheck/normals_crosscheck.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <algorithm>

namespace meshtrace::crosscheck {

namespace {
struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using HalfEdgeMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;
}  // namespace

double angleBetweenDegrees(const Vec3& a, const Vec3& b) {
  return glm::degrees(std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)));
}

OpenMeshNormals openMeshAngleWeightedNormals(const MeshData& mesh) {
  OpenMeshNormals out;
  HalfEdgeMesh om;
  std::vector<HalfEdgeMesh::VertexHandle> handles;
  handles.reserve(mesh.vertices.size());
  for (const Vec3& v : mesh.vertices) handles.push_back(om.add_vertex({v.x, v.y, v.z}));
  out.complete.assign(mesh.vertices.size(), true);
  for (const TriangleIndices& t : mesh.triangles) {
    const bool repeated = t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
    // OpenMesh reports a face it cannot add (a complex edge or vertex) with
    // an invalid handle; its corners then miss a contribution.
    if (repeated || !om.add_face(handles[t[0]], handles[t[1]], handles[t[2]]).is_valid()) {
      for (std::uint32_t v : t) out.complete[v] = false;
      ++out.facesRejected;
    }
  }
  out.normals.assign(mesh.vertices.size(), Vec3(0.0));
  for (auto vh : om.vertices()) {
    OpenMesh::Vec3d sum(0.0, 0.0, 0.0);
    for (auto h : om.vih_range(vh)) {
      if (om.is_boundary(h)) continue;  // no face on this side
      HalfEdgeMesh::Normal sector;
      om.calc_sector_normal(h, sector);
      const double length = sector.norm();
      if (length == 0.0) continue;  // degenerate face: no direction
      sum += om.calc_sector_angle(h) * (sector / length);
    }
    const double length = sum.norm();
    if (length > 0.0) out.normals[vh.idx()] = Vec3(sum[0], sum[1], sum[2]) / length;
  }
  return out;
}

NormalsReport crossCheckNormals(const MeshData& mesh, const std::vector<Vec3>& ours,
                                std::size_t worstCount) {
  NormalsReport report;
  report.vertices = mesh.vertices.size();
  const OpenMeshNormals om = openMeshAngleWeightedNormals(mesh);
  const std::vector<Vec3>& reference = om.normals;
  report.facesRejected = om.facesRejected;
  report.perVertexDegrees.assign(mesh.vertices.size(), -1.0f);
  std::vector<VertexDeviation> all;
  double sum = 0.0;
  for (std::uint32_t v = 0; v < mesh.vertices.size(); ++v) {
    const bool haveBoth = ours[v] != Vec3(0.0) && reference[v] != Vec3(0.0);
    if (!om.complete[v] || !haveBoth) {
      // A vertex no triangle uses has no normal on either side: nothing to skip.
      if (ours[v] != Vec3(0.0) || reference[v] != Vec3(0.0)) ++report.verticesSkipped;
      continue;
    }
    const double d = angleBetweenDegrees(ours[v], reference[v]);
    report.perVertexDegrees[v] = static_cast<float>(d);
    all.push_back({v, d});
    sum += d;
    report.maxDegrees = std::max(report.maxDegrees, d);
  }
  report.compared = all.size();
  report.meanDegrees = all.empty() ? 0.0 : sum / double(all.size());
  const std::size_t n = std::min(worstCount, all.size());
  std::partial_sort(
      all.begin(), all.begin() + n, all.end(),
      [](const VertexDeviation& a, const VertexDeviation& b) { return a.degrees > b.degrees; });
  report.worst.assign(all.begin(), all.begin() + n);
  return report;
}

NormalsReport crossCheckNormals(const Mesh& mesh, std::size_t worstCount) {
  const MeshData data{mesh.vertices(), mesh.triangles()};
  if (!mesh.vertexNormals().empty())
    return crossCheckNormals(data, mesh.vertexNormals(), worstCount);
  return crossCheckNormals(data, angleWeightedVertexNormals(data), worstCount);
}

}  // namespace meshtrace::crosscheck
