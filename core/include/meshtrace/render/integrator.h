#pragma once
// Whitted-style shading: ambient, diffuse and specular per light, hard
// shadows, and mirror reflection up to the scene's depth (the recursion
// itself is in render/whitted.h).
#include "meshtrace/accel/intersector.h"

namespace meshtrace {

inline constexpr std::size_t kMaxPacketLights = 32;

class Integrator {
 public:
  explicit Integrator(const SceneIntersector& intersector) : intersector_(intersector) {}

  // Colour seen along `ray`, which is at recursion level `level` (0 = primary).
  Color trace(const Ray& ray, int level, Counters& counters) const;
  // Colour at image position (x, y) in pixels of the scene's camera; y = 0 is
  // the bottom row.
  Color pixel(double x, double y, Counters& counters) const;
  // The colours of the 2x2 pixels (x, y), (x + 1, y), (x, y + 1) and
  // (x + 1, y + 1), in that order: pixel() of each, with their primary rays
  // traced as one packet, the shadow rays toward each light from their hits
  // as another, and their mirror reflections as the next level's packet (up
  // to kMaxPacketLights lights; with more, each ray's shading goes on alone).
  void quad(double x, double y, Color out[kPacketSize], Counters& counters) const;
  // The same through another camera (the viewer's, once moved).
  Color pixel(const Camera& camera, double x, double y, Counters& counters) const;
  void quad(const Camera& camera, double x, double y, Color out[kPacketSize],
            Counters& counters) const;

  const SceneIntersector& intersector() const { return intersector_; }

 private:
  const SceneIntersector& intersector_;
};

}  // namespace meshtrace
