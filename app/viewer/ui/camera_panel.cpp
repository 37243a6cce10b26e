// The camera: its .sce line (print, copy), reset, and how the mouse moves it.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <cmath>

#include "viewer/model/camera_control.h"
#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

namespace {
// Named cameras for this scene, kept in the settings (settings.h).
void drawBookmarks(ViewerState& state) {
  const std::filesystem::path& scene = state.session.file();
  ImGui::SetNextItemWidth(-90);
  ImGui::InputTextWithHint("##bookmark", "bookmark name", &state.bookmarkName);
  ImGui::SameLine();
  if (ImGui::Button("Bookmark")) {
    const std::string name =
        state.bookmarkName.empty()
            ? "view " + std::to_string(bookmarksOf(state.settings, scene).size() + 1)
            : state.bookmarkName;
    setBookmark(state.settings, scene, name, cameraLine(state.session.camera()));
    saveSettingsIfKept(state);
    state.bookmarkName.clear();
  }
  std::optional<std::string> removed;
  int id = 0;
  for (const CameraBookmark& b : bookmarksOf(state.settings, scene)) {
    ImGui::PushID(id++);
    if (ImGui::Button(b.name.c_str())) {
      try {
        state.session.setCamera(parseCameraLine(b.cameraLine));
      } catch (const std::exception& e) {
        setMessage(state, "bookmark '" + b.name + "': " + e.what(), true);
      }
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("x")) removed = b.name;
    ImGui::PopID();
  }
  if (removed) {
    removeBookmark(state.settings, scene, *removed);
    saveSettingsIfKept(state);
  }
}
}  // namespace

void drawCameraPanel(ViewerState& state) {
  if (!state.session.loaded()) return;
  const std::string line = cameraLine(state.session.camera());
  ImGui::TextWrapped("%s", line.c_str());
  if (ImGui::Button("Copy")) copyCameraLine(state);
  ImGui::SameLine();
  if (ImGui::Button("Print")) std::printf("%s\n", line.c_str());
  ImGui::SameLine();
  if (ImGui::Button("Paste")) pasteCameraLine(state);
  ImGui::SameLine();
  if (ImGui::Button("Reset camera")) state.session.resetCamera();
  CameraSpec camera = state.session.camera();
  float fov = static_cast<float>(camera.fovyDegrees);
  ImGui::SetNextItemWidth(-130);
  if (ImGui::SliderFloat("field of view", &fov, 1.0f, 170.0f, "%.1f deg")) {
    // Tenths of a degree, as the slider shows: the camera line stays short.
    camera.fovyDegrees = std::round(fov * 10.0) / 10.0;
    state.session.setCamera(camera);
  }
  drawBookmarks(state);
  ImGui::TextDisabled("Left drag orbits, right drag pans, Shift + wheel moves closer.");
}

}  // namespace meshtrace::viewer
