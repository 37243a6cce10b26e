// The scene list: folders of scenes, a path field and a folder browser.
#include <imgui.h>
#include <imgui_stdlib.h>

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
}  // namespace

void drawScenePanel(ViewerState& state) {
  ImGui::SetNextItemWidth(-60);
  if (state.focusPathField) ImGui::SetKeyboardFocusHere();
  state.focusPathField = false;
  const bool entered = ImGui::InputTextWithHint("##path", ".sce file or folder", &state.pathField,
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
  ImGui::TextDisabled("Drop a .sce file or a folder on the window to open it.");
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

}  // namespace meshtrace::viewer
