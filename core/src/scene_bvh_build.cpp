// Building the scene's two-level BVH: object boxes and per-mesh BVHs.
#include <tbb/parallel_for.h>

#include <chrono>
#include <cmath>

#include "meshtrace/scene_bvh.h"

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

MeshBvh buildMeshBvh(const Mesh& mesh, const BvhBuildOptions& options) {
  MeshBvh out;
  out.tree = collapseToBvh8(buildBvh(mesh.vertices(), mesh.triangles(), options));
  out.frame = blockFrame(mesh);
  out.blocks = makeTriangleBlocks(mesh, out.frame, out.tree);
  return out;
}

}  // namespace

SceneBvh::SceneBvh(const Scene& scene, const SceneBvhOptions& options) : scene_(scene) {
  const auto start = std::chrono::steady_clock::now();
  meshBvhs_.resize(scene.meshes.size());
  tbb::parallel_for(std::size_t(0), scene.meshes.size(), [&](std::size_t i) {
    if (scene.meshes[i].triangles().size() >= options.minMeshTriangles)
      meshBvhs_[i] = buildMeshBvh(scene.meshes[i], options.mesh);
  });

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
    if (!scene.meshes[i].triangles().empty()) add(ObjectKind::Mesh, i, scene.meshes[i].bounds());
  top_ = collapseToBvh8(buildBvh(boxes, options.top));
  for (const Aabb& b : boxes)
    sceneScale_ = std::max({sceneScale_, maxAbsComponent(b.min), maxAbsComponent(b.max)});

  stats_.topLevelObjects = objects_.size();
  stats_.topLevelBytes = top_.bytes() + objects_.size() * sizeof(Object);
  stats_.maxDepth = top_.depth;
  int meshDepth = 0;
  for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
    const Mesh& mesh = scene.meshes[i];
    const MeshBvh& bvh = meshBvhs_[i];
    if (bvh.empty()) {
      if (!mesh.triangles().empty())
        stats_.leftOut.push_back("no BVH for " + mesh.file().filename().string() + ": " +
                                 std::to_string(mesh.triangles().size()) + " triangles, under " +
                                 std::to_string(options.minMeshTriangles));
      continue;
    }
    ++stats_.meshesWithBvh;
    stats_.trianglesInBvhs += mesh.triangles().size();
    stats_.meshBvhBytes += bvh.bytes();
    meshDepth = std::max(meshDepth, bvh.tree.depth);
  }
  stats_.maxDepth += meshDepth;
  stats_.buildSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace meshtrace
