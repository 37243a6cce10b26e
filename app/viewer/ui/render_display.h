#pragma once
// The progressive render as the viewer shows it: starts and restarts the
// background render when the scene, camera or view settings change, pulls
// the finished tiles every frame, turns probes into false colours and keeps
// the textures current.
#include <memory>

#include "../gl/texture.h"
#include "../model/session.h"
#include "../model/views.h"
#include "meshtrace/image.h"
#include "meshtrace/progressive.h"

namespace meshtrace::viewer {

struct RenderWish {
  View view = View::Color;
  Overlay overlay = Overlay::None;
  int extraSamples = 0;
  TraceOptions trace;
};

class RenderDisplay {
 public:
  // `workerNice` > 0 lowers the render threads' priority below the UI
  // thread's: smoother frames on a busy machine, a slower render.
  RenderDisplay(int threads, int workerNice);

  // Starts a new render if the session or the wish changed since the last
  // call; returns true if it did.
  bool sync(SceneSession& session, const RenderWish& wish);
  void stop();
  // Pulls finished tiles and updates the textures; `scales` supplies the
  // deviation data (the depth and cost ranges are tracked here).
  void update(const FalseColorScales& deviation);
  // Recolour everything on the next update (e.g. new deviation data).
  void invalidate() { dirtyAll_ = true; }

  const gl::Texture& image() const { return image_; }
  const gl::Texture& overlay() const { return overlay_; }
  const ProgressiveFrame& frame() const { return frame_; }
  ProgressiveStatus status() const { return renderer_.status(); }
  bool active() const { return prepared_ != nullptr; }
  const std::shared_ptr<const PreparedScene>& prepared() const { return prepared_; }
  const Camera& camera() const { return camera_; }
  const FalseColorScales& scales() const { return scales_; }
  const RenderWish& wish() const { return wish_; }
  int threads() const { return renderer_.threads(); }
  bool waitUntilFinished(double ms) const { return renderer_.waitUntilFinished(ms); }

  // The colour image as far as it is rendered (RGB, top row first).
  Image8 colorImage() const;

 private:
  void recolor(int c0, int r0, int c1, int r1);
  bool trackScales(const std::vector<int>& tiles);

  ProgressiveRenderer renderer_;
  ProgressiveFrame frame_;
  std::shared_ptr<const PreparedScene> prepared_;
  Camera camera_;
  std::uint64_t revision_ = ~0ull;
  RenderWish wish_;
  bool started_ = false;
  bool dirtyAll_ = true;
  FalseColorScales scales_;
  std::vector<std::uint8_t> viewRgba_, overlayRgba_;
  gl::Texture image_, overlay_;
};

}  // namespace meshtrace::viewer
