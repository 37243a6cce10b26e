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
#include "viewer/model/disposer.h"
#include "viewer/model/heat_scales.h"
#include "viewer/model/render_scene.h"
#include "viewer/model/views.h"
#include "viewer/ui/view_textures.h"

namespace meshtrace::viewer {

struct RenderWish {
  View view = View::Color;
  Overlay overlay = Overlay::None;
  int extraSamples = 0;
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
  // thread's: a frame need not wait for them (background_priority.h says
  // why the render is no slower for it against other programs). `wake`
  // runs on a render thread when the first image, the exact image or the
  // whole render is done; the passes between show with the next frame.
  RenderDisplay(int threads, int workerNice, std::function<void()> wake = {});

  // Starts a new render if the scene, the camera or the wish changed since
  // the last call (a null scene stops the render); returns true if it did.
  // `requestedAt`: when the user asked for what changed, the start of the
  // figures in shownTimes(); a render that follows a preview asked for at
  // the same moment keeps the preview's first image time.
  bool sync(std::shared_ptr<const RenderScene> scene, const CameraSpec& camera,
            const RenderWish& wish, Clock::time_point requestedAt);
  // Stops the render and forgets its image.
  void stop();
  // The next sync starts the render again from its first pass.
  void restart() { started_ = false; }
  // While the UI thread builds and draws a frame, one render thread waits
  // (when the threads fill the cores): the frame gets a core of its own
  // instead of a third of two.
  void frameBegins() { renderer_.pauseWorkers(paused_ ? threads() : coreForFrames_); }
  void frameEnds() { renderer_.pauseWorkers(paused_ ? threads() : 0); }
  // Paused, every render thread waits between pixels, this render's and
  // the next's, until resumed.
  void setPaused(bool paused) {
    paused_ = paused;
    renderer_.pauseWorkers(paused_ ? threads() : 0);
  }
  bool paused() const { return paused_; }
  // Pulls finished tiles and updates the textures, within a few ms (what
  // does not fit waits for the next call); `deviation` supplies the
  // deviation data (the depth and cost ranges are tracked here).
  void update(const FalseColorScales& deviation);
  // Lets go of `object` off the UI thread (render_display.cpp's own
  // replaced scenes go there too).
  void dispose(std::shared_ptr<const void> object) { disposer_.dispose(std::move(object)); }
  // Recolour everything on the next update (e.g. new deviation data).
  void invalidate() { dirtyAll_ = true; }

  const gl::Texture& image() const { return textures_.image(); }
  const gl::Texture& overlay() const { return textures_.overlay(); }
  const ProgressiveFrame& frame() const { return frame_; }
  ProgressiveStatus status() const { return renderer_.status(); }
  // The status taken just before the last update(): the frame holds at
  // least what it says is done.
  const ProgressiveStatus& frameStatus() const { return frameStatus_; }
  // The textures hold an image of the current scene (its first image
  // reached them): false from stop() until then, so that an opening scene
  // never shows the last one's picture.
  bool showsImage() const { return showsImage_; }
  const ShownTimes& shownTimes() const { return shown_; }
  // A render runs whose coarse pass has not reached the texture yet.
  bool awaitingFirstImage() const { return scene_ && shown_.firstImageMs < 0; }
  // The render has reached its first or its exact image, and the texture
  // not yet, or a moved camera waits for a first image shown: worth a
  // frame at once.
  bool imageWaiting() const;
  bool active() const { return scene_ != nullptr; }
  // The scene of the current render, or null.
  const PreparedScene* prepared() const { return scene_ ? scene_->prepared.get() : nullptr; }
  const std::shared_ptr<const RenderScene>& renderScene() const { return scene_; }
  // Every tile the render has published is in the textures.
  bool texturesCurrent() const { return textures_.current(); }
  // The textures hold the whole of the current render: it had finished
  // when the frame was last copied (the live status may say finished
  // before the copy holds its last tiles), no render started since, and
  // every tile is uploaded.
  bool showsFinishedRender() const {
    return frameStatus_.finished && frameStatus_.job == renderer_.status().job &&
           frame_.job == frameStatus_.job && textures_.current();
  }
  const Camera& camera() const { return camera_; }
  const FalseColorScales& scales() const { return scales_; }
  const RenderWish& wish() const { return wish_; }
  int threads() const { return renderer_.threads(); }
  bool waitUntilFinished(double ms) const { return renderer_.waitUntilFinished(ms); }

  // The colour image as far as it is rendered (RGB, top row first).
  Image8 colorImage() const;

 private:
  void timeShownImages();

  // Lets go of replaced scenes off the UI thread; declared before the
  // renderer, so that the renderer's jobs end first.
  Disposer disposer_;
  ProgressiveRenderer renderer_;
  int coreForFrames_ = 0;  // workers paused during a frame
  bool paused_ = false;
  ProgressiveFrame frame_;
  ProgressiveStatus frameStatus_;
  bool showsImage_ = false;
  std::shared_ptr<const RenderScene> scene_;
  Camera camera_;
  RenderWish wish_;
  Clock::time_point requestedAt_;
  ShownTimes shown_;
  bool started_ = false;
  bool cameraWaiting_ = false;  // a moved camera waits for the render's first image
  bool dirtyAll_ = true;
  FalseColorScales scales_;
  // The ranges are measured as tiles arrive and applied at most every
  // kRescaleEvery while the render runs; a change recolours every tile.
  ScaleTracker tracker_;
  Clock::time_point lastRescale_{};
  ViewTextures textures_;
};

}  // namespace meshtrace::viewer
