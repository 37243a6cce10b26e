// Stability case 4, degenerate geometry changes nothing. To a clean closed
// mesh we add zero-area triangles (three distinct collinear vertices, both
// along the mesh's own edges and across a face), triangles with repeated
// indices, duplicates of existing triangles, triangles with a zero-length
// edge (two vertices at the same position), and isolated vertices (one far
// outside, which also stretches the bounding box). The render must equal the
// clean mesh's bit for bit, for every algorithm and acceleration, FLAT and
// PHONG, and no normal, hit or pixel may be NaN.
#include <gtest/gtest.h>

#include "meshtrace/render/render.h"
#include "meshtrace/report/stability.h"

namespace meshtrace {
namespace {

// The clean mesh: the grid box [-1, 1]^3 with n = 4, vertices at multiples of
// 0.5, so midpoints of edges are exact and collinear triples exactly so.
MeshData cleanMesh() { return makeClosedGridBox(4); }

MeshData withDegenerates() {
  MeshData m = cleanMesh();
  const auto add = [&](const Vec3& p) {
    m.vertices.push_back(p);
    return static_cast<std::uint32_t>(m.vertices.size() - 1);
  };
  const std::size_t clean = m.triangles.size();
  for (std::size_t i = 0; i < clean; i += 3) {
    const TriangleIndices t = m.triangles[i];
    const Vec3 a = m.vertices[t[0]], b = m.vertices[t[1]], c = m.vertices[t[2]];
    // Zero area: the midpoint of an edge, on that edge, both orientations.
    const std::uint32_t mid = add(0.5 * (a + b));
    m.triangles.push_back({t[0], mid, t[1]});
    m.triangles.push_back({t[1], mid, t[0]});
    // Zero area across the face: a, the centre of edge bc... and beyond.
    m.triangles.push_back({t[0], add(0.5 * (b + c)), add(a + (b + c - 2.0 * a))});
    // Repeated indices.
    m.triangles.push_back({t[0], t[0], t[1]});
    m.triangles.push_back({t[2], t[2], t[2]});
    // A duplicate.
    m.triangles.push_back(t);
    // A zero-length edge: a second vertex at a's position.
    m.triangles.push_back({t[0], add(a), t[1]});
  }
  add(Vec3(0.25, 0.25, 0.25));   // isolated, inside
  add(Vec3(40.0, -30.0, 20.0));  // isolated, far outside
  return m;
}

Scene sceneWith(MeshData mesh, Shading shading) {
  Scene s;
  s.file = "degenerate.sce";
  s.camera = Camera(CameraSpec{{2.6, 2.1, 3.3}, {0.0, 0.0, 0.0}, {0, 1, 0}, 50.0, 80, 60});
  s.depth = 1;
  s.ambience = Color(0.2);
  s.lights = {{{3, 5, 4}, Color(0.9)}};
  s.planes.push_back({{0, -1, 0}, {0, 1, 0}, {Color(0.2), Color(0.6), Color(0.0), 1.0, 0.5}});
  s.meshes.emplace_back("mesh.off", std::move(mesh), shading,
                        Material{Color(0.3), Color(0.7, 0.4, 0.3), Color(0.4), 30.0, 0.3});
  return s;
}

bool finite(const std::vector<Vec3>& v) {
  for (const Vec3& x : v)
    if (!isFinite(x)) return false;
  return true;
}

TEST(StabilityDegenerate, NoNaNInNormals) {
  for (Shading shading : {Shading::Flat, Shading::Phong}) {
    const Scene s = sceneWith(withDegenerates(), shading);
    const Mesh& mesh = s.meshes[0];
    for (std::uint32_t i = 0; i < mesh.triangles().size(); ++i)
      EXPECT_TRUE(isFinite(mesh.flatNormal(i))) << i;
    EXPECT_TRUE(finite(s.meshes[0].vertexNormals()));
  }
}

TEST(StabilityDegenerate, RendersExactlyLikeTheCleanMesh) {
  for (Shading shading : {Shading::Flat, Shading::Phong}) {
    const Scene clean = sceneWith(cleanMesh(), shading);
    const Scene dirty = sceneWith(withDegenerates(), shading);
    for (const TriangleKernel& k : allTriangleKernels()) {
      for (AccelMethod accel : {AccelMethod::None, AccelMethod::Bvh}) {
        RenderOptions options;
        options.trace = {accel, k};
        const Image a = render(clean, options), b = render(dirty, options);
        std::size_t differ = 0, nan = 0;
        for (std::size_t i = 0; i < b.pixels.size(); ++i) {
          differ += a.pixels[i] != b.pixels[i];
          nan += !isFinite(b.pixels[i]);
        }
        const std::string label = std::string(toString(shading)) + " " + toString(k.test) + " " +
                                  toString(k.precision) + " " + toString(accel);
        EXPECT_EQ(nan, 0u) << label;
        EXPECT_EQ(differ, 0u) << label;
      }
    }
  }
}

// Hits reported on degenerate triangles would be the only way for them to
// matter: no kernel may report one, and no hit may carry a NaN.
TEST(StabilityDegenerate, KernelsNeverHitZeroAreaTriangles) {
  const MeshData m = withDegenerates();
  const std::size_t clean = cleanMesh().triangles.size();
  const Scene s = sceneWith(m, Shading::Flat);
  std::size_t hits = 0, nan = 0;
  for (const TriangleKernel& k : allTriangleKernels()) {
    for (int y = 0; y < 60; ++y)
      for (int x = 0; x < 80; ++x) {
        const TriangleRay ray(s.camera.primaryRay(x, y), k);
        for (std::size_t i = 0; i < m.triangles.size(); ++i) {
          const TriangleIndices& t = m.triangles[i];
          TriangleHit h{};
          if (!ray.intersect(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]], 0.0, kInfinity,
                             h))
            continue;
          nan += !(std::isfinite(h.t) && std::isfinite(h.beta) && std::isfinite(h.gamma));
          // Triangles past the clean ones, except the duplicates, are degenerate.
          hits += i >= clean && s.meshes[0].flatNormal(static_cast<std::uint32_t>(i)) == Vec3(0.0);
        }
      }
  }
  EXPECT_EQ(hits, 0u);
  EXPECT_EQ(nan, 0u);
}

}  // namespace
}  // namespace meshtrace
