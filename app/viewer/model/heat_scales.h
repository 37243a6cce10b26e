#pragma once
// The ranges the false-colour views are drawn with, measured over what a
// render has published so far: the largest box count and traversal cost
// present (not the number of meshes, which few rays reach), and the depth
// between robust percentiles of the hits (a floor running to the horizon
// would otherwise take the whole grey ramp and leave the objects one shade).
#include <cstdint>
#include <vector>

#include "meshtrace/render/progressive.h"
#include "viewer/model/views.h"

namespace meshtrace::viewer {

// The share of hit depths left out at each end of the depth scale, and
// how many depths along it the scale is drawn through (views.h).
inline constexpr double kDepthPercentile = 0.02;
inline constexpr int kDepthQuantiles = 17;

class ScaleTracker {
 public:
  // Forgets everything: a new render of `width` x `height` pixels.
  void reset(int width, int height);
  // Takes in what tile `tile` of `frame` holds now.
  void add(const ProgressiveFrame& frame, int tile);
  // Writes the ranges into `scales` (depthNear/Far, boxMax, costMax);
  // returns whether any of them changed since the last call.
  bool apply(FalseColorScales& scales);

 private:
  static constexpr int kDepthGrid = 8;  // depths sampled every 8th pixel each way
  int width_ = 0, height_ = 0;
  std::uint32_t boxMax_ = 0, costMax_ = 0;
  std::vector<float> depths_;  // per sample point: NaN until traced, -1 for a miss
  bool depthsChanged_ = false;
  std::vector<double> quantiles_;
};

// The value at `fraction` (0..1) of `values` in order, by nearest rank;
// reorders `values`. NaN for none.
double percentile(std::vector<float>& values, double fraction);

}  // namespace meshtrace::viewer
