#pragma once
// The two ways to run the viewer: a GLFW window, or headless through OSMesa
// writing a snapshot of the whole window once the render is done.
#include <filesystem>

#include "viewer/model/options.h"

namespace meshtrace::viewer {

int runWindow(const ViewerOptions& options, const std::filesystem::path& executable);
int runHeadless(const ViewerOptions& options, const std::filesystem::path& executable);

}  // namespace meshtrace::viewer
