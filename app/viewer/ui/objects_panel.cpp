// The object list: per mesh FLAT/PHONG, visibility and counts; reset; save.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>

#include "viewer/model/line_breaks.h"
#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

namespace {
constexpr float kShadingButtonWidth = 56;

float textWidth(const std::string& s) { return ImGui::CalcTextSize(s.c_str()).x; }

std::string countsText(const MeshState& m) {
  return std::to_string(m.triangles) + " / " + std::to_string(m.vertices);
}

// Whether the counts have a column of their own: only where it leaves the
// names their width, or eight letters' of a longer name; else the counts
// go under each name.
bool countsColumnFits(const SceneSession& session) {
  float counts = textWidth("tris / verts"), names = 0;
  for (const MeshState& m : session.meshes()) {
    counts = std::max(counts, textWidth(countsText(m)));
    names = std::max(names, textWidth(m.name));
  }
  const float fixed = ImGui::GetFrameHeight() + kShadingButtonWidth + counts +
                      8 * ImGui::GetStyle().CellPadding.x + std::min(names, textWidth("mmmmmmmm"));
  return ImGui::GetContentRegionAvail().x >= fixed;
}

// The mesh's name in its cell, cut short with "..." where the cell is too
// narrow, whole in a tooltip with its counts.
void drawName(const MeshState& m, bool countsBelow) {
  const std::string counts = countsText(m) + " tris / verts";
  ImGui::TextUnformatted(elide(m.name, ImGui::GetContentRegionAvail().x, textWidth).c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s\n%s", m.name.c_str(), counts.c_str());
  if (!countsBelow) return;
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  textFields({std::to_string(m.triangles) + " tris", std::to_string(m.vertices) + " verts"}, ", ");
  ImGui::PopStyleColor();
}

void drawObjects(ViewerState& state, RenderDisplay& display) {
  SceneSession& session = state.session;
  if (!session.loaded()) {
    ImGui::TextDisabled("No scene loaded.");
    return;
  }
  {
    const Scene& scene = session.scene();
    textFields({std::to_string(scene.spheres.size()) + " spheres",
                std::to_string(scene.planes.size()) + " planes",
                std::to_string(scene.cylinders.size()) + " cylinders",
                std::to_string(scene.lights.size()) + " lights"},
               ", ");
  }
  if (session.meshes().empty()) {
    ImGui::TextDisabled("No meshes.");
    return;
  }
  const bool countsColumn = countsColumnFits(session);
  if (ImGui::BeginTable("meshes", countsColumn ? 4 : 3,
                        ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
    // The headers name the columns only where they are not cut short.
    ImGui::TableSetupColumn(countsColumn ? "show" : "");
    ImGui::TableSetupColumn("mesh", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("shading");
    if (countsColumn) ImGui::TableSetupColumn("tris / verts");
    ImGui::TableHeadersRow();
    for (std::size_t i = 0; i < session.meshes().size(); ++i) {
      const MeshState& m = session.meshes()[i];
      ImGui::PushID(static_cast<int>(i));
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      bool visible = m.visible;
      if (ImGui::Checkbox("##visible", &visible)) session.setVisible(i, visible);
      ImGui::TableNextColumn();
      drawName(m, !countsColumn);
      ImGui::TableNextColumn();
      // One button toggles FLAT and PHONG; a changed mode is highlighted.
      const bool changed = m.shading != m.fileShading;
      if (changed) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.6f, 0.35f, 0.1f, 1.0f));
      if (ImGui::Button(toString(m.shading), ImVec2(kShadingButtonWidth, 0)))
        session.setShading(i, m.shading == Shading::Flat ? Shading::Phong : Shading::Flat);
      if (changed) ImGui::PopStyleColor();
      if (countsColumn) {
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(countsText(m).c_str());
      }
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
