// The scene list: folders of scenes, a path field and a folder browser.
#include <imgui.h>
#include <imgui_stdlib.h>

#include "panels.h"

namespace meshtrace::viewer {

namespace {
void drawFolderBrowser(ViewerState& state) {
  namespace fs = std::filesystem;
  if (state.browseDir.empty()) state.browseDir = fs::current_path().string();
  ImGui::TextWrapped("%s", state.browseDir.c_str());
  if (ImGui::Button("Add this folder")) {
    addFolder(state, state.browseDir, fs::path(state.browseDir).filename().string());
    state.browsing = false;
  }
  ImGui::SameLine();
  if (ImGui::Button("Close")) state.browsing = false;
  ImGui::BeginChild("browser", ImVec2(0, 140), true);
  if (ImGui::Selectable("..")) state.browseDir = fs::path(state.browseDir).parent_path().string();
  for (const fs::path& dir : subfolders(state.browseDir)) {
    if (ImGui::Selectable((dir.filename().string() + "/").c_str())) state.browseDir = dir.string();
  }
  ImGui::EndChild();
}
}  // namespace

void drawScenePanel(ViewerState& state) {
  ImGui::SetNextItemWidth(-60);
  const bool entered = ImGui::InputTextWithHint("##path", ".sce file or folder", &state.pathField,
                                                ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  if ((ImGui::Button("Open") || entered) && !state.pathField.empty())
    openPath(state, state.pathField);
  if (ImGui::Button(state.browsing ? "Hide folder browser" : "Browse folders..."))
    state.browsing = !state.browsing;
  if (state.browsing) drawFolderBrowser(state);
  ImGui::TextDisabled("Drop a .sce file or a folder on the window to open it.");
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
