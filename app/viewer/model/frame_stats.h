#pragma once
// The durations of the UI's frames drawn while a render runs: the longest
// and the 99th percentile. Nothing to report until such a frame was drawn
// (a render may finish before the first one), which is not the same as 0 ms.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace meshtrace::viewer {

class FrameStats {
 public:
  void add(double ms) { samples_.push_back(ms); }
  void clear() { samples_.clear(); }
  std::size_t count() const { return samples_.size(); }

  std::optional<double> longest() const;
  // Nearest rank: the smallest duration that `percent` % of the frames do not exceed.
  std::optional<double> percentile(double percent) const;

 private:
  std::vector<double> samples_;
};

// "12.3 ms", or "-" when there is no figure.
std::string formatMs(std::optional<double> ms);

}  // namespace meshtrace::viewer
