#include <imgui.h>

#include <algorithm>
#include <utility>

#include "meshtrace/io/reference_lookup.h"
#include "viewer/model/camera_control.h"
#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

void setMessage(ViewerState& state, const std::string& message, bool error) {
  state.message = message;
  state.messageIsError = error;
  state.messageIsWarning = false;
  std::fprintf(error ? stderr : stdout, "%s\n", message.c_str());
}

void showSceneWarnings(ViewerState& state, const std::string& before) {
  const std::vector<std::string>& warnings = state.session.warnings();
  if (warnings.empty()) {
    if (!before.empty()) setMessage(state, before, false);
    return;
  }
  std::string text = before.empty() ? "" : before + "; ";
  for (std::size_t i = 0; i < warnings.size(); ++i)
    text += (i ? "; warning: " : "warning: ") + warnings[i];
  state.message = text;
  state.messageIsError = false;
  state.messageIsWarning = true;
  std::fprintf(stderr, "%s\n", text.c_str());
}

void rememberScene(ViewerState& state) {
  if (state.settingsPath.empty()) return;
  addRecent(state.settings, state.session.file());
  saveSettingsIfKept(state);
}

void saveSettingsIfKept(ViewerState& state) {
  if (!state.settingsPath.empty()) state.settingsWriter.save(state.settings, state.settingsPath);
}

void openScene(ViewerState& state, const std::filesystem::path& file) {
  state.timing.openedAt = state.timing.actionTime();
  state.retired.push_back(state.session.beginOpening(file));
  state.reload.pending = false;
  SceneRequests& scenes = state.scenes;
  state.retired.push_back(std::exchange(scenes.preview, nullptr));
  state.retired.push_back(std::exchange(scenes.render, nullptr));
  scenes.failure.clear();
  scenes.trace = state.trace;
  scenes.pipeline->open(file, state.trace, ++scenes.lastId);
  state.hover.reset();
  state.pinned.reset();
  state.observer.camera.reset();
  state.inspections.entries.clear();
  state.crosscheck.task->cancel();
  state.crosscheck.reports.clear();
  state.timing.loadMs = 0.0;
  state.timing.renderingFrames.clear();
  state.timing.frames = 0;
  ReferenceState& ref = state.reference;
  ref.task->cancel();
  ref.path.clear();
  ref.image = Image8{};
  ref.error.clear();
  ref.errors.clear();
  ref.current.reset();
  if (const auto found = findReference(file)) ref.path = *found;
  ref.pathField = ref.path.string();
  proposeSavePaths(state, file);
  // A load error shows in place of the image; the message line stays free.
  state.message.clear();
}

void addFolder(ViewerState& state, const std::filesystem::path& dir, const std::string& title) {
  std::error_code ec;
  const auto canonical = std::filesystem::weakly_canonical(dir, ec);
  for (const SceneFolder& f : state.folders)
    if (f.root == canonical) return;
  state.folders.push_back(scanFolder(ec ? dir : canonical, title));
}

void openPath(ViewerState& state, const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    addFolder(state, path, path.filename().string());
  } else if (path.extension() == ".sce" || isBareMesh(path)) {
    openScene(state, path);
  } else {
    setMessage(state, "not a .sce file, a mesh file or a folder: " + path.string(), true);
  }
}

void copyCameraLine(ViewerState& state) {
  if (!state.session.loaded()) return;
  const std::string line = cameraLine(state.session.camera());
  ImGui::SetClipboardText(line.c_str());
  setMessage(state, "copied: " + line, false);
}

void pasteCameraLine(ViewerState& state) {
  if (!state.session.loaded()) return;
  const char* text = ImGui::GetClipboardText();
  try {
    state.session.setCamera(parseCameraLine(text ? text : ""));
    setMessage(state, "pasted: " + cameraLine(state.session.camera()), false);
  } catch (const std::exception& e) {
    setMessage(state, std::string("not a camera line: ") + e.what(), true);
  }
}

std::optional<std::size_t> findMesh(const SceneSession& session, const std::string& name) {
  const auto& meshes = session.meshes();
  for (std::size_t i = 0; i < meshes.size(); ++i)
    if (meshes[i].name == name) return i;
  if (!name.empty() && std::all_of(name.begin(), name.end(), ::isdigit)) {
    const std::size_t i = std::stoul(name);
    if (i < meshes.size()) return i;
  }
  return std::nullopt;
}

std::string meshNames(const SceneSession& session) {
  if (session.meshes().empty()) return " (it has no meshes)";
  std::string names;
  for (std::size_t i = 0; i < session.meshes().size(); ++i)
    names += (i ? ", " : "") + session.meshes()[i].name;
  return " (its meshes: " + names + ")";
}

std::string describeObject(const ViewerState& state, const RenderDisplay& display,
                           const PrimitiveRef& ref) {
  std::string s = std::string(toString(ref.kind)) + " #" + std::to_string(ref.object);
  const auto& scene = display.renderScene();
  if (ref.kind == ObjectKind::Mesh && scene && ref.object < scene->sceneMesh.size()) {
    const std::uint32_t m = scene->sceneMesh[ref.object];
    if (m < state.session.meshes().size())
      s = "mesh '" + state.session.meshes()[m].name + "' #" + std::to_string(m);
  }
  return s;
}

}  // namespace meshtrace::viewer
