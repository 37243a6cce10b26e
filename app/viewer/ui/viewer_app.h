#pragma once
// The viewer's shell: applies the command line, lays out the three columns
// (scenes and objects, the image, the details) and runs one frame's logic.
// Platform code (a GLFW window or an OSMesa buffer) drives it between
// ImGui::NewFrame and ImGui::Render.
#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
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
  // False for a frame built while a render just started waits for its
  // first image (for at most kOpeningWaitMs after opening a scene,
  // kRestartWaitMs after any other start, e.g. each step of an orbit):
  // drawing it would show an empty or the last image and hold the first
  // image back by the time the draw takes.
  bool shouldPresent() const;
  // Called after each frame with its duration, from taking the input to
  // the frame on screen (or built, when not presented); true if it counts
  // as drawn while rendering.
  bool frameDone(double ms);
  void drop(const std::vector<std::string>& paths);
  // What a frame does before it draws: takes in the background work's
  // results and starts the render they allow. For tests, without ImGui.
  void poll() { sync(); }

  // True when nothing more will change without input: the scene is shown
  // and its render (with the AA samples asked for) is complete and in the
  // textures, no work runs in the background; or a scene failed to load;
  // or there is no scene.
  bool idle() const;
  // Why a headless run must fail: the scene did not load, the command line
  // named a mesh, pixel or reference the scene lacks, or a render scene
  // could not be made. Empty if nothing went wrong.
  std::vector<std::string> failures() const;
  // How long the platform may wait for input before the next frame, given
  // when the last frame took its input (input during the wait ends it at
  // once): not at all when the render has an image the texture lacks (its
  // first or its exact one); until the first image when a scene was just
  // opened; a 60th of a second for kFramesAfterInput frames after input
  // (what a click changes shows a frame later); a 10th while the render
  // runs unattended or work goes on in the background (each frame costs
  // the render a core for its duration, and the first and the exact image
  // and the background work's results end the wait anyway); a 4th when
  // idle.
  double waitBeforeNextFrameMs(Clock::time_point lastFrameInput) const;
  std::string takeScreenshotRequest();
  // Keep the text each frame shows in state().frameText (for --describe).
  void captureText(bool on) { state_.captureText = on; }
  void printStats() const;

  // Reads the settings from `file` and writes them back there as they
  // change (the real window; tests and headless runs keep none).
  void useSettings(const std::filesystem::path& file);

  ViewerState& state() { return state_; }
  RenderDisplay& display() { return display_; }

  static constexpr double kOpeningWaitMs = 100.0;
  static constexpr double kRestartWaitMs = 30.0;
  static constexpr int kFramesAfterInput = 2;
  static constexpr int kWatchIntervalMs = 200;

 private:
  void applyOptions();
  // Applies the command line's settings that name parts of the scene, once
  // it has loaded; what they name that it lacks goes to optionErrors.
  void applySceneOptions();
  // --bvh-depth names a depth the scene's BVH has (once it is built).
  void checkBvhDepth();
  // A setting of the command line the scene lacks: a message, and a
  // failure of a headless run.
  void refuse(const std::string& problem);
  // --shading and --b-shading: MESH=MODE for each mesh named.
  void applyShading(const char* option, const std::vector<std::pair<std::string, Shading>>& modes);
  // A/B from the command line: once B's render is complete, keeps it and
  // turns to A's settings.
  void advanceAbSetup();
  // The textures show the finished render of the render scene made for the
  // latest request (the settings as they are now).
  bool showsLatestRequest() const;
  // Takes in what the background work finished, and starts what is due.
  void receive();
  void requestRenderScene();
  void runBackgroundWork();
  void sync();
  // The current render started less than kOpeningWaitMs (a scene opened)
  // or kRestartWaitMs ago and its first image is not in the texture yet.
  bool waitingForFirstImage() const;
  RenderWish wish() const;

  ViewerState state_;
  RenderDisplay display_;
  int framesSinceInput_ = 0;
  enum class AbStage { None, RenderingB, Done };
  AbStage abStage_ = AbStage::None;
  bool renderingAtFrameStart_ = false;
  // The height of the Details panel's sections after the inspector, last
  // frame: the inspector's pane leaves them that room.
  float belowInspector_ = 0.0f;
  // The height of the Objects list below the scene list, last frame.
  float belowSceneList_ = 0.0f;
  // Until when a frame waits for the current render's first image.
  std::optional<Clock::time_point> firstImageDeadline_;
};

}  // namespace meshtrace::viewer
