#pragma once
// Whitted-style shading: ambient, diffuse and specular per light, hard
// shadows, and mirror reflection up to the scene's depth.
#include "meshtrace/intersector.h"
#include "meshtrace/surface.h"

namespace meshtrace {

class Integrator {
 public:
  explicit Integrator(const SceneIntersector& intersector) : intersector_(intersector) {}

  // Colour seen along `ray`, which is at recursion level `level` (0 = primary).
  Color trace(const Ray& ray, int level, Counters& counters) const;
  // Colour at image position (x, y) in pixels; y = 0 is the bottom row.
  Color pixel(double x, double y, Counters& counters) const;

  const SceneIntersector& intersector() const { return intersector_; }

 private:
  Color localColor(const Vec3& viewDir, const SurfacePoint& sp, Counters& counters) const;

  const SceneIntersector& intersector_;
};

}  // namespace meshtrace
