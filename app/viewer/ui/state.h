#pragma once
// What the viewer's panels share: the options, the scene session, the scene
// list, the view settings, the inspector's pixel, the cross-check results,
// the reference image and the messages to show.
#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "crosscheck/normals_crosscheck.h"
#include "meshtrace/report/image_compare.h"
#include "viewer/gl/texture.h"
#include "viewer/model/folder_browser.h"
#include "viewer/model/frame_stats.h"
#include "viewer/model/options.h"
#include "viewer/model/scene_catalog.h"
#include "viewer/model/session.h"
#include "viewer/model/views.h"
#include "viewer/ui/render_display.h"

namespace meshtrace::viewer {

struct PixelRef {
  int x = 0, y = 0;  // image pixel, y = 0 the bottom row
  bool operator==(const PixelRef&) const = default;
};

struct ReferenceState {
  std::filesystem::path path;  // empty: none
  std::string pathField;
  std::string error;
  Image8 image;
  gl::Texture texture, difference;
  std::vector<std::uint8_t> differenceRgba;
  std::uint64_t differenceFor = ~0ull;  // tile versions summed, to notice changes
  std::vector<float> errorHistory;      // RMSE every 100 ms of the current render
  std::uint64_t historyJob = 0;
  double lastSampleMs = -1.0;
  std::optional<ImageDifference> current;
  bool panelOpen = false;  // the compare panel was drawn last frame
};

struct TimingStats {
  using Clock = std::chrono::steady_clock;
  // When the input of the frame being built was taken: what the user does in
  // it was asked for then. Unset between frames (a drop arrives there).
  std::optional<Clock::time_point> frameInputAt;
  std::optional<Clock::time_point> openedAt;  // a scene was opened, its render not started yet
  double loadMs = 0.0;
  FrameStats renderingFrames;  // frames drawn while a render ran, since the scene was opened
  int frames = 0;

  Clock::time_point actionTime() const { return frameInputAt.value_or(Clock::now()); }
};

struct ViewerState {
  ViewerOptions options;
  std::filesystem::path executable;
  SceneSession session;
  std::vector<SceneFolder> folders;
  std::string pathField;
  std::optional<FolderBrowser> browser;  // open while shown

  View view = View::Color;
  Overlay overlay = Overlay::None;
  float opacity = 0.6f;
  int extraSamples = 0;
  TraceOptions trace;

  std::optional<PixelRef> hover, pinned;

  // Per scene mesh, the OpenMesh cross-check (computed on demand).
  std::vector<std::optional<crosscheck::NormalsReport>> crosschecks;
  double crosscheckMs = 0.0;

  ReferenceState reference;
  TimingStats timing;
  std::string savePath, screenshotPath, sceneSavePath;
  std::string screenshotRequest;  // set by the UI, served after the frame is drawn
  std::string message;            // last action's result
  bool messageIsError = false;
};

}  // namespace meshtrace::viewer
