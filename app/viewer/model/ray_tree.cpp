#include "viewer/model/ray_tree.h"

namespace meshtrace::viewer {

std::vector<RaySegment> rayTree(const PixelInspection& inspection, const Scene& scene,
                                double missLength,
                                const std::function<std::string(const PrimitiveRef&)>& describe) {
  std::vector<RaySegment> out;
  for (const BounceRecord& b : inspection.bounces) {
    const RayKind kind = b.level == 0 ? RayKind::Primary : RayKind::Reflection;
    if (!b.hit) {
      out.push_back(
          {b.ray.origin, b.ray.origin + missLength * b.ray.direction, kind, b.level, "miss"});
      continue;
    }
    const Vec3 hit = b.surface.point;
    out.push_back({b.ray.origin, hit, kind, b.level,
                   (b.level == 0 ? "hit: " : "bounce " + std::to_string(b.level) + ": ") +
                       describe(b.surface.ref)});
    for (const LightRecord& l : b.lights) {
      // A light behind the surface casts no shadow ray.
      if (!l.facing) continue;
      const Vec3 light = scene.lights[l.light].position;
      const std::string name = "light " + std::to_string(l.light);
      if (!l.shadowed) {
        out.push_back({hit, light, RayKind::Lit, b.level, name});
        continue;
      }
      const Vec3 blocker = l.blocker ? hit + l.toLight * l.blockerT : hit;
      out.push_back({hit, blocker, RayKind::Blocked, b.level,
                     "blocked by " + (l.blocker ? describe(*l.blocker) : std::string("?"))});
      out.push_back({blocker, light, RayKind::PastBlocker, b.level, name});
    }
  }
  return out;
}

}  // namespace meshtrace::viewer
