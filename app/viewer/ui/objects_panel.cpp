// The object list: per mesh FLAT/PHONG, visibility and counts; reset; save.
#include <imgui.h>
#include <imgui_stdlib.h>

#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

namespace {
void drawObjects(ViewerState& state, RenderDisplay& display) {
  SceneSession& session = state.session;
  if (!session.loaded()) {
    ImGui::TextDisabled("No scene loaded.");
    return;
  }
  {
    const Scene& scene = session.scene();
    ImGui::Text("%zu spheres, %zu planes, %zu cylinders, %zu lights", scene.spheres.size(),
                scene.planes.size(), scene.cylinders.size(), scene.lights.size());
  }
  if (session.meshes().empty()) {
    ImGui::TextDisabled("No meshes.");
    return;
  }
  if (ImGui::BeginTable("meshes", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
    ImGui::TableSetupColumn("show");
    ImGui::TableSetupColumn("mesh", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("shading");
    ImGui::TableSetupColumn("tris / verts");
    ImGui::TableHeadersRow();
    for (std::size_t i = 0; i < session.meshes().size(); ++i) {
      const MeshState& m = session.meshes()[i];
      ImGui::PushID(static_cast<int>(i));
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      bool visible = m.visible;
      if (ImGui::Checkbox("##visible", &visible)) session.setVisible(i, visible);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(m.name.c_str());
      ImGui::TableNextColumn();
      // One button toggles FLAT and PHONG; a changed mode is highlighted.
      const bool changed = m.shading != m.fileShading;
      if (changed) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.6f, 0.35f, 0.1f, 1.0f));
      if (ImGui::Button(toString(m.shading), ImVec2(56, 0)))
        session.setShading(i, m.shading == Shading::Flat ? Shading::Phong : Shading::Flat);
      if (changed) ImGui::PopStyleColor();
      ImGui::TableNextColumn();
      ImGui::Text("%zu / %zu", m.triangles, m.vertices);
      ImGui::PopID();
    }
    ImGui::EndTable();
  }
  ImGui::BeginDisabled(!session.meshesChanged());
  if (ImGui::Button("Reset to the file")) session.resetMeshes();
  ImGui::EndDisabled();
  ImGui::SetNextItemWidth(-110);
  ImGui::InputText("##scenesave", &state.sceneSavePath);
  ImGui::SameLine();
  if (ImGui::Button("Save scene")) save(state, display, SaveKind::Scene, Existing::Refuse);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Hidden meshes are saved as comment lines.");
}
}  // namespace

void drawObjectsPanel(ViewerState& state, RenderDisplay& display) {
  const ImVec2 top = ImGui::GetCursorScreenPos();
  drawObjects(state, display);
  const float bottom = ImGui::GetItemRectMax().y;
  state.regions["objects"] = {top.x, top.y, top.x + ImGui::GetContentRegionAvail().x, bottom};
}

}  // namespace meshtrace::viewer
