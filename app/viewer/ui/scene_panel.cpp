// The scene list: a path field, a folder browser, and the folders of
// scenes in a pane of bounded height (pane_heights.h).
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>

#include "viewer/model/pane_heights.h"
#include "viewer/ui/message_colors.h"
#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

namespace {
void drawFolderBrowser(ViewerState& state) {
  FolderBrowser& browser = *state.browser;
  ImGui::TextWrapped("%s", browser.folder().c_str());
  if (ImGui::Button("Add this folder")) {
    addFolder(state, browser.folder(), browser.folder().filename().string());
    state.browser.reset();
    return;
  }
  ImGui::SameLine();
  if (ImGui::Button("Close")) {
    state.browser.reset();
    return;
  }
  ImGui::BeginChild("browser", ImVec2(0, 140), true);
  std::optional<std::size_t> chosen;
  for (std::size_t i = 0; i < browser.entries().size(); ++i)
    if (ImGui::Selectable(browser.entries()[i].label.c_str())) chosen = i;
  ImGui::EndChild();
  // Moving changes the entries: only after the loop over them.
  if (chosen) browser.enter(*chosen);
}

void drawFolders(ViewerState& state) {
  for (SceneFolder& folder : state.folders) {
    ImGui::PushID(folder.root.string().c_str());
    const std::string header = folder.title + " (" + std::to_string(folder.scenes.size()) + ")";
    if (ImGui::CollapsingHeader(header.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
      if (!folder.error.empty())
        ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", folder.error.c_str());
      for (const auto& scene : folder.scenes) {
        const bool selected = scene == state.session.file();
        if (ImGui::Selectable(sceneLabel(folder, scene).c_str(), selected)) openScene(state, scene);
      }
    }
    ImGui::PopID();
  }
}
}  // namespace

void drawScenePanel(ViewerState& state, float keepBelow) {
  ImGui::SetNextItemWidth(-60);
  if (state.focusPathField) ImGui::SetKeyboardFocusHere();
  state.focusPathField = false;
  const bool entered = ImGui::InputTextWithHint("##path", ".sce, mesh or folder", &state.pathField,
                                                ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  if ((ImGui::Button("Open") || entered) && !state.pathField.empty())
    openPath(state, state.pathField);
  if (ImGui::Button(state.browser ? "Hide folder browser" : "Browse folders...")) {
    if (state.browser)
      state.browser.reset();
    else
      state.browser.emplace();
  }
  if (state.browser) drawFolderBrowser(state);
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("Drop a .sce file, a mesh or a folder on the window to open it.");
  ImGui::PopStyleColor();
  if (state.session.generated()) {
    ImGui::TextWrapped(
        "A generated scene for %s: a camera framing the mesh, a light and a floor. "
        "Save scene writes it as .sce beside the mesh, to edit.",
        state.session.file().filename().string().c_str());
  }
  // Errors and warnings about the open scene stay here while it is open.
  if (const std::string& error = state.session.reloadError(); !error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorColor);
    ImGui::TextWrapped("Reload failed, the last good scene is kept:\n%s", error.c_str());
    ImGui::PopStyleColor();
  }
  if (!state.session.warnings().empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kWarningColor);
    for (const std::string& w : state.session.warnings())
      ImGui::TextWrapped("warning: %s", w.c_str());
    ImGui::PopStyleColor();
  }
  // The folders scroll in a pane of their own: the Objects list below
  // stays in view however many there are.
  const float splitter = kPaneSplitterHeight + ImGui::GetStyle().ItemSpacing.y;
  const float room = ImGui::GetWindowHeight() - ImGui::GetStyle().WindowPadding.y -
                     ImGui::GetCursorPosY() - splitter;
  float& chosen = state.settings.panes.sceneList;
  const float height =
      std::max(1.0f, sceneListHeight(chosen, state.sceneListContent, room, keepBelow));
  const ImVec2 top = ImGui::GetCursorScreenPos();
  ImGui::BeginChild("scene list", ImVec2(0, height));
  drawFolders(state);
  // In the pane's content, wherever it is scrolled to; used next frame.
  state.sceneListContent = ImGui::GetCursorPosY();
  ImGui::EndChild();
  state.regions["scene_list"] = {top.x, top.y, top.x + ImGui::GetItemRectSize().x, top.y + height};
  paneSplitter(state, "##scene-list-height", height, chosen);
}

}  // namespace meshtrace::viewer
