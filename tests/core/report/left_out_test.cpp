// Each kind of work a scene may leave out is pinned on a purpose-made scene:
// it is listed by leftOut (or by the BVH's own stats) exactly when the
// scene does not need it, and the render's counters confirm it was skipped.
#include "meshtrace/report/left_out.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "accel/scene_bvh.h"
#include "meshtrace/render/render.h"
#include "meshtrace/report/stability.h"

namespace meshtrace {
namespace {

bool listed(const std::vector<std::string>& items, const std::string& prefix) {
  return std::any_of(items.begin(), items.end(),
                     [&](const std::string& s) { return s.rfind(prefix, 0) == 0; });
}

// One sphere in front of the camera, 16x12 pixels; the rest per test.
Scene baseScene() {
  Scene s;
  s.file = "left_out.sce";
  s.camera = Camera(CameraSpec{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 45.0, 16, 12});
  s.spheres.push_back({{0, 0, 0}, 1.0, {Color(0.2), Color(0.5), Color(0.2), 10.0, 0.0}});
  return s;
}

Counters renderCounters(const Scene& s) {
  Counters c;
  render(s, {}, &c);
  return c;
}

// The grid box of side n, or with n = 0 just two triangles (one square face:
// under any sensible BVH threshold).
void addMesh(Scene& s, int gridN, Shading shading, const char* name) {
  MeshData box = makeClosedGridBox(std::max(gridN, 1));
  if (gridN == 0) box.triangles.resize(2);
  for (Vec3& v : box.vertices) v = 0.3 * v + Vec3(1.5, 0.0, 0.0);
  s.meshes.emplace_back(name, std::move(box), shading, Material{});
}

TEST(LeftOut, VertexNormalsOnlyForPhongMeshes) {
  Scene flat = baseScene();
  addMesh(flat, 1, Shading::Flat, "flat.off");
  EXPECT_TRUE(listed(leftOut(flat), "vertex normals not computed: no PHONG mesh"));
  EXPECT_EQ(vertexNormalsComputed(flat), 0u);

  Scene mixed = flat;
  addMesh(mixed, 1, Shading::Phong, "phong.off");
  EXPECT_FALSE(listed(leftOut(mixed), "vertex normals not computed: no PHONG mesh"));
  EXPECT_TRUE(listed(leftOut(mixed), "vertex normals not computed for flat.off"));
  EXPECT_EQ(vertexNormalsComputed(mixed), mixed.meshes[1].vertices().size());
}

TEST(LeftOut, NoShadowRaysWithoutLights) {
  Scene dark = baseScene();
  EXPECT_TRUE(listed(leftOut(dark), "no shadow rays"));
  EXPECT_EQ(renderCounters(dark).shadowRays, 0u);

  Scene lit = baseScene();
  lit.lights.push_back({{2, 3, 4}, Color(1.0)});
  EXPECT_FALSE(listed(leftOut(lit), "no shadow rays"));
  EXPECT_GT(renderCounters(lit).shadowRays, 0u);
}

TEST(LeftOut, NoReflectionRaysWithoutMirrorsOrDepth) {
  Scene mirror = baseScene();
  mirror.spheres[0].material.mirror = 0.5;
  mirror.planes.push_back({{0, -1, 0}, {0, 1, 0}, {}});

  Scene depth0 = mirror;  // mirrors but depth 0
  EXPECT_TRUE(listed(leftOut(depth0), "no reflection rays: depth is 0"));
  EXPECT_EQ(renderCounters(depth0).reflectionRays, 0u);

  Scene noMirror = baseScene();
  noMirror.depth = 3;
  EXPECT_TRUE(listed(leftOut(noMirror), "no reflection rays: no material"));
  EXPECT_EQ(renderCounters(noMirror).reflectionRays, 0u);

  mirror.depth = 3;
  EXPECT_FALSE(listed(leftOut(mirror), "no reflection rays"));
  EXPECT_GT(renderCounters(mirror).reflectionRays, 0u);
}

TEST(LeftOut, NoBvhForSmallMeshes) {
  Scene s = baseScene();
  addMesh(s, 0, Shading::Flat, "small.off");  // 2 triangles
  addMesh(s, 4, Shading::Flat, "large.off");  // 192 triangles
  ASSERT_LT(s.meshes[0].triangles().size(), kMinBvhTriangles);
  ASSERT_GE(s.meshes[1].triangles().size(), kMinBvhTriangles);
  const SceneIntersector intersector(s, TraceOptions{});
  ASSERT_NE(intersector.bvh(), nullptr);
  const auto& items = intersector.bvh()->stats().leftOut;
  EXPECT_TRUE(listed(items, "no BVH for small.off"));
  EXPECT_FALSE(listed(items, "no BVH for large.off"));
  EXPECT_FALSE(intersector.bvh()->inMeshBvh(0));
  EXPECT_TRUE(intersector.bvh()->inMeshBvh(1));
}

TEST(LeftOut, OpenMeshCrossCheckNotRunUnlessAsked) {
  Scene s = baseScene();
  EXPECT_FALSE(listed(leftOut(s), "OpenMesh cross-check"));  // no mesh: nothing to check
  addMesh(s, 1, Shading::Phong, "m.off");
  EXPECT_TRUE(listed(leftOut(s), "OpenMesh cross-check of the normals not run"));
}

}  // namespace
}  // namespace meshtrace
