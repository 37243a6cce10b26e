#pragma once
// What both platforms do around the app each frame: set up Dear ImGui's
// renderer, draw a frame, serve screenshot requests, pace and time frames.
#include <chrono>
#include <string>

#include "../ui/viewer_app.h"

namespace meshtrace::viewer {

// Creates the ImGui context (no .ini file) and the OpenGL3 renderer; the
// GL functions must be loaded.
void initImGui();
void shutdownImGui();
// Draws one throwaway frame: the font atlas is built and the shaders are
// compiled (slow in a software rasteriser) before any render competes.
void warmUp(int width, int height);

// Runs app.frame() between NewFrame and Render, draws it into the current
// framebuffer (width x height) and serves a screenshot request. Returns the
// frame's duration in ms (GL finished).
double drawFrame(ViewerApp& app, int width, int height);

// Writes the current framebuffer to `path` as PNG; false (and a message) on failure.
bool saveFramebuffer(ViewerApp& app, const std::string& path, int width, int height);

}  // namespace meshtrace::viewer
