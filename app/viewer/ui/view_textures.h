#pragma once
// The textures the image view draws, kept current with a progressive frame
// tile by tile: colours, probe views and the heat overlay through their
// false colours, each traced pixel filling the block it stands for. A tile
// not traced yet keeps what the texture showed before (the previous render,
// while the camera moves) instead of going blank. The work per frame is
// bounded: tiles left over wait for the next frame.
#include <chrono>
#include <cstdint>
#include <vector>

#include "meshtrace/render/progressive.h"
#include "viewer/gl/texture.h"
#include "viewer/model/views.h"

namespace meshtrace::viewer {

class ViewTextures {
 public:
  // Sizes the textures for a render of width x height, before its frame
  // has that size: a new GL texture is the costly part of a new size, and
  // is better made while the render's first pass is traced.
  void sizeFor(int width, int height, bool withOverlay);
  // Matches the textures to the frame's size; a new size makes every tile stale.
  void fit(const ProgressiveFrame& frame, bool withOverlay);
  void markChanged(const std::vector<int>& tiles);
  // Every traced tile (after a change of scale), or every tile, blank ones
  // included (after a change of view).
  void markTraced(const ProgressiveFrame& frame);
  void markAll();

  // Colours and uploads stale tiles, in order, until `budget` is spent.
  void refresh(const ProgressiveFrame& frame, View view, Overlay overlay,
               const FalseColorScales& scales, std::chrono::steady_clock::duration budget);
  bool current() const;  // no tile waits

  const gl::Texture& image() const { return image_; }
  const gl::Texture& overlay() const { return overlay_; }

 private:
  void colorTile(const ProgressiveFrame& frame, int tile, View view, Overlay overlay,
                 const FalseColorScales& scales);
  void upload(const ProgressiveFrame& frame, int row, int firstTile, int endTile, bool withOverlay);

  std::vector<char> stale_;  // per tile
  bool blank_ = false;       // a texture was made or resized since the last fit()
  // The colours of one row of tiles on their way to the textures: a row's
  // stale tiles are coloured and uploaded in one go (refresh), so nothing
  // image-sized is kept, and a new image size writes no new memory here.
  std::vector<std::uint8_t> viewRgba_, overlayRgba_;
  gl::Texture image_, overlay_;
};

}  // namespace meshtrace::viewer
