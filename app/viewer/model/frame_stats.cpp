#include "viewer/model/frame_stats.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace meshtrace::viewer {

std::optional<double> FrameStats::longest() const {
  if (samples_.empty()) return std::nullopt;
  return *std::max_element(samples_.begin(), samples_.end());
}

std::optional<double> FrameStats::percentile(double percent) const {
  if (samples_.empty()) return std::nullopt;
  std::vector<double> sorted = samples_;
  std::sort(sorted.begin(), sorted.end());
  const double rank = std::ceil(percent / 100.0 * double(sorted.size()));
  const std::size_t i = static_cast<std::size_t>(std::clamp(rank, 1.0, double(sorted.size())));
  return sorted[i - 1];
}

std::string formatMs(std::optional<double> ms) {
  if (!ms) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f ms", *ms);
  return buf;
}

}  // namespace meshtrace::viewer
