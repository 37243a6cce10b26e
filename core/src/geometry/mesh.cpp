#include "meshtrace/geometry/mesh.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <memory>
#include <tuple>

#include "meshtrace/geometry/triangle.h"
#include "meshtrace/util/enum_names.h"
#include "util/build_vector.h"

namespace meshtrace {

namespace {
constexpr EnumName<Shading> kShadings[] = {{Shading::Flat, "FLAT"}, {Shading::Phong, "PHONG"}};
}  // namespace

const char* toString(Shading shading) { return nameIn(kShadings, shading); }
Shading parseShading(std::string_view name) { return parseNamed(kShadings, name, "shading mode"); }

namespace {

// Elements a task takes in the passes over a mesh's triangles or vertices.
constexpr std::size_t kGrain = std::size_t{1} << 14;

Vec3 normalOf(const MeshData& mesh, std::size_t triangle) {
  const TriangleIndices& t = mesh.triangles[triangle];
  return triangleNormal(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
}

// Whether each triangle has a normal (area, in double precision).
std::vector<char> trianglesWithArea(const MeshData& mesh) {
  std::vector<char> hasArea(mesh.triangles.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, hasArea.size(), kGrain),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i < r.end(); ++i) {
                        const TriangleIndices& t = mesh.triangles[i];
                        hasArea[i] = hasNormal(mesh.vertices[t[0]], mesh.vertices[t[1]],
                                               mesh.vertices[t[2]]);
                      }
                    });
  return hasArea;
}

// Whether each triangle contributes to the vertex normals: not degenerate
// (no direction to give), and the first in file order among the triangles
// with the same three vertices in any order (a triangle listed twice counts
// once, so duplicates in a file do not tilt the normals of their corners).
// Duplicates share their smallest vertex, so the triangles are grouped by
// it (a stable counting sort) and each group is sorted by the other two:
// linear in the mesh, where a hash set of the triangles had made an
// allocation per triangle.
std::vector<char> contributingTriangles(const MeshData& mesh, const std::vector<char>& hasArea) {
  const std::size_t n = mesh.triangles.size();
  std::vector<char> contributes(n, 0);
  const auto sorted = [&](std::size_t i) {
    TriangleIndices t = mesh.triangles[i];
    if (t[0] > t[1]) std::swap(t[0], t[1]);
    if (t[1] > t[2]) std::swap(t[1], t[2]);
    if (t[0] > t[1]) std::swap(t[0], t[1]);
    return t;
  };
  std::vector<std::uint32_t> groupEnd(mesh.vertices.size() + 1, 0);
  for (std::size_t i = 0; i < n; ++i)
    if (hasArea[i]) ++groupEnd[sorted(i)[0] + 1];
  for (std::size_t v = 1; v < groupEnd.size(); ++v) groupEnd[v] += groupEnd[v - 1];
  struct Other {
    std::uint32_t middle, largest, triangle;
    bool operator<(const Other& o) const {
      return std::tie(middle, largest, triangle) < std::tie(o.middle, o.largest, o.triangle);
    }
  };
  std::vector<Other> grouped;
  reserveOnLargePages(grouped, groupEnd.back());
  grouped.resize(groupEnd.back());
  std::vector<std::uint32_t> fill(groupEnd.begin(), groupEnd.end() - 1);
  for (std::size_t i = 0; i < n; ++i) {
    if (!hasArea[i]) continue;
    const TriangleIndices t = sorted(i);
    grouped[fill[t[0]]++] = {t[1], t[2], static_cast<std::uint32_t>(i)};
  }
  // Groups are independent: sorted in parallel, each writing only the
  // flags of its own triangles.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, groupEnd.size() - 1, kGrain),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t v = r.begin(); v < r.end(); ++v) {
                        const auto first = grouped.begin() + groupEnd[v];
                        const auto last = grouped.begin() + groupEnd[v + 1];
                        std::sort(first, last);
                        for (auto it = first; it != last; ++it)
                          contributes[it->triangle] = it == first || it[-1].middle != it->middle ||
                                                      it[-1].largest != it->largest;
                      }
                    });
  return contributes;
}

// Adds each triangle's angle-weighted normal to the sums of its corners
// that `into` accepts, in triangle order, for the triangles `counts`
// accepts. The corner angles (two atan2 a triangle, most of the work) and
// the triangles' normals are taken in parallel, a chunk of triangles at a
// time, while the chunks before are summed in order: the sums, and so the
// normals, do not depend on the thread count.
template <typename Counts, typename Into>
void sumAngleWeightedNormals(const MeshData& mesh, const Counts& counts, const Into& into,
                             std::vector<Vec3>& sums) {
  struct Chunk {
    std::size_t begin = 0, end = 0;
    std::vector<Vec3> angles, normals;
  };
  constexpr std::size_t kChunk = std::size_t{1} << 14;
  const std::size_t triangles = mesh.triangles.size();
  std::size_t next = 0;
  tbb::parallel_pipeline(
      static_cast<std::size_t>(2 * tbb::this_task_arena::max_concurrency() + 1),
      tbb::make_filter<void, std::shared_ptr<Chunk>>(tbb::filter_mode::serial_in_order,
                                                     [&](tbb::flow_control& fc) {
                                                       if (next >= triangles) {
                                                         fc.stop();
                                                         return std::shared_ptr<Chunk>();
                                                       }
                                                       auto c = std::make_shared<Chunk>();
                                                       c->begin = next;
                                                       c->end = next =
                                                           std::min(next + kChunk, triangles);
                                                       return c;
                                                     }) &
          tbb::make_filter<std::shared_ptr<Chunk>, std::shared_ptr<Chunk>>(
              tbb::filter_mode::parallel,
              [&](std::shared_ptr<Chunk> c) {
                c->angles.resize(c->end - c->begin);
                c->normals.resize(c->end - c->begin);
                for (std::size_t i = c->begin; i < c->end; ++i) {
                  if (!counts(i)) continue;
                  const TriangleIndices& t = mesh.triangles[i];
                  c->angles[i - c->begin] =
                      cornerAngles(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
                  c->normals[i - c->begin] = normalOf(mesh, i);
                }
                return c;
              }) &
          tbb::make_filter<std::shared_ptr<Chunk>, void>(
              tbb::filter_mode::serial_in_order, [&](const std::shared_ptr<Chunk>& c) {
                for (std::size_t i = c->begin; i < c->end; ++i) {
                  if (!counts(i)) continue;
                  const TriangleIndices& t = mesh.triangles[i];
                  const Vec3& w = c->angles[i - c->begin];
                  const Vec3& normal = c->normals[i - c->begin];
                  for (int k = 0; k < 3; ++k)
                    if (into(t[k])) sums[t[k]] += w[k] * normal;
                }
              }));
}

}  // namespace

std::vector<Vec3> angleWeightedVertexNormals(const MeshData& mesh) {
  std::vector<Vec3> normals;
  reserveOnLargePages(normals, mesh.vertices.size());
  normals.assign(mesh.vertices.size(), Vec3(0.0));
  // Which triangles count is known only after a sort, while their angles
  // need nothing but the triangle. So the sums first take every triangle
  // with area while contributingTriangles runs beside them; a triangle
  // listed again (rare) then has its corners' sums made again from those
  // that count, in the same order, so each sum is the one it would have
  // been had only those been added.
  std::vector<char> contributes;
  const std::vector<char> withArea = trianglesWithArea(mesh);
  const auto hasArea = [&](std::size_t i) { return withArea[i] != 0; };
  const auto everyCorner = [](std::uint32_t) { return true; };
  tbb::parallel_invoke([&] { contributes = contributingTriangles(mesh, withArea); },
                       [&] { sumAngleWeightedNormals(mesh, hasArea, everyCorner, normals); });
  std::vector<char> redo;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    if (contributes[i] || !hasArea(i)) continue;
    if (redo.empty()) redo.assign(normals.size(), 0);
    for (const std::uint32_t v : mesh.triangles[i]) redo[v] = 1;
  }
  if (!redo.empty()) {
    const auto remade = [&](std::uint32_t v) { return redo[v] != 0; };
    for (std::uint32_t v = 0; v < normals.size(); ++v)
      if (remade(v)) normals[v] = Vec3(0.0);
    const auto countsThere = [&](std::size_t i) {
      const TriangleIndices& t = mesh.triangles[i];
      return contributes[i] && (remade(t[0]) || remade(t[1]) || remade(t[2]));
    };
    sumAngleWeightedNormals(mesh, countsThere, remade, normals);
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, normals.size(), kGrain),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t v = r.begin(); v < r.end(); ++v) {
                        const double len = glm::length(normals[v]);
                        normals[v] = len > 0.0 ? normals[v] / len : Vec3(0.0);
                      }
                    });
  return normals;
}

FaceOfTriangle Mesh::faceOf(std::uint32_t triangle) const {
  const std::vector<PolygonFace>& polygons = data_->polygons;
  // The last polygon starting at or before the triangle, if any.
  const auto after =
      std::upper_bound(polygons.begin(), polygons.end(), triangle,
                       [](std::uint32_t t, const PolygonFace& p) { return t < p.firstTriangle; });
  if (after == polygons.begin()) return {triangle, 3};
  const PolygonFace& p = *(after - 1);
  if (triangle < p.endTriangle()) return {p.face, p.corners};
  return {p.faceAfter(triangle), 3};
}

Mesh::Mesh(std::filesystem::path file, MeshData data, Shading shading, const Material& material)
    : file_(std::move(file)),
      data_(std::make_shared<const MeshData>(std::move(data))),
      shading_(Shading::Flat),
      material_(material) {
  const std::vector<Vec3>& v = data_->vertices;
  bounds_ = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, v.size(), kGrain), Aabb{},
      [&](const tbb::blocked_range<std::size_t>& r, Aabb box) {
        for (std::size_t i = r.begin(); i < r.end(); ++i) box.extend(v[i]);
        return box;
      },
      [](Aabb a, const Aabb& b) {
        a.extend(b);
        return a;
      });
  setShading(shading);
}

Vec3 Mesh::flatNormal(std::uint32_t tri) const { return normalOf(*data_, tri); }

const std::vector<Vec3>& Mesh::vertexNormals() const {
  static const std::vector<Vec3> kNone;
  return vertexNormals_ ? *vertexNormals_ : kNone;
}

void Mesh::setShading(Shading shading) {
  shading_ = shading;
  if (shading == Shading::Phong && !vertexNormals_ && !data_->vertices.empty()) {
    vertexNormals_ = std::make_shared<const std::vector<Vec3>>(angleWeightedVertexNormals(*data_));
  }
}

Vec3 Mesh::shadingNormal(std::uint32_t tri, double beta, double gamma, const Vec3& flat) const {
  if (shading_ == Shading::Flat) return flat;
  const TriangleIndices& t = data_->triangles[tri];
  const std::vector<Vec3>& vn = *vertexNormals_;
  const Vec3 n = (1.0 - beta - gamma) * vn[t[0]] + beta * vn[t[1]] + gamma * vn[t[2]];
  const double len = glm::length(n);
  // Opposing vertex normals (a knife-edge fold) can cancel; the face normal is
  // then the only meaningful direction.
  return len > 1e-12 ? n / len : flat;
}

}  // namespace meshtrace
