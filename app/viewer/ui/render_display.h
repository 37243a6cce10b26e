#pragma once
// The progressive render as the viewer shows it: starts and restarts the
// background render when the scene, camera or view settings change, pulls
// the finished tiles every frame into the textures (view_textures.h), tracks
// the ranges of the false colours and times when the images are shown.
#include <chrono>
#include <functional>
#include <memory>

#include "meshtrace/io/image.h"
#include "meshtrace/render/progressive.h"
#include "viewer/gl/texture.h"
#include "viewer/model/session.h"
#include "viewer/model/views.h"
#include "viewer/ui/view_textures.h"

namespace meshtrace::viewer {

struct RenderWish {
  View view = View::Color;
  Overlay overlay = Overlay::None;
  int extraSamples = 0;
  TraceOptions trace;
};

// How long after the user asked for the current render (opened the scene,
// moved the camera, ...) its images reached the texture; -1 until they did.
struct ShownTimes {
  double firstImageMs = -1.0;  // every tile holds at least the coarse pass
  double exactImageMs = -1.0;  // every pixel traced exactly
};

class RenderDisplay {
 public:
  using Clock = std::chrono::steady_clock;

  // `workerNice` > 0 lowers the render threads' priority below the UI
  // thread's: smoother frames on a busy machine, a slower render. `wake`
  // runs on a render thread when the first image, the exact image or the
  // whole render is done; the passes between show with the next frame.
  RenderDisplay(int threads, int workerNice, std::function<void()> wake = {});

  // Starts a new render if the session or the wish changed since the last
  // call; returns true if it did. `requestedAt`: when the user asked for
  // what changed, the start of the figures in shownTimes().
  bool sync(SceneSession& session, const RenderWish& wish, Clock::time_point requestedAt);
  void stop();
  // While the UI thread builds and draws a frame, one render thread waits
  // (when the threads fill the cores): the frame gets a core of its own
  // instead of a third of two.
  void frameBegins() { renderer_.pauseWorkers(coreForFrames_); }
  void frameEnds() { renderer_.pauseWorkers(0); }
  // Pulls finished tiles and updates the textures, within a few ms (what
  // does not fit waits for the next call); `deviation` supplies the
  // deviation data (the depth and cost ranges are tracked here).
  void update(const FalseColorScales& deviation);
  // Recolour everything on the next update (e.g. new deviation data).
  void invalidate() { dirtyAll_ = true; }

  const gl::Texture& image() const { return textures_.image(); }
  const gl::Texture& overlay() const { return textures_.overlay(); }
  const ProgressiveFrame& frame() const { return frame_; }
  ProgressiveStatus status() const { return renderer_.status(); }
  const ShownTimes& shownTimes() const { return shown_; }
  // A render runs whose coarse pass has not reached the texture yet.
  bool awaitingFirstImage() const { return prepared_ && shown_.firstImageMs < 0; }
  // The render has reached its first or its exact image, and the texture
  // not yet: worth a frame at once.
  bool imageWaiting() const;
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
  // Widens the depth and cost ranges by `tiles`; true if the current view
  // or overlay colours by a range that changed.
  bool trackScales(const std::vector<int>& tiles);
  void timeShownImages();

  ProgressiveRenderer renderer_;
  int coreForFrames_ = 0;  // workers paused during a frame
  ProgressiveFrame frame_;
  std::shared_ptr<const PreparedScene> prepared_;
  Camera camera_;
  std::uint64_t revision_ = ~0ull;
  RenderWish wish_;
  Clock::time_point requestedAt_;
  ShownTimes shown_;
  bool started_ = false;
  bool dirtyAll_ = true;
  FalseColorScales scales_;
  // The ranges changed since the traced tiles were coloured: recolour them
  // all, at most every kRescaleEvery while the render runs.
  bool rescalePending_ = false;
  Clock::time_point lastRescale_{};
  ViewTextures textures_;
};

}  // namespace meshtrace::viewer
