#include "viewer/ui/view_textures.h"

#include <algorithm>
#include <utility>

#include "meshtrace/io/image.h"
#include "meshtrace/render/inspect_colors.h"

namespace meshtrace::viewer {

namespace {
void putColor(std::uint8_t* out, const Color& c) {
  for (int k = 0; k < 3; ++k) out[k] = toByte(c[k]);
  out[3] = 255;
}
}  // namespace

void ViewTextures::sizeFor(int width, int height, bool withOverlay) {
  const auto sizeDiffers = [&](const gl::Texture& t) {
    return !t.valid() || t.width() != width || t.height() != height;
  };
  blank_ = blank_ || sizeDiffers(image_) || (withOverlay && sizeDiffers(overlay_));
  image_.resize(width, height);
  if (withOverlay) overlay_.resize(width, height);
}

void ViewTextures::fit(const ProgressiveFrame& frame, bool withOverlay) {
  // A texture made or resized holds nothing yet: every tile is coloured again.
  sizeFor(frame.width, frame.height, withOverlay);
  const bool resized = std::exchange(blank_, false) || stale_.size() != frame.tileStep.size();
  const std::size_t rowOfTiles = static_cast<std::size_t>(frame.width) * frame.tileSize * 4;
  viewRgba_.resize(rowOfTiles);
  if (withOverlay) overlayRgba_.resize(rowOfTiles);
  if (resized) {
    stale_.assign(frame.tileStep.size(), 0);
    markAll();
  }
}

void ViewTextures::markChanged(const std::vector<int>& tiles) {
  for (int t : tiles) stale_[t] = 1;
}

void ViewTextures::markTraced(const ProgressiveFrame& frame) {
  for (std::size_t t = 0; t < stale_.size(); ++t)
    if (frame.tileStep[t] > 0) stale_[t] = 1;
}

void ViewTextures::markAll() { std::fill(stale_.begin(), stale_.end(), 1); }

bool ViewTextures::current() const {
  return std::find(stale_.begin(), stale_.end(), 1) == stale_.end();
}

void ViewTextures::colorTile(const ProgressiveFrame& frame, int t, View view, Overlay overlay,
                             const FalseColorScales& scales) {
  const bool probeView = needsProbes(view);
  const bool withOverlay = overlay != Overlay::None && !frame.probes.empty();
  const int c0 = (t % frame.tilesX) * frame.tileSize, r0 = (t / frame.tilesX) * frame.tileSize;
  const int c1 = std::min(c0 + frame.tileSize, frame.width);
  const int r1 = std::min(r0 + frame.tileSize, frame.height);
  const int step = std::max(1, frame.tileStep[t]);
  // Pixel (c, r) in the frame, and in the staging rows of the tile's row.
  const auto at = [&](int c, int r) { return (static_cast<std::size_t>(r) * frame.width + c) * 4; };
  const auto staged = [&](int c, int r) { return at(c, r - r0); };
  if (!probeView && frame.tileStep[t] == 1) {
    // Exact colours: whole rows as they are.
    for (int r = r0; r < r1; ++r)
      std::copy(&frame.rgba[at(c0, r)], &frame.rgba[at(c1, r)], &viewRgba_[staged(c0, r)]);
    if (!withOverlay) return;
  }
  // Each traced pixel stands for the step x step block it is the corner of:
  // one colour per block.
  for (int br = r0; br < r1; br += step)
    for (int bc = c0; bc < c1; bc += step) {
      const PixelProbe* p = frame.probeAt(bc, br);
      std::uint8_t viewColor[4] = {0, 0, 0, 0}, heat[4] = {0, 0, 0, 0};
      if (p && probeView) putColor(viewColor, falseColor(view, *p, scales));
      if (p && withOverlay && overlayCovers(overlay, *p))
        putColor(heat, heatColor(overlayValue(overlay, *p, scales)));
      const std::uint8_t* rgba = frame.rgbaAt(bc, br);
      if (rgba && !probeView) std::copy(rgba, rgba + 4, viewColor);
      const bool viewDone = !probeView && frame.tileStep[t] == 1;
      for (int r = br; r < std::min(br + step, r1); ++r)
        for (int c = bc; c < std::min(bc + step, c1); ++c) {
          if (!viewDone) std::copy(viewColor, viewColor + 4, &viewRgba_[staged(c, r)]);
          if (withOverlay) std::copy(heat, heat + 4, &overlayRgba_[staged(c, r)]);
        }
    }
}

void ViewTextures::upload(const ProgressiveFrame& frame, int row, int firstTile, int endTile,
                          bool withOverlay) {
  const int c0 = firstTile * frame.tileSize, c1 = std::min(endTile * frame.tileSize, frame.width);
  const int r0 = row * frame.tileSize, r1 = std::min(r0 + frame.tileSize, frame.height);
  image_.upload(viewRgba_.data(), c0, r0, c1, r1);
  if (withOverlay) overlay_.upload(overlayRgba_.data(), c0, r0, c1, r1);
}

void ViewTextures::refresh(const ProgressiveFrame& frame, View view, Overlay overlay,
                           const FalseColorScales& scales,
                           std::chrono::steady_clock::duration budget) {
  const auto start = std::chrono::steady_clock::now();
  const bool probeView = needsProbes(view);
  const bool withOverlay = overlay != Overlay::None && !frame.probes.empty();
  // Until the frame holds a render for this view, the tiles wait.
  if (probeView ? frame.probes.empty() : frame.rgba.empty()) return;
  // A row of tiles at a time; the stale tiles of a run go up in one call.
  for (int row = 0; row < frame.tilesY; ++row) {
    if (std::chrono::steady_clock::now() - start > budget) return;
    for (int col = 0; col < frame.tilesX;) {
      const int first = row * frame.tilesX + col;
      if (!stale_[first]) {
        ++col;
        continue;
      }
      int end = col;
      for (; end < frame.tilesX && stale_[row * frame.tilesX + end]; ++end) {
        colorTile(frame, row * frame.tilesX + end, view, overlay, scales);
        stale_[row * frame.tilesX + end] = 0;
      }
      upload(frame, row, col, end, withOverlay);
      col = end;
    }
  }
}

}  // namespace meshtrace::viewer
