// The Preview structure (a uniform grid over runs of triangles, for a first
// pass while the BVH builds) finds what the BVH and brute force find, and a
// first-pass-only job stops after its first pass.
#include "render/progressive_preview.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "meshtrace/geometry/mesh_generators.h"
#include "meshtrace/io/mesh_writer.h"
#include "meshtrace/io/scene_parser.h"
#include "meshtrace/render/progressive.h"
#include "support/files.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

// A knot and a torus (two meshes, one grid), a lone triangle far off, a
// sphere, a cylinder and a floor: every kind the grid and the brute-force
// shape tests serve.
std::shared_ptr<Scene> previewScene() {
  const auto dir = test::scratchDir();
  writeOff(makeTorusKnot(Vec3(0.0, 1.2, 0.0), 0.4, 2, 3, 0.35, 256, 16), dir / "knot.off");
  writeOff(makeTorus(Vec3(1.6, 0.5, -0.5), 0.6, 0.2, 24, 12), dir / "torus.off");
  test::writeFile(dir / "tri.off", "OFF\n3 1 0\n-3 0 -3\n-2 0 -3\n-2.5 1.5 -3\n3 0 1 2\n");
  const std::string text =
      "camera 0 2 6  0 0.8 0  0 1 0  45  96 72\nambience 0.2 0.2 0.2\nlight 3 4 3  0.9 0.9 0.9\n"
      "mesh knot.off PHONG 0.1 0.1 0.1  0.7 0.4 0.2  0.5 0.5 0.5  30 0\n"
      "mesh torus.off FLAT 0.1 0.1 0.1  0.2 0.4 0.7  0.5 0.5 0.5  30 0\n"
      "mesh tri.off FLAT 0.1 0.1 0.1  0.2 0.7 0.2  0 0 0  1 0\n"
      "sphere -1.5 0.5 0.5 0.5  0.1 0.1 0.1  0.6 0.6 0.6  0 0 0  1 0\n"
      "cylinder 1.5 0.5 1 0.2 0 1 0 1  0.1 0.1 0.1  0.6 0.6 0.6  0 0 0  1 0\n"
      "plane 0 0 0  0 1 0  0.1 0.1 0.1  0.5 0.5 0.5  0 0 0  1 0\n";
  return std::make_shared<Scene>(parseScene(text, dir / "preview.sce"));
}

// Every primary ray of `scene`'s camera finds through `grid` the hit brute
// force finds.
void expectBruteForceHits(const Scene& scene, const PreviewGrid& grid, const std::string& what) {
  TraceOptions none;
  none.accel = AccelMethod::None;
  const SceneIntersector bruteForce(scene, none);
  for (int y = 0; y < scene.camera.height(); ++y)
    for (int x = 0; x < scene.camera.width(); ++x) {
      const Ray ray = scene.camera.primaryRay(x, y);
      Counters c;
      Hit a, b;
      ASSERT_EQ(bruteForce.closestHit(ray, 0.0, a, c), grid.closestHit(ray, 0.0, b, c));
      ASSERT_EQ(a.t, b.t) << what << " " << x << "," << y;
      ASSERT_EQ(a.ref.triangle, b.ref.triangle) << what << " " << x << "," << y;
    }
}

TEST(PreviewGrid, FindsTheBvhsNearestHitAndBlockersForEveryPixel) {
  const auto scene = previewScene();
  const PreparedScene full(scene, TraceOptions{});
  const PreparedScene preview(scene, TraceOptions{}, SceneStructure::Preview);
  EXPECT_FALSE(preview.built());
  const SceneIntersector& grid = preview.intersector();
  EXPECT_TRUE(preview.built());
  const Camera& camera = scene->camera;
  int meshHits = 0, blocked = 0;
  for (int y = 0; y < camera.height(); ++y)
    for (int x = 0; x < camera.width(); ++x) {
      const Ray ray = camera.primaryRay(x, y);
      Counters c;
      Hit a, b;
      const bool foundA = full.intersector().closestHit(ray, 0.0, a, c);
      const bool foundB = grid.closestHit(ray, 0.0, b, c);
      ASSERT_EQ(foundA, foundB) << x << "," << y;
      if (!foundA) continue;
      ASSERT_EQ(a.t, b.t) << x << "," << y;
      ASSERT_EQ(a.ref.kind, b.ref.kind);
      ASSERT_EQ(a.ref.object, b.ref.object);
      ASSERT_EQ(a.ref.triangle, b.ref.triangle);
      ASSERT_EQ(a.beta, b.beta);
      ASSERT_EQ(a.gamma, b.gamma);
      meshHits += a.ref.kind == ObjectKind::Mesh;
      // Toward the light, from a point a little off the surface.
      const Vec3 p = ray.origin + a.t * ray.direction;
      const Vec3 toLight = scene->lights[0].position - p;
      const double dist = glm::length(toLight);
      const Ray shadow{p + 1e-6 * toLight / dist, toLight / dist};
      const bool occA = full.intersector().occluded(shadow, 0.0, dist, c);
      ASSERT_EQ(occA, grid.occluded(shadow, 0.0, dist, c)) << x << "," << y;
      blocked += occA;
    }
  EXPECT_GT(meshHits, 500) << "the meshes fill a good part of the image";
  EXPECT_GT(blocked, 100) << "and shadow each other";
}

TEST(PreviewGrid, TrianglesAcrossTheWholeSceneMakeACoarserGridNotAHugeOne) {
  // 200 slanted triangles whose boxes span the whole scene beside 1,280
  // small ones: listed in every cell of a grid fine enough for the small
  // ones, they would take 200 times its cells.
  const auto dir = test::scratchDir();
  MeshData mesh = makeIcosphere(Vec3(0.0), 1.0, 3);
  for (int i = 0; i < 200; ++i) {
    const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
    const double z = -2.0 + 0.01 * i;
    mesh.vertices.insert(mesh.vertices.end(), {Vec3(-3, -3, z), Vec3(3, -3, z + 2), Vec3(0, 3, z)});
    mesh.triangles.push_back({base, base + 1, base + 2});
  }
  writeOff(mesh, dir / "slanted.off");
  const Scene scene = parseScene(
      "camera 0 0 9  0 0 0  0 1 0  45  40 40\nlight 3 4 9  1 1 1\n"
      "mesh slanted.off FLAT 0.1 0.1 0.1  0.5 0.5 0.5  0 0 0  1 0\n",
      dir / "slanted.sce");
  const PreviewGrid grid(scene, TriangleKernel{});
  EXPECT_LE(grid.entries(), 16 * mesh.triangles.size());
  expectBruteForceHits(scene, grid, "slanted");
}

TEST(PreviewGrid, ChunksFollowTheSurfaceOrderAndSingleTrianglesServeAShuffledMesh) {
  const auto dir = test::scratchDir();
  MeshData knot = makeTorusKnot(Vec3(0.0), 0.5, 2, 3, 0.3, 128, 16);
  writeOff(knot, dir / "ordered.off");
  std::mt19937 random(7);
  std::shuffle(knot.triangles.begin(), knot.triangles.end(), random);
  writeOff(knot, dir / "shuffled.off");
  for (const char* name : {"ordered", "shuffled"}) {
    const Scene scene = parseScene(
        "camera 0 0 4  0 0 0  0 1 0  45  32 32\nlight 3 4 3  1 1 1\n"
        "mesh " +
            std::string(name) + ".off FLAT 0.1 0.1 0.1  0.5 0.5 0.5  0 0 0  1 0\n",
        dir / (std::string(name) + ".sce"));
    const PreviewGrid grid(scene, TriangleKernel{});
    EXPECT_EQ(grid.chunkSize(), name == std::string("ordered") ? 16u : 1u) << name;
    expectBruteForceHits(scene, grid, name);
  }
}

TEST(Progressive, AFirstPassOnlyJobEndsAfterItsFirstPassAndEveryPassIsTimed) {
  const auto scene = previewScene();
  ProgressiveRenderer renderer(2);
  ProgressiveSettings settings;
  settings.firstStep = 16;
  settings.firstPassOnly = true;
  renderer.start(std::make_shared<PreparedScene>(scene, TraceOptions{}, SceneStructure::Preview),
                 scene->camera, settings);
  ASSERT_TRUE(renderer.waitUntilFinished(60000));
  ProgressiveStatus s = renderer.status();
  EXPECT_TRUE(s.finished && s.coarseDone);
  EXPECT_FALSE(s.exactDone);
  EXPECT_EQ(s.passCount, 1);
  ASSERT_EQ(s.passMs.size(), 1u);
  EXPECT_GE(s.passMs[0], 0.0);
  EXPECT_EQ(s.counters.primaryRays, 6u * 5u) << "one pixel per 16x16 block of 96x72";

  settings.firstPassOnly = false;
  settings.extraSamples = 1;
  renderer.start(std::make_shared<PreparedScene>(scene, TraceOptions{}), scene->camera, settings);
  ASSERT_TRUE(renderer.waitUntilFinished(60000));
  s = renderer.status();
  ASSERT_EQ(s.passMs.size(), 6u);  // 16, 8, 4, 2, 1, one AA pass
  for (std::size_t p = 1; p < s.passMs.size(); ++p) EXPECT_GE(s.passMs[p], s.passMs[p - 1]);
  EXPECT_EQ(s.passMs[4], s.exactMs);
  EXPECT_EQ(s.passMs[5], s.finishedMs);
}

}  // namespace
}  // namespace meshtrace
