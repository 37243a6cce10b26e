#pragma once
// What both platforms do around the app each frame: set up Dear ImGui's
// renderer, build and draw frames paced by the app, serve screenshot
// requests and time the frames.
#include <functional>
#include <string>
#include <utility>

#include "viewer/platform/wake_flag.h"
#include "viewer/ui/viewer_app.h"

namespace meshtrace::viewer {

// Creates the ImGui context (no .ini file) and the OpenGL3 renderer; the
// GL functions must be loaded.
void initImGui();
void shutdownImGui();
// Draws one throwaway frame, before the window is shown and before any
// render competes: the font atlas is built and every shader the frames
// need is compiled (slow in a software rasteriser without its shader
// cache). Returns how long it took, in ms.
double warmUp(int width, int height);

// Draws the frame last built into the current framebuffer (width x height),
// waits for GL to finish and serves a screenshot request.
void drawFrame(ViewerApp& app, int width, int height);

// Writes the current framebuffer to `path` as PNG; false (and a message) on failure.
bool saveFramebuffer(ViewerApp& app, const std::string& path, int width, int height);

// What a platform does for runFrames.
struct FrameHost {
  std::function<bool()> keepRunning;
  // Waits up to `ms` for input or a wake-up (returning at once if one is
  // pending) and hands the input to ImGui.
  std::function<void(double ms)> waitForInput;
  // Starts an ImGui frame on the platform's side; returns the framebuffer size.
  std::function<std::pair<int, int>()> beginFrame;
  std::function<void()> present;  // shows the drawn frame (swaps buffers)
};

// Runs frames until host.keepRunning() is false: waits as long as the app
// allows (input, and the render reaching an image, end the wait), builds the
// frame, draws and presents it unless the app says it is not worth it, and
// reports its duration to the app. Frames come at most 60 a second: after
// a frame, the loop pauses until 1/60 s from its start, unless `handedOver`
// is raised (the app's wake-up raises it when background work hands
// something over: a loaded scene, a preview, a render's first image), so
// that a hand-over is met by a frame at once rather than after the rest
// of the pause.
void runFrames(ViewerApp& app, const FrameHost& host, WakeFlag& handedOver);

}  // namespace meshtrace::viewer
