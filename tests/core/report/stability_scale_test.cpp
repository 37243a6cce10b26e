// Stability case 2, scale and offset invariance.
// (a) Rays spawned from a hit (shadow and reflection directions) never hit
//     the surface they left, for triangles, spheres, planes and cylinders of
//     size 1e-4 to 1e4 placed at 0, 1e4 and 1e6 on every axis.
// (b) A scene translated by 1e4 or 1e6, or scaled by 1e-4 or 1e4, renders
//     the same image as the original: no acne, no lost contact shadows.
#include <gtest/gtest.h>

#include <cstdio>

#include "meshtrace/render/render.h"
#include "meshtrace/report/image_compare.h"
#include "meshtrace/report/stability.h"

namespace meshtrace {
namespace {

constexpr double kScales[] = {1e-4, 1.0, 1e4};
constexpr double kOffsets[] = {0.0, 1e4, 1e6};
constexpr int kSamples = 300;  // per scale and offset

SelfHitResult selfHitsOverScales(ObjectKind kind, TriangleKernel kernel) {
  SelfHitResult total;
  std::uint64_t seed = 1;
  for (double scale : kScales)
    for (double offset : kOffsets) {
      const SelfHitResult r =
          measureSelfIntersection(kind, kernel, scale, offset, kSamples, seed++);
      total.primaryHits += r.primaryHits;
      total.spawned += r.spawned;
      total.reHits += r.reHits;
    }
  return total;
}

void print(const char* what, const SelfHitResult& r) {
  std::printf("[ figures  ] %-28s primary hits %5zu  spawned %5zu  re-hits %zu\n", what,
              r.primaryHits, r.spawned, r.reHits);
}

TEST(StabilityScale, SpawnedRaysNeverReHitShapes) {
  for (ObjectKind kind : {ObjectKind::Sphere, ObjectKind::Plane, ObjectKind::Cylinder}) {
    const SelfHitResult r = selfHitsOverScales(kind, TriangleKernel{});
    print(toString(kind), r);
    EXPECT_EQ(r.primaryHits, std::size(kScales) * std::size(kOffsets) * kSamples) << toString(kind);
    EXPECT_EQ(r.reHits, 0u) << toString(kind);
  }
}

TEST(StabilityScale, SpawnedRaysNeverReHitTriangles) {
  for (const TriangleKernel& k : allTriangleKernels()) {
    const SelfHitResult r = selfHitsOverScales(ObjectKind::Mesh, k);
    const std::string label =
        std::string("triangle ") + toString(k.test) + " " + toString(k.precision);
    print(label.c_str(), r);
    // Every double kernel finds every primary hit; in single precision a
    // triangle of size 1e-4 at 1e6 is below float resolution and vanishes.
    if (k.precision == Precision::Double) {
      EXPECT_EQ(r.primaryHits, 9u * kSamples) << label;
    }
    // The guarantee: the watertight test rejects t within its error bound.
    // Cramer and Moller-Trumbore have no such bound; in double the offset
    // alone keeps their spawned rays off the surface here, in single all
    // but rarely (one ray in 6177 when measured). Rays that start on the
    // surface itself re-hit it nearly half the time, so a rate above one
    // in a thousand means the offset no longer works.
    if (k.test == TriangleTest::Watertight || k.precision == Precision::Double) {
      EXPECT_EQ(r.reHits, 0u) << label;
    } else {
      EXPECT_LE(r.reHits * 1000, r.spawned) << label;
    }
  }
}

// A small scene with every primitive kind, a sphere and a box resting on the
// plane (contact shadows), mirrors and two lights, with positions mapped by
// p -> scale * p + offset.
Scene testScene(double scale, double offset) {
  const auto map = [&](const Vec3& p) { return scale * p + Vec3(offset); };
  Scene s;
  s.file = "invariance.sce";
  s.camera =
      Camera(CameraSpec{map({0.3, 1.6, 5.0}), map({0.0, 0.5, 0.0}), {0, 1, 0}, 45.0, 96, 72});
  s.depth = 2;
  s.background = Color(0.1, 0.1, 0.3);
  s.ambience = Color(0.2);
  s.lights = {{map({4, 6, 4}), Color(0.8)}, {map({-5, 3, 2}), Color(0.4)}};
  const Material matte{Color(0.3), Color(0.6, 0.5, 0.4), Color(0.3), 20.0, 0.0};
  const Material mirror{Color(0.2), Color(0.3, 0.4, 0.6), Color(0.5), 50.0, 0.4};
  s.planes.push_back({map({0, 0, 0}), {0, 1, 0}, {Color(0.2), Color(0.7), Color(0.0), 1.0, 0.3}});
  s.spheres.push_back({map({-1.0, 0.7, 0.0}), 0.7 * scale, mirror});
  s.cylinders.push_back({map({1.2, 0.6, -0.5}), 0.4 * scale, {0, 1, 0}, 1.2 * scale, matte});
  MeshData box = makeClosedGridBox(2);
  for (Vec3& v : box.vertices) v = map(Vec3(0.2, 0.4, 1.0) + 0.4 * v);
  s.meshes.emplace_back("box.off", std::move(box), Shading::Flat, mirror);
  return s;
}

TEST(StabilityScale, RenderIsInvariantUnderTranslationAndScale) {
  const Image8 reference = quantize(render(testScene(1.0, 0.0), {}));
  const struct {
    double scale, offset;
  } cases[] = {{1.0, 1e4}, {1.0, 1e6}, {1e-4, 0.0}, {1e4, 0.0}, {1e-4, 1e4}, {1e-4, 1e6}};
  for (const auto& c : cases) {
    const Image8 moved = quantize(render(testScene(c.scale, c.offset), {}));
    const ImageDifference d = compareImages(moved, reference);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < moved.rgb.size(); ++i) differ += moved.rgb[i] != reference.rgb[i];
    std::printf("[ figures  ] scale %-6g offset %-6g RMSE %.3f  max %d  channels differing %zu\n",
                c.scale, c.offset, d.rmse, d.maxDifference, differ);
    // Measured: identical images. Acne or a lost contact shadow would
    // change hundreds of the 6912 pixels, a rounding decision flipped on a
    // silhouette or a shared edge a few; here not even those may differ.
    EXPECT_EQ(differ, 0u) << "scale " << c.scale << " offset " << c.offset;
  }
}

}  // namespace
}  // namespace meshtrace
