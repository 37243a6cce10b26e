#pragma once
// The viewer's shell: applies the command line, lays out the three columns
// (scenes and objects, the image, the details) and runs one frame's logic.
// Platform code (a GLFW window or an OSMesa buffer) drives it between
// ImGui::NewFrame and ImGui::Render.
#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "viewer/ui/render_display.h"
#include "viewer/ui/state.h"

namespace meshtrace::viewer {

class ViewerApp {
 public:
  using Clock = std::chrono::steady_clock;

  // `wake` runs on a render thread when the render reaches its first image,
  // its exact image or its end: a platform waiting for input should wake up
  // and draw a frame.
  ViewerApp(const ViewerOptions& options, const std::filesystem::path& executable,
            std::function<void()> wake = {});

  // One frame's logic, between ImGui::NewFrame and ImGui::Render; the
  // user's input for it was taken at `inputAt`.
  void frame(Clock::time_point inputAt);
  // False for a frame built while a scene just opened waits for its first
  // image (for at most kOpeningWaitMs): drawing it would show an empty image
  // and hold the first image back by the time the draw takes.
  bool shouldPresent() const;
  // Called after each frame with its duration, from taking the input to
  // the frame on screen (or built, when not presented); true if it counts
  // as drawn while rendering.
  bool frameDone(double ms);
  void drop(const std::vector<std::string>& paths);

  // True when a scene is shown and its render (with the AA samples asked
  // for) is complete, or when there is nothing to render.
  bool idle() const;
  // How long the platform may wait for input before the next frame, given
  // when the last frame took its input (input during the wait ends it at
  // once): not at all when the render has an image the texture lacks (its
  // first or its exact one); until the first image when a scene was just
  // opened; a 60th of a second for kFramesAfterInput frames after input
  // (what a click changes shows a frame later); a 10th while the render
  // runs unattended (each frame costs the render a core for its duration,
  // and the first and the exact image end the wait anyway); a 4th when idle.
  double waitBeforeNextFrameMs(Clock::time_point lastFrameInput) const;
  std::string takeScreenshotRequest();
  void printStats() const;

  ViewerState& state() { return state_; }
  RenderDisplay& display() { return display_; }

  static constexpr double kOpeningWaitMs = 100.0;
  static constexpr int kFramesAfterInput = 2;

 private:
  void applyOptions();
  void sync();
  // A scene was just opened (less than kOpeningWaitMs ago) and its first
  // image is not in the texture yet.
  bool waitingForOpeningImage() const;
  RenderWish wish() const;

  ViewerState state_;
  RenderDisplay display_;
  int framesSinceInput_ = 0;
  bool renderingAtFrameStart_ = false;
  // The current render was started by opening its scene, at this time.
  std::optional<Clock::time_point> openingJobAt_;
};

}  // namespace meshtrace::viewer
