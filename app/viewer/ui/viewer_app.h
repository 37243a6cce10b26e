#pragma once
// The viewer's shell: applies the command line, lays out the three columns
// (scenes and objects, the image, the details) and runs one frame's logic.
// Platform code (a GLFW window or an OSMesa buffer) drives it between
// ImGui::NewFrame and ImGui::Render.
#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "render_display.h"
#include "state.h"

namespace meshtrace::viewer {

class ViewerApp {
 public:
  ViewerApp(const ViewerOptions& options, const std::filesystem::path& executable);

  void frame();
  // Called after each frame is drawn, with its duration.
  void frameDrawn(double ms);
  void drop(const std::vector<std::string>& paths);

  // True when a scene is shown and its render (with the AA samples asked
  // for) is complete, or when there is nothing to render.
  bool idle() const;
  // How long a frame should take: 60 per second while the user interacts,
  // 15 per second while the render runs unattended (the frames would only
  // take time from the render), and no frames at all when idle.
  double framePeriodMs() const;
  std::string takeScreenshotRequest();
  void printStats() const;

  ViewerState& state() { return state_; }
  RenderDisplay& display() { return display_; }

 private:
  void applyOptions();
  void sync();
  RenderWish wish() const;

  ViewerState state_;
  RenderDisplay display_;
  std::chrono::steady_clock::time_point lastInteraction_{};
  std::uint64_t timedJob_ = 0;
  int jobFrames_ = 0;
};

}  // namespace meshtrace::viewer
