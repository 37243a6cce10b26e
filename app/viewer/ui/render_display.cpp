#include "viewer/ui/render_display.h"

#include <sys/resource.h>
#include <unistd.h>

#include <thread>

namespace meshtrace::viewer {

namespace {
bool sameSettings(const RenderWish& a, const RenderWish& b) {
  const bool colorA = !needsProbes(a.view) || a.overlay != Overlay::None;
  const bool colorB = !needsProbes(b.view) || b.overlay != Overlay::None;
  const bool probesA = needsProbes(a.view) || needsProbes(a.overlay);
  const bool probesB = needsProbes(b.view) || needsProbes(b.overlay);
  return colorA == colorB && probesA == probesB && a.extraSamples == b.extraSamples &&
         a.trace.accel == b.trace.accel;
}

// Colouring and uploading tiles may take this long per frame, so that a
// frame stays well inside its budget when many tiles arrive at once.
constexpr auto kTextureBudget = std::chrono::milliseconds(4);
constexpr auto kRescaleEvery = std::chrono::milliseconds(250);

FalseColorScales freshRanges() {
  FalseColorScales s;
  s.depthNear = -1.0;
  s.depthFar = 0.0;
  s.costMax = 1.0;
  return s;
}
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

bool RenderDisplay::sync(SceneSession& session, const RenderWish& wish,
                         Clock::time_point requestedAt) {
  const bool changed = !started_ || session.revision() != revision_ || !sameSettings(wish, wish_);
  if (wish.view != wish_.view || wish.overlay != wish_.overlay) dirtyAll_ = true;
  wish_ = wish;
  if (!changed) return false;
  started_ = true;
  revision_ = session.revision();
  if (!session.loaded()) {
    stop();
    return false;
  }
  prepared_ = session.prepared(wish.trace);
  camera_ = Camera(session.camera());
  ProgressiveSettings settings;
  settings.extraSamples = wish.extraSamples;
  settings.probes = needsProbes(wish.view) || needsProbes(wish.overlay);
  settings.color = !needsProbes(wish.view) || wish.overlay != Overlay::None;
  renderer_.start(prepared_, camera_, settings);
  requestedAt_ = requestedAt;
  shown_ = ShownTimes{};
  return true;
}

void RenderDisplay::stop() {
  renderer_.cancel();
  prepared_.reset();
  frame_ = ProgressiveFrame{};
}

bool RenderDisplay::trackScales(const std::vector<int>& tiles) {
  const FalseColorScales before = scales_;
  for (int t : tiles) {
    const int c0 = (t % frame_.tilesX) * frame_.tileSize,
              r0 = (t / frame_.tilesX) * frame_.tileSize;
    const int step = frame_.tileStep[t];
    for (int r = r0; r < std::min(r0 + frame_.tileSize, frame_.height); r += step)
      for (int c = c0; c < std::min(c0 + frame_.tileSize, frame_.width); c += step) {
        const PixelProbe& p = frame_.probes[static_cast<std::size_t>(r) * frame_.width + c];
        scales_.costMax = std::max(scales_.costMax, double(p.cost));
        if (!p.hit()) continue;
        if (scales_.depthNear < 0 || p.depth < scales_.depthNear) scales_.depthNear = p.depth;
        scales_.depthFar = std::max(scales_.depthFar, double(p.depth));
      }
  }
  const bool depth = wish_.view == View::Depth &&
                     (before.depthNear != scales_.depthNear || before.depthFar != scales_.depthFar);
  const bool cost = (wish_.view == View::BvhCost || wish_.overlay == Overlay::BvhCost) &&
                    before.costMax != scales_.costMax;
  return depth || cost;
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
  if (allExact) shown_.exactImageMs = ms;
}

bool RenderDisplay::imageWaiting() const {
  if (!prepared_) return false;
  const ProgressiveStatus s = renderer_.status();
  return (s.coarseDone && shown_.firstImageMs < 0) || (s.exactDone && shown_.exactImageMs < 0);
}

void RenderDisplay::update(const FalseColorScales& deviation) {
  if (!prepared_) return;
  const std::uint64_t oldJob = frame_.job;
  const std::vector<int> tiles = renderer_.update(frame_);
  if (frame_.job != oldJob) {
    // The texture still shows the last render; the new one replaces it tile
    // by tile, with ranges measured afresh.
    scales_ = freshRanges();
    rescalePending_ = false;
  }
  if (frame_.width == 0) return;
  scales_.boxMax = std::max<double>(1.0, double(prepared_->scene().meshes.size()));
  scales_.meshDeviation = deviation.meshDeviation;
  scales_.deviationMax = deviation.deviationMax;
  scales_.scene = &prepared_->scene();
  textures_.fit(frame_, wish_.overlay != Overlay::None);
  if (dirtyAll_) {
    dirtyAll_ = false;
    textures_.markAll();
  }
  textures_.markChanged(tiles);
  if (!frame_.probes.empty() && trackScales(tiles)) rescalePending_ = true;
  const Clock::time_point now = Clock::now();
  if (rescalePending_ && (now - lastRescale_ >= kRescaleEvery || renderer_.status().exactDone)) {
    rescalePending_ = false;
    lastRescale_ = now;
    textures_.markTraced(frame_);
  }
  textures_.refresh(frame_, wish_.view, wish_.overlay, scales_, kTextureBudget);
  timeShownImages();
}

Image8 RenderDisplay::colorImage() const {
  Image8 out;
  out.width = frame_.width;
  out.height = frame_.height;
  out.rgb.resize(static_cast<std::size_t>(out.width) * out.height * 3);
  for (int row = 0; row < out.height; ++row)
    for (int col = 0; col < out.width; ++col)
      if (const std::uint8_t* rgba = frame_.rgbaAt(col, row))
        std::copy(rgba, rgba + 3, &out.rgb[(static_cast<std::size_t>(row) * out.width + col) * 3]);
  return out;
}

}  // namespace meshtrace::viewer
