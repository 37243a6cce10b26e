// The pixel inspector's traversal: it must explain exactly what the
// Integrator rendered (same colour to the bit, same rays), and record hits,
// normals, shadows with their blockers, reflections and boxes faithfully.
#include "meshtrace/render/inspect.h"

#include <gtest/gtest.h>

#include "meshtrace/geometry/mesh_generators.h"
#include "meshtrace/geometry/triangle.h"
#include "meshtrace/io/mesh_writer.h"
#include "meshtrace/io/scene_parser.h"
#include "meshtrace/render/inspect_colors.h"
#include "meshtrace/render/integrator.h"
#include "meshtrace/render/render.h"
#include "support/files.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

// A PHONG icosphere, a FLAT box, a mirror sphere, a floor and two lights:
// shadows, reflections (depth 2) and both shading modes in 48x36 pixels.
Scene inspectionScene() {
  const auto dir = test::scratchDir();
  writeOff(makeIcosphere(Vec3(-1.2, 0.8, 0.0), 0.8, 2), dir / "ball.off");
  writeOff(makeGriddedBox(Vec3(0.6, 0.0, -0.5), Vec3(1.6, 1.0, 0.5), 1), dir / "box.off");
  const std::string text =
      "camera 0 2.5 6  0 0.6 0  0 1 0  45  48 36\n"
      "depth 2\nbackground 0.1 0.2 0.3\nambience 0.2 0.2 0.2\n"
      "light 2 5 3  0.8 0.8 0.8\nlight -3 4 1  0.4 0.3 0.2\n"
      "mesh ball.off PHONG 0.1 0.1 0.1  0.7 0.2 0.2  0.5 0.5 0.5  30 0\n"
      "mesh box.off FLAT 0.1 0.1 0.1  0.2 0.6 0.2  0.2 0.2 0.2  10 0.3\n"
      "sphere 0 0.5 1.2  0.5  0.1 0.1 0.1  0.1 0.1 0.1  0.9 0.9 0.9  80 0.8\n"
      "plane 0 0 0  0 1 0  0.1 0.1 0.1  0.6 0.6 0.6  0 0 0  1 0.2\n";
  return parseScene(text, dir / "inspect.sce");
}

// Calls body(x, y, inspection) for every pixel of the scene.
template <typename Body>
void inspectEveryPixel(const Scene& scene, const SceneIntersector& intersector, const Body& body) {
  for (int y = 0; y < scene.camera.height(); ++y)
    for (int x = 0; x < scene.camera.width(); ++x)
      body(x, y, inspectPixel(intersector, scene.camera, x, y));
}

TEST(Inspect, ColourAndRaysMatchTheIntegratorToTheBit) {
  const Scene scene = inspectionScene();
  const SceneIntersector intersector(scene, TraceOptions{});
  const Integrator integrator(intersector);
  int reflecting = 0;
  for (int y = 0; y < scene.camera.height(); ++y) {
    for (int x = 0; x < scene.camera.width(); ++x) {
      Counters c;
      const Color expected = integrator.pixel(x, y, c);
      const PixelInspection in = inspectPixel(intersector, scene.camera, x, y);
      ASSERT_EQ(in.color, expected) << "pixel " << x << "," << y;
      EXPECT_EQ(in.counters.shadowRays, c.shadowRays);
      EXPECT_EQ(in.counters.reflectionRays, c.reflectionRays);
      ASSERT_EQ(in.bounces.size(), c.reflectionRays + 1);
      reflecting += in.bounces.size() > 1;
    }
  }
  EXPECT_GT(reflecting, 50) << "the scene should exercise reflections";
}

TEST(Inspect, ReflectionLevelsComposeThePixel) {
  const Scene scene = inspectionScene();
  const SceneIntersector intersector(scene, TraceOptions{});
  int checked = 0;
  inspectEveryPixel(scene, intersector, [&](int, int, const PixelInspection& in) {
    for (std::size_t k = 0; k + 1 < in.bounces.size(); ++k) {
      const BounceRecord& b = in.bounces[k];
      const BounceRecord& next = in.bounces[k + 1];
      ASSERT_TRUE(b.reflects);
      EXPECT_EQ(next.level, b.level + 1);
      EXPECT_DOUBLE_EQ(next.weight, b.weight * b.mirror);
      EXPECT_EQ(b.color, (1.0 - b.mirror) * b.local + b.mirror * next.color);
      ++checked;
    }
    EXPECT_FALSE(in.bounces.back().reflects);
  });
  EXPECT_GT(checked, 0);
}

TEST(Inspect, LightsSumToTheLocalColourAndShadowsNameTheirBlocker) {
  const Scene scene = inspectionScene();
  const SceneIntersector intersector(scene, TraceOptions{});
  int shadowed = 0, lit = 0;
  inspectEveryPixel(scene, intersector, [&](int, int, const PixelInspection& in) {
    for (const BounceRecord& b : in.bounces) {
      if (!b.hit) continue;
      ASSERT_EQ(b.lights.size(), scene.lights.size());
      Color sum = b.ambient;
      for (const LightRecord& l : b.lights) {
        sum += l.diffuse;
        sum += l.specular;
        EXPECT_EQ(l.facing, l.nDotL > 0.0);
        if (!l.facing || l.shadowed) {
          EXPECT_EQ(l.diffuse, Color(0.0));
          EXPECT_EQ(l.specular, Color(0.0));
        }
        if (l.shadowed) {
          ++shadowed;
          ASSERT_TRUE(l.blocker.has_value());
          EXPECT_GT(l.blockerT, 0.0);
          const double toLight = glm::length(scene.lights[l.light].position - b.surface.point);
          EXPECT_LT(l.blockerT, toLight);
        } else if (l.facing) {
          ++lit;
          EXPECT_FALSE(l.blocker.has_value());
        }
      }
      EXPECT_NEAR(glm::length(sum - b.local), 0.0, 1e-12);
    }
  });
  EXPECT_GT(shadowed, 10);
  EXPECT_GT(lit, 10);
}

TEST(Inspect, MeshHitsCarryBarycentricsAndNormals) {
  const Scene scene = inspectionScene();
  const SceneIntersector intersector(scene, TraceOptions{});
  int phong = 0, flat = 0;
  inspectEveryPixel(scene, intersector, [&](int, int, const PixelInspection& in) {
    const BounceRecord& b = in.bounces[0];
    if (!b.hit || b.surface.ref.kind != ObjectKind::Mesh) return;
    const SurfaceRecord& s = b.surface;
    const Mesh& mesh = scene.meshes[s.ref.object];
    EXPECT_NEAR(s.alpha + s.beta + s.gamma, 1.0, 1e-12);
    EXPECT_GE(std::min({s.alpha, s.beta, s.gamma}), -1e-12);
    const TriangleIndices& t = mesh.triangles()[s.ref.triangle];
    EXPECT_EQ(s.geometricNormal,
              triangleNormal(mesh.vertices()[t[0]], mesh.vertices()[t[1]], mesh.vertices()[t[2]]));
    EXPECT_NEAR(glm::length(s.point - b.ray.at(s.t)), 0.0, 1e-9);
    EXPECT_EQ(s.phong, mesh.shading() == Shading::Phong);
    if (mesh.shading() == Shading::Phong) {
      ++phong;
      ASSERT_TRUE(s.hasVertexNormals);
      const Vec3 n = glm::normalize(s.alpha * s.vertexNormals[0] + s.beta * s.vertexNormals[1] +
                                    s.gamma * s.vertexNormals[2]);
      EXPECT_NEAR(glm::length(n - s.shadingNormal), 0.0, 1e-12);
      EXPECT_NEAR(s.normalAngleDegrees,
                  glm::degrees(std::acos(std::clamp(glm::dot(n, s.geometricNormal), -1.0, 1.0))),
                  1e-6);
    } else {
      ++flat;
      EXPECT_FALSE(s.hasVertexNormals);
      EXPECT_EQ(s.shadingNormal, s.geometricNormal);
      EXPECT_EQ(s.normalAngleDegrees, 0.0);
    }
    // The hit mesh's box was entered before the hit and left after it (to
    // rounding: a face in the box's plane meets the slab at the same t).
    bool found = false;
    for (const BoxRecord& box : b.boxes)
      if (box.mesh == s.ref.object) {
        found = true;
        EXPECT_LE(box.tEnter, s.t * (1 + 1e-12));
        EXPECT_GE(box.tExit, s.t * (1 - 1e-12));
      }
    EXPECT_TRUE(found);
    for (std::size_t i = 1; i < b.boxes.size(); ++i)
      EXPECT_LE(b.boxes[i - 1].tEnter, b.boxes[i].tEnter);
  });
  EXPECT_GT(phong, 20);
  EXPECT_GT(flat, 20);
}

TEST(Inspect, ProbeAgreesWithTheInspectionAndWithDebugAabb) {
  const Scene scene = inspectionScene();
  const SceneIntersector intersector(scene, TraceOptions{});
  const BoxHitCounts boxes = countBoxHits(scene, 1);
  inspectEveryPixel(scene, intersector, [&](int x, int y, const PixelInspection& in) {
    const PixelProbe p = probePixel(intersector, scene.camera, x, y);
    const BounceRecord& b = in.bounces[0];
    const int row = scene.camera.height() - 1 - y;
    EXPECT_EQ(p.boxHits, boxes.counts[static_cast<std::size_t>(row) * boxes.width + x]);
    ASSERT_EQ(p.hit(), b.hit);
    EXPECT_GT(p.cost, 0u);
    if (!b.hit) return;
    EXPECT_FLOAT_EQ(p.depth, static_cast<float>(b.surface.t));
    EXPECT_EQ(p.object, objectIndex(scene, b.surface.ref));
    EXPECT_EQ(p.kind, b.surface.ref.kind);
    EXPECT_EQ(p.triangle, b.surface.ref.triangle);
  });
}

TEST(Inspect, TheBvhNodesEnteredLeadFromEachRootToTheHit) {
  const Scene scene = inspectionScene();
  const SceneIntersector intersector(scene, TraceOptions{});
  int meshHits = 0;
  inspectEveryPixel(scene, intersector, [&](int x, int y, const PixelInspection& in) {
    const BounceRecord& b = in.bounces[0];
    const double tMax = b.hit ? b.surface.t * (1.0 + 1e-6) : kInfinity;
    const RayInverse inverse(b.ray);
    bool objectsRoot = false, leafHoldingTheHit = false;
    for (const BvhNodeBox& n : b.nodes) {
      double t0, t1;
      ASSERT_TRUE(intersectSlabs(n.box, inverse, 0.0, tMax, t0, t1)) << x << "," << y;
      objectsRoot = objectsRoot || (n.level == BvhLevel::Objects && n.depth == 0);
      const Vec3 p = b.surface.point;
      const double slack = 1e-6;
      leafHoldingTheHit =
          leafHoldingTheHit || (n.level == BvhLevel::Triangles && n.leaf &&
                                glm::all(glm::greaterThanEqual(p, n.box.min - slack)) &&
                                glm::all(glm::lessThanEqual(p, n.box.max + slack)));
    }
    if (!b.hit || b.surface.ref.kind != ObjectKind::Mesh) return;
    ++meshHits;
    EXPECT_TRUE(objectsRoot) << x << "," << y;
    EXPECT_TRUE(leafHoldingTheHit) << "the leaf of the hit triangle is entered: " << x << "," << y;
  });
  EXPECT_GT(meshHits, 100);
  TraceOptions none;
  none.accel = AccelMethod::None;
  const SceneIntersector bruteForce(scene, none);
  EXPECT_TRUE(inspectPixel(bruteForce, scene.camera, 10, 10).bounces[0].nodes.empty());
}

TEST(Inspect, ABvhCutCoversEveryTriangleAtEveryDepth) {
  const Scene scene = inspectionScene();
  const SceneIntersector intersector(scene, TraceOptions{});
  const BvhCut root = bvhCut(intersector, BvhLevel::Triangles, 0, 1000);
  ASSERT_EQ(root.boxes.size(), 1u);
  EXPECT_GE(root.levelDepth, 2);
  for (int depth = 0; depth <= root.levelDepth; ++depth) {
    const BvhCut cut = bvhCut(intersector, BvhLevel::Triangles, depth, 100000);
    EXPECT_FALSE(cut.truncated);
    for (const BvhNodeBox& n : cut.boxes) EXPECT_TRUE(n.depth == depth || n.leaf);
    for (const Mesh& mesh : scene.meshes)
      for (const TriangleIndices& t : mesh.triangles()) {
        const Vec3 c =
            (mesh.vertices()[t[0]] + mesh.vertices()[t[1]] + mesh.vertices()[t[2]]) / 3.0;
        bool inside = false;
        for (const BvhNodeBox& n : cut.boxes)
          inside = inside || (glm::all(glm::greaterThanEqual(c, n.box.min - 1e-6)) &&
                              glm::all(glm::lessThanEqual(c, n.box.max + 1e-6)));
        ASSERT_TRUE(inside) << "depth " << depth;
      }
  }
  const BvhCut deepest = bvhCut(intersector, BvhLevel::Triangles, root.levelDepth, 100000);
  for (const BvhNodeBox& n : deepest.boxes) EXPECT_TRUE(n.leaf);
  const BvhCut few = bvhCut(intersector, BvhLevel::Triangles, root.levelDepth, 3);
  EXPECT_EQ(few.boxes.size(), 3u);
  EXPECT_TRUE(few.truncated);
  // The objects' level: the sphere and the triangle BVH under one root.
  EXPECT_EQ(bvhCut(intersector, BvhLevel::Objects, 0, 10).boxes.size(), 1u);
}

TEST(Inspect, ObjectIndexNumbersKindsInSceneOrder) {
  const Scene scene = inspectionScene();  // 1 sphere, 1 plane, 0 cylinders, 2 meshes
  EXPECT_EQ(objectIndex(scene, {ObjectKind::Sphere, 0, 0}), 0);
  EXPECT_EQ(objectIndex(scene, {ObjectKind::Plane, 0, 0}), 1);
  EXPECT_EQ(objectIndex(scene, {ObjectKind::Mesh, 0, 5}), 2);
  EXPECT_EQ(objectIndex(scene, {ObjectKind::Mesh, 1, 0}), 3);
}

TEST(InspectColors, HeatRampGrowsBrighterAndClamps) {
  double last = -1.0;
  for (int i = 0; i <= 20; ++i) {
    const Color c = heatColor(i / 20.0);
    const double luma = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
    EXPECT_GT(luma, last) << i;
    last = luma;
  }
  EXPECT_EQ(heatColor(-3.0), heatColor(0.0));
  EXPECT_EQ(heatColor(7.0), heatColor(1.0));
  EXPECT_NE(idColor(1), idColor(2));
  EXPECT_EQ(normalColor(Vec3(1, 0, -1)), Color(1, 0.5, 0));
  EXPECT_EQ(depthColor(2.0, 2.0, 4.0), Color(1.0));
}

}  // namespace
}  // namespace meshtrace
