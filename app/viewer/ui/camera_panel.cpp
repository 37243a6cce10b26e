// The camera: its .sce line (print, copy), reset, and how the mouse moves it.
#include <imgui.h>

#include "viewer/model/camera_control.h"
#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

void drawCameraPanel(ViewerState& state) {
  if (!state.session.loaded()) return;
  const std::string line = cameraLine(state.session.camera());
  ImGui::TextWrapped("%s", line.c_str());
  if (ImGui::Button("Copy")) copyCameraLine(state);
  ImGui::SameLine();
  if (ImGui::Button("Print")) std::printf("%s\n", line.c_str());
  ImGui::SameLine();
  if (ImGui::Button("Reset camera")) state.session.resetCamera();
  ImGui::TextDisabled("Left drag orbits, right drag pans, Shift + wheel moves closer.");
}

}  // namespace meshtrace::viewer
