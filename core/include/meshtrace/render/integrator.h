#pragma once
// Whitted-style shading: ambient, diffuse and specular per light, hard
// shadows, and mirror reflection up to the scene's depth (the recursion
// itself is in render/whitted.h).
#include <algorithm>
#include <vector>

#include "meshtrace/accel/intersector.h"

namespace meshtrace {

inline constexpr std::size_t kMaxPacketLights = 32;

// The LastBlocker of each light's shadow rays, per recursion level (the
// levels past the first few share one), for a run of pixels traced in turn
// on one thread: a render task keeps one over its tile, so that a pixel's
// shadow rays start from its neighbour's blocker.
class LastBlockers {
 public:
  explicit LastBlockers(const Scene& scene)
      : lights_(scene.lights.size()),
        slots_(lights_ * static_cast<std::size_t>(std::min(scene.depth, kLevels - 1) + 1)) {}

  LastBlocker* at(int level, std::size_t light) {
    return &slots_[static_cast<std::size_t>(std::min(level, kLevels - 1)) * lights_ + light];
  }

 private:
  static constexpr int kLevels = 4;
  std::size_t lights_;
  std::vector<LastBlocker> slots_;
};

class Integrator {
 public:
  explicit Integrator(const SceneIntersector& intersector) : intersector_(intersector) {}

  // Colour seen along `ray`, which is at recursion level `level` (0 = primary).
  // Each query may take `blockers`, which only makes it quicker.
  Color trace(const Ray& ray, int level, Counters& counters,
              LastBlockers* blockers = nullptr) const;
  // Colour at image position (x, y) in pixels of the scene's camera; y = 0 is
  // the bottom row.
  Color pixel(double x, double y, Counters& counters, LastBlockers* blockers = nullptr) const;
  // The colours of the 2x2 pixels (x, y), (x + 1, y), (x, y + 1) and
  // (x + 1, y + 1), in that order: pixel() of each, with their primary rays
  // traced as one packet, the shadow rays toward each light from their hits
  // as another, and their mirror reflections as the next level's packet (up
  // to kMaxPacketLights lights; with more, each ray's shading goes on alone).
  void quad(double x, double y, Color out[kPacketSize], Counters& counters,
            LastBlockers* blockers = nullptr) const;
  // The same through another camera (the viewer's, once moved).
  Color pixel(const Camera& camera, double x, double y, Counters& counters,
              LastBlockers* blockers = nullptr) const;
  void quad(const Camera& camera, double x, double y, Color out[kPacketSize], Counters& counters,
            LastBlockers* blockers = nullptr) const;

  const SceneIntersector& intersector() const { return intersector_; }

 private:
  const SceneIntersector& intersector_;
};

}  // namespace meshtrace
