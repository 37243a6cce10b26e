#include "render_display.h"

#include <sys/resource.h>
#include <unistd.h>

#include "meshtrace/inspect_colors.h"

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

void putColor(std::uint8_t* out, const Color& c) {
  for (int k = 0; k < 3; ++k) out[k] = toByte(c[k]);
  out[3] = 255;
}
}  // namespace

RenderDisplay::RenderDisplay(int threads, int workerNice)
    : renderer_(threads, [workerNice] {
        // Linux gives each thread its own nice value.
        if (workerNice > 0) setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), workerNice);
      }) {}

bool RenderDisplay::sync(SceneSession& session, const RenderWish& wish) {
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
  dirtyAll_ = true;
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
  return before.depthNear != scales_.depthNear || before.depthFar != scales_.depthFar ||
         before.costMax != scales_.costMax;
}

void RenderDisplay::update(const FalseColorScales& deviation) {
  if (!prepared_) return;
  const std::uint64_t oldJob = frame_.job;
  const std::vector<int> tiles = renderer_.update(frame_);
  if (frame_.job != oldJob) {
    dirtyAll_ = true;
    scales_ = FalseColorScales{};
    scales_.depthNear = -1.0;
    scales_.depthFar = 0.0;
    scales_.costMax = 1.0;
  }
  if (frame_.width == 0) return;
  scales_.boxMax = std::max<double>(1.0, double(prepared_->scene().meshes.size()));
  scales_.meshDeviation = deviation.meshDeviation;
  scales_.deviationMax = deviation.deviationMax;
  scales_.scene = &prepared_->scene();
  if (!frame_.probes.empty() && trackScales(tiles)) dirtyAll_ = true;
  const std::size_t bytes = static_cast<std::size_t>(frame_.width) * frame_.height * 4;
  if (viewRgba_.size() != bytes) {
    viewRgba_.assign(bytes, 0);
    overlayRgba_.assign(bytes, 0);
    dirtyAll_ = true;
  }
  image_.resize(frame_.width, frame_.height);
  if (wish_.overlay != Overlay::None) overlay_.resize(frame_.width, frame_.height);
  if (dirtyAll_) {
    dirtyAll_ = false;
    recolor(0, 0, frame_.width, frame_.height);
    return;
  }
  if (tiles.empty()) return;
  int c0 = frame_.width, r0 = frame_.height, c1 = 0, r1 = 0;
  for (int t : tiles) {
    const int tc = (t % frame_.tilesX) * frame_.tileSize,
              tr = (t / frame_.tilesX) * frame_.tileSize;
    c0 = std::min(c0, tc);
    r0 = std::min(r0, tr);
    c1 = std::max(c1, std::min(tc + frame_.tileSize, frame_.width));
    r1 = std::max(r1, std::min(tr + frame_.tileSize, frame_.height));
  }
  recolor(c0, r0, c1, r1);
}

void RenderDisplay::recolor(int c0, int r0, int c1, int r1) {
  const bool probeView = needsProbes(wish_.view);
  const bool withOverlay = wish_.overlay != Overlay::None && !frame_.probes.empty();
  if (probeView || withOverlay) {
    for (int r = r0; r < r1; ++r) {
      for (int c = c0; c < c1; ++c) {
        const std::size_t i = (static_cast<std::size_t>(r) * frame_.width + c) * 4;
        const PixelProbe* p = frame_.probeAt(c, r);
        if (probeView) {
          if (p)
            putColor(&viewRgba_[i], falseColor(wish_.view, *p, scales_));
          else
            viewRgba_[i + 3] = 0;
        }
        if (withOverlay) {
          if (p)
            putColor(&overlayRgba_[i], heatColor(overlayValue(wish_.overlay, *p, scales_)));
          else
            overlayRgba_[i + 3] = 0;
        }
      }
    }
  }
  image_.upload(probeView ? viewRgba_.data() : frame_.rgba.data(), c0, r0, c1, r1);
  if (withOverlay) overlay_.upload(overlayRgba_.data(), c0, r0, c1, r1);
}

Image8 RenderDisplay::colorImage() const {
  Image8 out;
  out.width = frame_.width;
  out.height = frame_.height;
  out.rgb.resize(static_cast<std::size_t>(out.width) * out.height * 3);
  for (std::size_t i = 0, n = out.rgb.size() / 3; i < n && !frame_.rgba.empty(); ++i)
    for (int k = 0; k < 3; ++k) out.rgb[i * 3 + k] = frame_.rgba[i * 4 + k];
  return out;
}

}  // namespace meshtrace::viewer
