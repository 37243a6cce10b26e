#pragma once
// One ray against single primitives, shared by the brute-force and the BVH
// intersectors so that both compute the same thing primitive by primitive.
//
// The closest hit must not depend on the order in which primitives are
// tested, or a BVH (which tests them in spatial order) could pick another
// one than brute force. So every kernel is called with no upper limit on t
// (a kernel's own cut-off may be rounded differently from a plain t < tMax,
// as the watertight test's is), and ties in t go to the primitive that
// brute force tests first: spheres, planes, cylinders, meshes, each by index,
// and within a mesh by triangle index.
#include <optional>
#include <utility>

#include "accel/hit_kind.h"
#include "meshtrace/geometry/scene.h"
#include "meshtrace/geometry/triangle.h"
#include "meshtrace/util/counters.h"

namespace meshtrace {

// Brute-force test order.
inline bool precedes(const PrimitiveRef& a, const PrimitiveRef& b) {
  if (a.kind != b.kind) return a.kind < b.kind;
  if (a.object != b.object) return a.object < b.object;
  return a.triangle < b.triangle;
}

// The nearest hit so far, kept in the caller's Hit; hit.t on entry is a
// strict upper limit.
class ClosestHit {
 public:
  explicit ClosestHit(Hit& hit) : hit_(hit) {}

  const double& t() const { return hit_.t; }
  bool found() const { return found_; }

  void offer(double t, const PrimitiveRef& ref, double beta = 0.0, double gamma = 0.0) {
    if (t < hit_.t || (found_ && t == hit_.t && precedes(ref, hit_.ref))) {
      hit_.t = t;
      hit_.ref = ref;
      hit_.beta = beta;
      hit_.gamma = gamma;
      found_ = true;
    }
  }

 private:
  Hit& hit_;
  bool found_ = false;
};

// Per-primitive tests for one ray: `offer*` hand the primitive's own nearest
// hit beyond tMin to a ClosestHit; `*Blocks` tell whether it has a hit at
// tMin < t < tMax.
// A query told the primitive its ray starts on leaves that primitive's test
// out if it is a triangle (spawn.h says why that is exact).
class PrimitiveQuery {
 public:
  PrimitiveQuery(const Scene& scene, const Ray& ray, TriangleKernel kernel, double tMin,
                 Counters& counters, const PrimitiveRef* start = nullptr)
      : scene_(scene), ray_(ray), kernel_(kernel), tMin_(tMin), counters_(counters) {
    if (start && start->kind == ObjectKind::Mesh) {
      startMesh_ = start->object;
      startTriangle_ = start->triangle;
    }
  }

  const Ray& ray() const { return ray_; }
  TriangleKernel kernel() const { return kernel_; }
  double tMin() const { return tMin_; }
  // Whether the ray was spawned from a triangle (it starts on a mesh).
  bool startsOnTriangle() const { return startTriangle_ != 0xffffffffu; }

  void offerTriangle(std::uint32_t mesh, std::uint32_t tri, ClosestHit& closest) const {
    ++counters_.triangleTests;
    TriangleHit th;
    if (triangle(mesh, tri, kInfinity, th))
      closest.offer(th.t, {ObjectKind::Mesh, mesh, tri}, th.beta, th.gamma);
  }
  bool triangleBlocks(std::uint32_t mesh, std::uint32_t tri, double tMax) const {
    ++counters_.triangleTests;
    TriangleHit th;
    return triangle(mesh, tri, tMax, th);
  }
  // triangleBlocks for a triangle the float filter proved a hit before
  // tMax (BlockRay::classify): true without the exact test, unless it is
  // the triangle the ray starts on, which is never tested.
  bool certainTriangleBlocks(std::uint32_t mesh, std::uint32_t tri) const {
    ++counters_.triangleTests;
    return !(tri == startTriangle_ && mesh == startMesh_);
  }

  // Spheres, planes and cylinders by kind and index.
  void offerShape(ObjectKind kind, std::uint32_t i, ClosestHit& closest) const {
    double t = kInfinity;
    if (shape(kind, i, t)) closest.offer(t, {kind, i, 0});
  }
  bool shapeBlocks(ObjectKind kind, std::uint32_t i, double tMax) const {
    double t = tMax;
    return shape(kind, i, t);
  }

 private:
  bool triangle(std::uint32_t mesh, std::uint32_t tri, double tMax, TriangleHit& th) const {
    if (tri == startTriangle_ && mesh == startMesh_) return false;
    const Mesh& m = scene_.meshes[mesh];
    const TriangleIndices& idx = m.triangles()[tri];
    const auto& v = m.vertices();
    // The per-ray set-up (the watertight shear's divisions) is made at the
    // first triangle test: rays that meet no triangle, such as every ray in
    // a scene without meshes, never pay for it.
    if (!triangleRay_) triangleRay_.emplace(ray_, kernel_);
    return triangleRay_->intersect(v[idx[0]], v[idx[1]], v[idx[2]], tMin_, tMax, th);
  }

  bool shape(ObjectKind kind, std::uint32_t i, double& t) const {
    switch (kind) {
      case ObjectKind::Sphere:
        ++counters_.sphereTests;
        return intersect(scene_.spheres[i], ray_, tMin_, t);
      case ObjectKind::Plane:
        ++counters_.planeTests;
        return intersect(scene_.planes[i], ray_, tMin_, t);
      case ObjectKind::Cylinder:
        ++counters_.cylinderTests;
        return intersect(scene_.cylinders[i], ray_, tMin_, t);
      case ObjectKind::Mesh: break;
    }
    return false;
  }

  const Scene& scene_;
  const Ray& ray_;
  TriangleKernel kernel_;
  mutable std::optional<TriangleRay> triangleRay_;
  double tMin_;
  Counters& counters_;
  // The triangle the ray starts on; no mesh has this many triangles.
  std::uint32_t startMesh_ = 0, startTriangle_ = 0xffffffffu;
};

// A query and what it does with each primitive it reaches, by the kind of
// hit it looks for; each call answers whether the search is over. limit()
// is the largest t still of interest: the closest hit's t so far, or the
// fixed limit of an any-hit search. The traversals take the search alone,
// its query inside it, so that a primitive's test reaches the ray in one
// step.
class ClosestHitSearch {
 public:
  static constexpr HitKind kKind = HitKind::Closest;
  // Keeps the closest hit in `hit`, whose t on entry is a strict upper
  // limit (ClosestHit); the query is made in place from `queryArgs`.
  template <typename... QueryArgs>
  explicit ClosestHitSearch(Hit& hit, QueryArgs&&... queryArgs)
      : query_(std::forward<QueryArgs>(queryArgs)...), closest_(hit) {}

  const PrimitiveQuery& query() const { return query_; }
  bool found() const { return closest_.found(); }
  const double& limit() const { return closest_.t(); }
  bool shape(ObjectKind kind, std::uint32_t i) {
    query_.offerShape(kind, i, closest_);
    return false;
  }
  bool triangle(std::uint32_t mesh, std::uint32_t tri) {
    query_.offerTriangle(mesh, tri, closest_);
    return false;
  }

 private:
  PrimitiveQuery query_;
  ClosestHit closest_;
};

class AnyHitSearch {
 public:
  static constexpr HitKind kKind = HitKind::Any;
  // Looks for a hit at tMin < t < tMax; the query is made in place from
  // `queryArgs`.
  template <typename... QueryArgs>
  explicit AnyHitSearch(double tMax, QueryArgs&&... queryArgs)
      : query_(std::forward<QueryArgs>(queryArgs)...), tMax_(tMax) {}

  const PrimitiveQuery& query() const { return query_; }
  const double& limit() const { return tMax_; }
  bool shape(ObjectKind kind, std::uint32_t i) {
    return query_.shapeBlocks(kind, i, tMax_) && endedBy({kind, i, 0});
  }
  bool triangle(std::uint32_t mesh, std::uint32_t tri) {
    return query_.triangleBlocks(mesh, tri, tMax_) && endedBy({ObjectKind::Mesh, mesh, tri});
  }
  // A triangle the float filter proved a hit before the limit.
  bool certainTriangle(std::uint32_t mesh, std::uint32_t tri) {
    return query_.certainTriangleBlocks(mesh, tri) && endedBy({ObjectKind::Mesh, mesh, tri});
  }
  // The same test of one primitive of the scene, named by `p`.
  bool primitive(const PrimitiveRef& p) {
    return p.kind == ObjectKind::Mesh ? triangle(p.object, p.triangle) : shape(p.kind, p.object);
  }
  // The primitive that ended the search, once one has.
  const PrimitiveRef& blocker() const { return blocker_; }

 private:
  bool endedBy(const PrimitiveRef& p) {
    blocker_ = p;
    return true;
  }

  PrimitiveQuery query_;
  double tMax_;
  PrimitiveRef blocker_;
};

}  // namespace meshtrace
