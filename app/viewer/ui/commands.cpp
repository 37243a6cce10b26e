// The menu bar, the keys and the help overlay, all from the shortcut table
// (shortcuts.h), and what each command does.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>

#include "viewer/model/options.h"
#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

namespace {
// The GLFW key code of a chord's key (the window's ImGui backend indexes
// its keys by them); -1 for a key typed as a character ("?").
int keyCode(const std::string& key) {
  if (key == "Space") return GLFW_KEY_SPACE;
  if (key == "Esc") return GLFW_KEY_ESCAPE;
  if (key == "F1") return GLFW_KEY_F1;
  if (key == "F2") return GLFW_KEY_F2;
  if (key == "F3") return GLFW_KEY_F3;
  if (key == "F5") return GLFW_KEY_F5;
  if (key == "F12") return GLFW_KEY_F12;
  if (key == "-") return GLFW_KEY_MINUS;
  if (key == "=") return GLFW_KEY_EQUAL;
  if (key.size() == 1 && std::isalnum(static_cast<unsigned char>(key[0]))) return key[0];
  return -1;
}

bool typed(char c) {
  const ImGuiIO& io = ImGui::GetIO();
  for (int i = 0; i < io.InputQueueCharacters.Size; ++i)
    if (io.InputQueueCharacters[i] == static_cast<ImWchar>(c)) return true;
  return false;
}

bool pressed(const Chord& chord, const std::vector<KeyPress>& presses) {
  const int code = keyCode(chord.key);
  if (code < 0) return chord.key.size() == 1 && !ImGui::GetIO().KeyCtrl && typed(chord.key[0]);
  for (const KeyPress& p : presses)
    if (p.code == code && p.ctrl == chord.ctrl && p.shift == chord.shift && !p.alt) return true;
  return false;
}

void zoomAboutTheCentre(ViewerState& state, double factor) {
  const ScreenRect r = state.viewport.imageRect();
  state.viewport.zoomAt(factor, r.x + r.width / 2, r.y + r.height / 2);
}
}  // namespace

bool runCommand(ViewerState& state, RenderDisplay& display, const Shortcut& shortcut) {
  switch (shortcut.command) {
    case Command::Open:
      if (!state.browser) state.browser.emplace();
      state.focusPathField = true;
      return true;
    case Command::Reload: reloadScene(state); return true;
    case Command::SaveRender:
    case Command::SaveLayers:
      if (display.frame().width == 0)
        setMessage(state, "no render to save yet", true);
      else
        save(state, display,
             shortcut.command == Command::SaveRender ? SaveKind::Render : SaveKind::Layers,
             Existing::Refuse);
      return true;
    case Command::SaveScene:
      if (!state.session.loaded())
        setMessage(state, "no scene to save", true);
      else
        save(state, display, SaveKind::Scene, Existing::Refuse);
      return true;
    case Command::SaveWindow: save(state, display, SaveKind::Window, Existing::Refuse); return true;
    case Command::Quit: state.quitRequested = true; return true;
    case Command::ShowView: state.view = static_cast<View>(shortcut.view); return true;
    case Command::NextOverlay:
      state.overlay = static_cast<Overlay>((static_cast<int>(state.overlay) + 1) % kOverlayCount);
      return true;
    case Command::ZoomFit: state.viewport.fit(); return true;
    case Command::ZoomActualPixels: state.viewport.actualSize(); return true;
    case Command::ZoomIn: zoomAboutTheCentre(state, 2.0); return true;
    case Command::ZoomOut: zoomAboutTheCentre(state, 0.5); return true;
    case Command::Unpin:
      if (state.helpOpen)
        state.helpOpen = false;
      else
        state.pinned.reset();
      return true;
    case Command::ToggleScenePanel:
      state.settings.left.shown = !state.settings.left.shown;
      state.settingsChanged = true;
      return true;
    case Command::ToggleDetailsPanel:
      state.settings.right.shown = !state.settings.right.shown;
      state.settingsChanged = true;
      return true;
    case Command::Restart: display.restart(); return true;
    case Command::PauseResume: display.setPaused(!display.paused()); return true;
    case Command::MoreSamples:
      state.extraSamples = std::min(16, std::max(1, state.extraSamples * 2));
      return true;
    case Command::FewerSamples: state.extraSamples /= 2; return true;
    case Command::Help: state.helpOpen = !state.helpOpen; return true;
  }
  return false;
}

void handleShortcuts(ViewerState& state, RenderDisplay& display) {
  const std::vector<KeyPress> presses = std::move(state.keyPresses);
  state.keyPresses.clear();
  // Keys typed into a field are the field's; a question waits for its answer.
  if (ImGui::GetIO().WantTextInput || state.overwrite) return;
  for (const Shortcut& s : shortcuts())
    for (const Chord& c : s.keys)
      if (pressed(c, presses)) runCommand(state, display, s);
}

namespace {
// File > Open recent: the scenes opened last, newest first.
void drawRecentMenu(ViewerState& state) {
  if (!ImGui::BeginMenu("Open recent")) return;
  if (state.settings.recent.empty()) ImGui::MenuItem("(none yet)", nullptr, false, false);
  std::optional<std::filesystem::path> chosen;
  for (const std::filesystem::path& p : state.settings.recent)
    if (ImGui::MenuItem(p.string().c_str())) chosen = p;
  ImGui::EndMenu();
  if (chosen) openScene(state, *chosen);
}
}  // namespace

void drawMenuBar(ViewerState& state, RenderDisplay& display) {
  if (!ImGui::BeginMainMenuBar()) return;
  for (const char* menu : {"File", "View", "Render", "Help"}) {
    if (!ImGui::BeginMenu(menu)) continue;
    for (const Shortcut& s : shortcuts()) {
      if (s.menu != menu) continue;
      if (s.command == Command::Reload) drawRecentMenu(state);
      const bool checked = s.command == Command::ShowView && state.view == View(s.view);
      if (ImGui::MenuItem(s.label.c_str(), keysLabel(s).c_str(), checked))
        runCommand(state, display, s);
    }
    if (std::string(menu) == "View") {
      ImGui::Separator();
      for (int o = 0; o < kOverlayCount; ++o) {
        const std::string item = std::string("Overlay: ") + name(static_cast<Overlay>(o));
        if (ImGui::MenuItem(item.c_str(), nullptr, state.overlay == static_cast<Overlay>(o)))
          state.overlay = static_cast<Overlay>(o);
      }
    }
    if (std::string(menu) == "Render") {
      ImGui::Separator();
      ImGui::SetNextItemWidth(120);
      ImGui::SliderInt("AA samples", &state.extraSamples, 0, 16);
    }
    if (std::string(menu) == "Help" && ImGui::MenuItem("About")) state.aboutOpen = true;
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
}

void drawHelpOverlay(ViewerState& state) {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  if (state.helpOpen) {
    ImGui::SetNextWindowPos(ImVec2(size.x / 2, size.y / 2), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowBgAlpha(0.94f);
    ImGui::Begin("Keys (F1 or ? to close)", &state.helpOpen,
                 ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoCollapse);
    if (ImGui::BeginTable("keys", 3, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg)) {
      for (const Shortcut& s : shortcuts()) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextDisabled("%s", s.menu.c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(keysLabel(s).c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(s.label.c_str());
      }
      ImGui::EndTable();
    }
    ImGui::TextDisabled("Image: left drag orbits, right drag pans, wheel zooms, click pins.");
    ImGui::End();
  }
  if (state.aboutOpen) {
    ImGui::SetNextWindowPos(ImVec2(size.x / 2, size.y / 2), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::Begin("About", &state.aboutOpen,
                 ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings);
    ImGui::TextUnformatted(versionLine().c_str());
    ImGui::TextUnformatted("A ray tracer for triangle meshes: browse scenes, watch them render,");
    ImGui::TextUnformatted("inspect every pixel.");
    ImGui::Text("Dear ImGui %s, GLFW %s", IMGUI_VERSION, glfwGetVersionString());
    ImGui::End();
  }
}

}  // namespace meshtrace::viewer
