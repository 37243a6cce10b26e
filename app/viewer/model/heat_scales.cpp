#include "viewer/model/heat_scales.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace meshtrace::viewer {

void ScaleTracker::reset(int width, int height) {
  width_ = width;
  height_ = height;
  boxMax_ = costMax_ = 0;
  const int gw = (width + kDepthGrid - 1) / kDepthGrid, gh = (height + kDepthGrid - 1) / kDepthGrid;
  depths_.assign(static_cast<std::size_t>(gw) * gh, std::numeric_limits<float>::quiet_NaN());
  depthsChanged_ = false;
  quantiles_.clear();
}

void ScaleTracker::add(const ProgressiveFrame& frame, int tile) {
  if (frame.probes.empty()) return;
  const int step = frame.tileStep[tile];
  if (step <= 0) return;
  const int c0 = (tile % frame.tilesX) * frame.tileSize,
            r0 = (tile / frame.tilesX) * frame.tileSize;
  const int c1 = std::min(c0 + frame.tileSize, frame.width);
  const int r1 = std::min(r0 + frame.tileSize, frame.height);
  // Every traced pixel counts for the maxima; the depth samples sit on a
  // fixed grid, each taken once it is traced (tile corners are multiples
  // of every step, so a grid point is traced once the step reaches it).
  for (int r = r0; r < r1; r += step)
    for (int c = c0; c < c1; c += step) {
      const PixelProbe& p = frame.probes[static_cast<std::size_t>(r) * frame.width + c];
      boxMax_ = std::max<std::uint32_t>(boxMax_, p.boxHits);
      costMax_ = std::max(costMax_, p.cost);
      if (r % kDepthGrid || c % kDepthGrid) continue;
      float& d = depths_[static_cast<std::size_t>(r / kDepthGrid) *
                             ((width_ + kDepthGrid - 1) / kDepthGrid) +
                         c / kDepthGrid];
      if (std::isnan(d)) {
        d = p.hit() ? p.depth : -1.0f;
        depthsChanged_ = true;
      }
    }
}

double percentile(std::vector<float>& values, double fraction) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto k = static_cast<std::size_t>(std::clamp(
      std::ceil(fraction * double(values.size())) - 1.0, 0.0, double(values.size() - 1)));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

bool ScaleTracker::apply(FalseColorScales& scales) {
  const FalseColorScales before = scales;
  scales.boxMax = std::max(1u, boxMax_);
  scales.costMax = std::max(1u, costMax_);
  if (depthsChanged_) {
    depthsChanged_ = false;
    std::vector<float> hits;
    for (float d : depths_)
      if (d >= 0.0f) hits.push_back(d);
    if (!hits.empty()) {
      quantiles_.clear();
      for (int k = 0; k < kDepthQuantiles; ++k)
        quantiles_.push_back(percentile(
            hits, kDepthPercentile + (1.0 - 2.0 * kDepthPercentile) * k / (kDepthQuantiles - 1)));
    }
  }
  scales.depthQuantiles = quantiles_;
  scales.depthNear = quantiles_.empty() ? 0.0 : quantiles_.front();
  scales.depthFar = quantiles_.empty() ? 1.0 : quantiles_.back();
  return scales.boxMax != before.boxMax || scales.costMax != before.costMax ||
         scales.depthQuantiles != before.depthQuantiles;
}

}  // namespace meshtrace::viewer
