// Live reload: the open scene's file and its meshes are watched; a change
// reads the scene again through the background opening, keeping what the
// user changed (session.h), and a broken file leaves the last good scene
// and image shown with the error beside them.
#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

void watchOpenScene(ViewerState& state) {
  const SceneSession& session = state.session;
  std::vector<std::filesystem::path> files{session.file()};
  if (session.loaded())
    for (const Mesh& m : session.scene().meshes) files.push_back(m.file());
  else  // a failed opening or reload: the meshes last read may be the cause
    for (const std::filesystem::path& f : state.reload.watch.files()) files.push_back(f);
  state.reload.watch.watch(files);
}

void reloadScene(ViewerState& state) {
  if (state.session.file().empty() || state.session.opening()) return;
  if (!state.session.loaded()) {  // nothing to keep: open it anew
    openScene(state, state.session.file());
    return;
  }
  SceneRequests& scenes = state.scenes;
  state.reload.pending = true;
  scenes.failure.clear();
  scenes.trace = state.trace;
  scenes.pipeline->open(state.session.file(), state.trace, ++scenes.lastId);
}

void checkWatchedFiles(ViewerState& state) {
  if (state.reload.pending || state.session.opening()) return;
  const std::vector<std::filesystem::path> changed = state.reload.watch.changed();
  if (changed.empty()) return;
  state.reload.changed = changed.front().filename().string();
  reloadScene(state);
}

void reloaded(ViewerState& state, const LoadedScene& loaded) {
  state.reload.pending = false;
  state.session.adoptReload(loaded);
  const CameraSpec& c = state.session.camera();
  if (state.pinned && (state.pinned->x >= c.width || state.pinned->y >= c.height))
    state.pinned.reset();
  if (state.hover && (state.hover->x >= c.width || state.hover->y >= c.height)) state.hover.reset();
  state.inspections.entries.clear();
  state.crosscheck.task->cancel();
  state.crosscheck.reports.assign(state.session.meshes().size(), std::nullopt);
  watchOpenScene(state);
  showSceneWarnings(state, "reloaded " + state.session.file().string() + " (" +
                               state.reload.changed + " changed)");
}

void reloadFailed(ViewerState& state, const std::string& error) {
  state.reload.pending = false;
  state.session.failReload(error);
  setMessage(state, "reload failed, the last good scene is kept: " + error, true);
}

}  // namespace meshtrace::viewer
