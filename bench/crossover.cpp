#include "crossover.h"

#include <cstdio>
#include <limits>

#include "meshtrace/mesh_generators.h"
#include "rays.h"

namespace meshtrace::bench {

namespace {

// 10 x 10 tori of 2 * ring * tube triangles on the xz plane, seen from above.
Scene toriScene(int ring, int tube) {
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
      scene.meshes.emplace_back("torus", makeTorus(Vec3(3.0 * i, 0.0, 3.0 * j), 1.0, 0.35, ring, tube),
                                Shading::Flat, Material{});
  return scene;
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
  std::printf("| triangles per mesh | Mrays/s, BVH per mesh | Mrays/s, no mesh BVH | BVH / none |\n"
              "|---:|---:|---:|---:|\n");
  const int sizes[][2] = {{2, 2}, {3, 2}, {4, 2}, {4, 3}, {4, 4}, {6, 4}, {8, 4}, {8, 8}};
  for (const auto& [ring, tube] : sizes) {
    const Scene scene = toriScene(ring, tube);
    const RaySet rays = primaryRays(scene);
    const double with = primaryMrays(scene, 0, rays);
    const double without = primaryMrays(scene, std::numeric_limits<std::size_t>::max(), rays);
    std::printf("| %d | %.2f | %.2f | %.2f |\n", 2 * ring * tube, with, without, with / without);
    std::fflush(stdout);
  }
}

}  // namespace meshtrace::bench
