// The camera: its .sce line (print, copy), reset, and how the mouse moves it.
#include <imgui.h>

#include <cmath>

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
  ImGui::TextDisabled("Left drag orbits, right drag pans, Shift + wheel moves closer.");
}

}  // namespace meshtrace::viewer
