#pragma once
// A pixel's whole ray tree as segments in the scene, for drawing over the
// image and from the observer camera: the primary ray from the eye to its
// hit, each reflection bounce, and each shadow ray toward its light (a
// blocked one to its blocker, which is named, then on to the light).
#include <functional>
#include <string>
#include <vector>

#include "meshtrace/render/inspect.h"

namespace meshtrace::viewer {

enum class RayKind {
  Primary,
  Reflection,
  Lit,          // a shadow ray that reaches its light
  Blocked,      // a shadow ray up to what blocks it
  PastBlocker,  // the rest of the way to the light of a blocked shadow ray
};

struct RaySegment {
  Vec3 from, to;
  RayKind kind;
  int level = 0;      // the bounce it leaves from (0: the primary hit)
  std::string label;  // what to write at `to`, if anything
};

// `describe` names what a ray hit ("mesh 'ball' #0"); a ray that meets
// nothing goes on for `missLength`.
std::vector<RaySegment> rayTree(const PixelInspection& inspection, const Scene& scene,
                                double missLength,
                                const std::function<std::string(const PrimitiveRef&)>& describe);

}  // namespace meshtrace::viewer
