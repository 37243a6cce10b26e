#include "bench/crossover.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>

#include "bench/rays.h"
#include "meshtrace/geometry/mesh_generators.h"

namespace meshtrace::bench {

namespace {

// 10 x 10 small meshes on the xz plane, seen from above: flat squares of
// 2 n^2 triangles (n x n grids), flat fans (below) or tori of
// 2 * ring * tube triangles.
Scene gridOfMeshes(const std::function<MeshData(const Vec3&)>& make) {
  Scene scene;
  CameraSpec cam;
  cam.eye = Vec3(13.5, 25.0, 40.0);
  cam.center = Vec3(13.5, 0.0, 13.5);
  cam.fovyDegrees = 45.0;
  cam.width = 400;
  cam.height = 300;
  scene.camera = Camera(cam);
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j)
      scene.meshes.emplace_back("small", make(Vec3(3.0 * i, 0.0, 3.0 * j)), Shading::Flat,
                                Material{});
  return scene;
}

// A flat regular polygon of k triangles around its centre, facing +y, with
// the 2 x 2 squares' circumradius: the sizes between the squares' 2 and 8.
MeshData makeFan(const Vec3& center, int k) {
  MeshData m;
  m.vertices.push_back(center);
  for (int i = 0; i < k; ++i) {
    const double a = 2.0 * std::numbers::pi * i / k;
    m.vertices.push_back(center + std::sqrt(2.0) * Vec3(std::cos(a), 0.0, -std::sin(a)));
  }
  for (int i = 0; i < k; ++i)
    m.triangles.push_back(
        {0, static_cast<std::uint32_t>(1 + i), static_cast<std::uint32_t>(1 + (i + 1) % k)});
  return m;
}

double primaryMrays(const Scene& scene, std::size_t minTriangles, const RaySet& rays) {
  TraceOptions options;
  options.bvh.minMeshTriangles = minTriangles;
  const SceneIntersector intersector(scene, options);
  const double s = timeRays(rays.rays.size(), 1, 1, 5, [&](std::size_t i) {
    Hit hit;
    Counters c;
    intersector.closestHit(rays.rays[i], 0.0, hit, c);
  });
  return rays.rays.size() / s * 1e-6;
}

}  // namespace

void printCrossover() {
  std::printf(
      "| mesh | triangles per mesh | Mrays/s, BVH | Mrays/s, no BVH | BVH / none |\n"
      "|---|---:|---:|---:|---:|\n");
  const auto row = [](const char* shape, const Scene& scene) {
    const RaySet rays = primaryRays(scene);
    const double with = primaryMrays(scene, 0, rays);
    const double without = primaryMrays(scene, std::numeric_limits<std::size_t>::max(), rays);
    std::printf("| %s | %zu | %.2f | %.2f | %.2f |\n", shape, scene.meshes[0].triangles().size(),
                with, without, with / without);
    std::fflush(stdout);
  };
  row("square", gridOfMeshes([](const Vec3& c) { return makeGrid(c, 2.0, 1); }));
  for (int k = 3; k < 8; ++k)
    row("fan", gridOfMeshes([k](const Vec3& c) { return makeFan(c, k); }));
  row("square", gridOfMeshes([](const Vec3& c) { return makeGrid(c, 2.0, 2); }));
  const int sizes[][2] = {{3, 2}, {4, 2}, {4, 3}, {4, 4}, {6, 4}, {8, 4}, {8, 8}};
  for (const auto& [ring, tube] : sizes)
    row("torus",
        gridOfMeshes([ring, tube](const Vec3& c) { return makeTorus(c, 1.0, 0.35, ring, tube); }));
}

}  // namespace meshtrace::bench
