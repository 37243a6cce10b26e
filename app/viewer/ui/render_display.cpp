#include "viewer/ui/render_display.h"

#include <sys/resource.h>
#include <unistd.h>

#include <thread>
#include <utility>

#include "viewer/model/camera_control.h"
#include "viewer/model/pass_errors.h"

namespace meshtrace::viewer {

namespace {
bool sameSettings(const RenderWish& a, const RenderWish& b) {
  const bool colorA = !needsProbes(a.view) || a.overlay != Overlay::None;
  const bool colorB = !needsProbes(b.view) || b.overlay != Overlay::None;
  const bool probesA = needsProbes(a.view) || needsProbes(a.overlay);
  const bool probesB = needsProbes(b.view) || needsProbes(b.overlay);
  return colorA == colorB && probesA == probesB && a.extraSamples == b.extraSamples;
}

// Colouring and uploading tiles may take this long per frame, so that a
// frame stays well inside its budget when many tiles arrive at once.
constexpr auto kTextureBudget = std::chrono::milliseconds(4);
constexpr auto kRescaleEvery = std::chrono::milliseconds(250);

}  // namespace

RenderDisplay::RenderDisplay(int threads, int workerNice, std::function<void()> wake)
    : renderer_(
          threads,
          [workerNice] {
            // Linux gives each thread its own nice value.
            if (workerNice > 0) setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), workerNice);
          },
          [wake = std::move(wake)](const PassFinished& pass) {
            if (wake && (pass.coarse || pass.exact || pass.last)) wake();
          }) {
  const int cores = static_cast<int>(std::thread::hardware_concurrency());
  coreForFrames_ = renderer_.threads() > 1 && renderer_.threads() >= cores ? 1 : 0;
}

bool RenderDisplay::sync(std::shared_ptr<const RenderScene> scene, const CameraSpec& camera,
                         const RenderWish& wish, Clock::time_point requestedAt) {
  const bool cameraMoved = !sameCamera(camera, camera_.spec());
  const bool changed = !started_ || scene != scene_ || cameraMoved || !sameSettings(wish, wish_);
  if (wish.view != wish_.view || wish.overlay != wish_.overlay) dirtyAll_ = true;
  const bool onlyCameraMoved =
      changed && started_ && scene && scene == scene_ && sameSettings(wish, wish_) && cameraMoved;
  wish_ = wish;
  if (!changed) return false;
  // While the camera moves (an orbit), each camera's render shows its first
  // image before the next camera's starts: restarting on every frame would
  // show only pieces of coarse passes, each camera's replaced by the next's.
  cameraWaiting_ = onlyCameraMoved && shown_.firstImageMs < 0;
  if (cameraWaiting_) return false;
  started_ = true;
  if (!scene) {
    stop();
    return false;
  }
  disposer_.dispose(std::exchange(scene_, std::move(scene)));
  camera_ = Camera(camera);
  ProgressiveSettings settings;
  settings.extraSamples = wish.extraSamples;
  settings.probes = needsProbes(wish.view) || needsProbes(wish.overlay);
  settings.color = !needsProbes(wish.view) || wish.overlay != Overlay::None;
  settings.firstPassOnly = scene_->preview;
  renderer_.start(scene_->prepared, camera_, settings);
  const bool continues = requestedAt == requestedAt_ && shown_.firstImageMs >= 0;
  const double firstImageMs = shown_.firstImageMs;
  requestedAt_ = requestedAt;
  shown_ = ShownTimes{};
  if (continues) shown_.firstImageMs = firstImageMs;
  return true;
}

void RenderDisplay::stop() {
  renderer_.cancel();
  cameraWaiting_ = false;
  disposer_.dispose(std::exchange(scene_, nullptr));
  frame_ = ProgressiveFrame{};
  frameStatus_ = ProgressiveStatus{};
  shown_ = ShownTimes{};
  showsImage_ = false;
}

void RenderDisplay::timeShownImages() {
  if (shown_.exactImageMs >= 0 || frame_.tileStep.empty() || !textures_.current() ||
      frame_.job != renderer_.status().job)
    return;
  bool allTraced = true, allExact = true;
  for (int step : frame_.tileStep) {
    allTraced = allTraced && step > 0;
    allExact = allExact && step == 1;
  }
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - requestedAt_).count();
  if (allTraced && shown_.firstImageMs < 0) shown_.firstImageMs = ms;
  showsImage_ = showsImage_ || allTraced;
  if (allExact) shown_.exactImageMs = ms;
}

bool RenderDisplay::imageWaiting() const {
  if (!scene_) return false;
  const ProgressiveStatus s = renderer_.status();
  return (s.coarseDone && shown_.firstImageMs < 0) || (s.exactDone && shown_.exactImageMs < 0) ||
         (cameraWaiting_ && shown_.firstImageMs >= 0);
}

void RenderDisplay::update(const FalseColorScales& deviation) {
  if (!scene_) return;
  const std::uint64_t oldJob = frame_.job;
  // A render just started (sync) gets its texture size first, while the
  // workers trace its first pass: the frame's copy below then often has
  // that pass already, and shows it in this frame rather than the next.
  textures_.sizeFor(camera_.width(), camera_.height(), wish_.overlay != Overlay::None);
  frameStatus_ = renderer_.status();
  const std::vector<int> tiles = renderer_.update(frame_);
  if (frame_.width == 0) return;
  const bool newJob = frame_.job != oldJob;
  // The texture still shows the last render; the new one replaces it tile
  // by tile, with ranges measured afresh.
  if (newJob) tracker_.reset(frame_.width, frame_.height);
  for (int t : tiles) tracker_.add(frame_, t);
  scales_.meshDeviation = deviation.meshDeviation;
  scales_.deviationMax = deviation.deviationMax;
  scales_.scene = &scene_->prepared->scene();
  textures_.fit(frame_, wish_.overlay != Overlay::None);
  if (dirtyAll_) {
    dirtyAll_ = false;
    textures_.markAll();
  }
  textures_.markChanged(tiles);
  const Clock::time_point now = Clock::now();
  if (newJob || now - lastRescale_ >= kRescaleEvery || renderer_.status().exactDone) {
    lastRescale_ = now;
    if (tracker_.apply(scales_) && usesScales(wish_.view, wish_.overlay))
      textures_.markTraced(frame_);
  }
  textures_.refresh(frame_, wish_.view, wish_.overlay, scales_, kTextureBudget);
  timeShownImages();
}

Image8 RenderDisplay::colorImage() const { return currentImage(frame_); }

}  // namespace meshtrace::viewer
