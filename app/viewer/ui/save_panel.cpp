// Saving the render as PNG (or EXR, by the name's extension), its layers
// as EXR, and the whole window as a screenshot.
#include <imgui.h>
#include <imgui_stdlib.h>

#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

void drawSavePanel(ViewerState& state, RenderDisplay& display) {
  ImGui::SetNextItemWidth(-130);
  ImGui::InputText("##render", &state.savePath);
  ImGui::SameLine();
  ImGui::BeginDisabled(display.frame().width == 0);
  if (ImGui::Button("Save render")) save(state, display, SaveKind::Render, Existing::Refuse);
  ImGui::EndDisabled();
  ImGui::SetNextItemWidth(-130);
  ImGui::InputText("##layers", &state.layersPath);
  ImGui::SameLine();
  ImGui::BeginDisabled(display.frame().width == 0);
  if (ImGui::Button("Save layers")) save(state, display, SaveKind::Layers, Existing::Refuse);
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("One EXR of the colour, depth, normals, hit points, ids and cost.");
  ImGui::SetNextItemWidth(-130);
  ImGui::InputText("##window", &state.screenshotPath);
  ImGui::SameLine();
  if (ImGui::Button("Save window")) save(state, display, SaveKind::Window, Existing::Refuse);
}

}  // namespace meshtrace::viewer
