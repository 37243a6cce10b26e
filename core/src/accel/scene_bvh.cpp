// Building the scene's two-level BVH: object boxes and the triangle BVH.
#include "accel/scene_bvh.h"

#include <chrono>
#include <cmath>
#include <cstdio>

namespace meshtrace {

namespace {

Aabb sphereBox(const Sphere& s) {
  const Vec3 r(std::abs(s.radius));
  return {s.center - r, s.center + r};
}

// The open tube: along world axis i it reaches |a_i| h/2 from the centre
// through the axis, plus r sqrt(1 - a_i^2) through the circular rim.
Aabb cylinderBox(const Cylinder& c) {
  Vec3 half;
  for (int i = 0; i < 3; ++i) {
    const double a = c.axis[i];
    half[i] = std::abs(a) * 0.5 * std::abs(c.height) +
              std::abs(c.radius) * std::sqrt(std::max(0.0, 1.0 - a * a));
  }
  return {c.center - half, c.center + half};
}

void buildMeshBvh(const BvhBuildOptions& options, MeshBvh& out) {
  out.tree = collapseToBvh8(buildBvh(out.triangles, options));
  out.frame = blockFrame(out.triangles.bounds());
  out.blocks = makeTriangleBlocks(out.triangles, out.frame, out.tree);
}

}  // namespace

SceneBvh::SceneBvh(const Scene& scene, const SceneBvhOptions& options) : scene_(scene) {
  const auto start = std::chrono::steady_clock::now();
  inMeshBvh_.resize(scene.meshes.size());
  for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
    const Mesh& mesh = scene.meshes[i];
    const std::size_t n = mesh.triangles().size();
    inMeshBvh_[i] = n > 0 && n >= options.minMeshTriangles;
    if (inMeshBvh_[i])
      meshBvh_.triangles.add(mesh, static_cast<std::uint32_t>(i));
    else if (n > 0)
      stats_.leftOut.push_back("no BVH for " + mesh.file().filename().string() + ": " +
                               std::to_string(n) + " triangles, under " +
                               std::to_string(options.minMeshTriangles));
  }
  if (!meshBvh_.triangles.empty()) buildMeshBvh(options.mesh, meshBvh_);
  meshBvh_.prefetch = !meshBvh_.empty() && meshBvh_.bytes() >= options.prefetchBytes;
  if (!meshBvh_.empty() && !meshBvh_.prefetch) {
    char why[128];
    std::snprintf(why, sizeof why,
                  "BVH children not fetched ahead: the triangle BVH's %.1f MB are under %.1f MB",
                  meshBvh_.bytes() / 1048576.0, options.prefetchBytes / 1048576.0);
    stats_.leftOut.push_back(why);
  }

  std::vector<Aabb> boxes;
  const auto add = [&](ObjectKind kind, std::size_t i, const Aabb& box) {
    objects_.push_back({kind, static_cast<std::uint32_t>(i)});
    boxes.push_back(box);
  };
  for (std::size_t i = 0; i < scene.spheres.size(); ++i)
    add(ObjectKind::Sphere, i, sphereBox(scene.spheres[i]));
  for (std::size_t i = 0; i < scene.cylinders.size(); ++i)
    add(ObjectKind::Cylinder, i, cylinderBox(scene.cylinders[i]));
  for (std::size_t i = 0; i < scene.meshes.size(); ++i)
    if (!scene.meshes[i].triangles().empty() && !inMeshBvh_[i])
      add(ObjectKind::Mesh, i, scene.meshes[i].bounds());
  if (!meshBvh_.empty()) add(ObjectKind::Mesh, kMeshBvh, meshBvh_.triangles.bounds());
  top_ = collapseToBvh8(buildBvh(boxes, options.top));
  for (const Aabb& b : boxes)
    sceneScale_ = std::max({sceneScale_, maxAbsComponent(b.min), maxAbsComponent(b.max)});

  stats_.topLevelObjects = objects_.size();
  stats_.topLevelBytes = top_.bytes() + objects_.size() * sizeof(Object);
  stats_.meshesWithBvh = meshBvh_.triangles.meshCount();
  stats_.trianglesInBvhs = meshBvh_.triangles.size();
  stats_.meshBvhBytes = meshBvh_.bytes();
  stats_.maxDepth = top_.depth + meshBvh_.tree.depth;
  stats_.buildSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace meshtrace
