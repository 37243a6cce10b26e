#pragma once
// Files dropped on the window: GLFW hands over C strings; the app opens
// each path in turn (a .sce or a bare mesh opens, a folder joins the list,
// anything else is refused with a message).
#include "viewer/ui/viewer_app.h"

namespace meshtrace::viewer {

inline void dropPaths(ViewerApp& app, int count, const char** paths) {
  app.drop(std::vector<std::string>(paths, paths + count));
}

}  // namespace meshtrace::viewer
