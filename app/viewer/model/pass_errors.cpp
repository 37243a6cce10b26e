#include "viewer/model/pass_errors.h"

#include <algorithm>
#include <bit>

#include "viewer/model/ab_compare.h"

namespace meshtrace::viewer {

namespace {
int levelCount(const ProgressiveFrame& frame) {
  return std::bit_width(static_cast<unsigned>(std::max(1, frame.tileSize)));
}

// The colours at storage pixel (col, row) as its tile's exact pass left
// them, where the tile has had it; else as they are now.
const std::uint8_t* exactOrCurrent(const ProgressiveFrame& f, int col, int row) {
  const std::size_t i = static_cast<std::size_t>(row) * f.width + col;
  if (!f.exactRgba.empty() && f.tileStep[(row / f.tileSize) * f.tilesX + col / f.tileSize] == 1)
    return &f.exactRgba[i * 4];
  return &f.rgba[i * 4];
}

Image8 emptyImage(const ProgressiveFrame& frame) {
  Image8 out;
  out.width = frame.width;
  out.height = frame.height;
  out.rgb.assign(static_cast<std::size_t>(out.width) * out.height * 3, 0);
  return out;
}
}  // namespace

Image8 levelPassImage(const ProgressiveFrame& frame, int pass) {
  Image8 out = emptyImage(frame);
  const int step = std::max(1, frame.tileSize >> pass);
  for (int row = 0; row < frame.height; ++row)
    for (int col = 0; col < frame.width; ++col) {
      // Tile corners are multiples of every step: the block's corner lies
      // in the same tile.
      const std::uint8_t* rgba = exactOrCurrent(frame, col - col % step, row - row % step);
      std::copy(rgba, rgba + 3, &out.rgb[(static_cast<std::size_t>(row) * out.width + col) * 3]);
    }
  return out;
}

Image8 currentImage(const ProgressiveFrame& frame) {
  Image8 out = emptyImage(frame);
  for (int row = 0; row < out.height; ++row)
    for (int col = 0; col < out.width; ++col)
      if (const std::uint8_t* rgba = frame.rgbaAt(col, row))
        std::copy(rgba, rgba + 3, &out.rgb[(static_cast<std::size_t>(row) * out.width + col) * 3]);
  return out;
}

bool PassErrors::due(const ProgressiveStatus& status) const {
  return status.job != job_ || status.passesDone > covered_ || (status.finished && !finished_);
}

void PassErrors::asked(const ProgressiveStatus& status) {
  if (status.job != job_) {
    points_.clear();
    job_ = status.job;
  }
  covered_ = status.passesDone;
  finished_ = status.finished;
}

void PassErrors::merge(const Comparison& c) {
  if (c.job != job_) return;
  for (const PassError& p : c.points) {
    const auto at = std::lower_bound(points_.begin(), points_.end(), p.pass,
                                     [](const PassError& a, int pass) { return a.pass < pass; });
    if (at == points_.end() || at->pass != p.pass) points_.insert(at, p);
  }
}

void PassErrors::clear() {
  job_ = 0;
  covered_ = 0;
  finished_ = false;
  points_.clear();
}

PassErrors::Comparison PassErrors::compare(const FrameCopy& copy, const Image8& reference,
                                           int firstPass) {
  const ProgressiveFrame& frame = copy.frame;
  const ProgressiveStatus& status = copy.status;
  Comparison c;
  c.job = copy.job;
  c.passesDone = status.passesDone;
  const int levels = levelCount(frame);
  for (int pass = firstPass; pass < status.passesDone; ++pass) {
    const bool aa = pass >= levels;
    // An anti-aliasing pass's image is gone once the next one changed it.
    if (aa && pass != status.passesDone - 1) continue;
    const Image8 image = aa ? currentImage(frame) : levelPassImage(frame, pass);
    const double ms = pass < static_cast<int>(status.passMs.size()) ? status.passMs[pass] : -1.0;
    c.points.push_back({pass, ms, compareImages(image, reference).rmse, aa});
  }
  const Image8 now = currentImage(frame);
  c.current = compareImages(now, reference);
  c.differenceRgba = differenceRgba(now, reference, kDifferenceGain);
  return c;
}

}  // namespace meshtrace::viewer
