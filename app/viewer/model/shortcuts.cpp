#include "viewer/model/shortcuts.h"

#include "viewer/model/views.h"

namespace meshtrace::viewer {

namespace {
std::vector<Shortcut> makeTable() {
  std::vector<Shortcut> t{
      {"File", "Open a scene or folder...", Command::Open, {{"O", true}}},
      {"File", "Reload the scene", Command::Reload, {{"F5"}, {"R", true}}},
      {"File", "Save the render", Command::SaveRender, {{"S", true}}},
      {"File", "Save layers (EXR)", Command::SaveLayers, {{"E", true}}},
      {"File", "Save the scene", Command::SaveScene, {{"S", true, true}}},
      {"File", "Save the window", Command::SaveWindow, {{"F12"}}},
      {"File", "Quit", Command::Quit, {{"Q", true}}},
  };
  // Views on the digits, in the order of the view list (0 the tenth).
  for (int v = 0; v < kViewCount; ++v)
    t.push_back({"View",
                 label(static_cast<View>(v)),
                 Command::ShowView,
                 {{std::to_string((v + 1) % 10)}},
                 v});
  const std::vector<Shortcut> rest{
      {"View", "Next overlay", Command::NextOverlay, {{"O"}}},
      {"View", "Zoom to fit", Command::ZoomFit, {{"F"}}},
      {"View", "Actual pixels (1:1)", Command::ZoomActualPixels, {{"1", true}}},
      {"View", "Zoom in", Command::ZoomIn, {{"="}}},
      {"View", "Zoom out", Command::ZoomOut, {{"-"}}},
      {"View", "Unpin the pixel", Command::Unpin, {{"Esc"}}},
      {"View", "Show or hide the scene list", Command::ToggleScenePanel, {{"F2"}}},
      {"View", "Show or hide the details", Command::ToggleDetailsPanel, {{"F3"}}},
      {"Render", "Pause or resume the render", Command::PauseResume, {{"Space"}}},
      {"Render", "Restart the render", Command::Restart, {{"R"}}},
      {"Render", "More AA samples", Command::MoreSamples, {{"A"}}},
      {"Render", "Fewer AA samples", Command::FewerSamples, {{"A", false, true}}},
      {"Help", "Keys", Command::Help, {{"F1"}, {"?"}}},
  };
  t.insert(t.end(), rest.begin(), rest.end());
  return t;
}
}  // namespace

const std::vector<Shortcut>& shortcuts() {
  static const std::vector<Shortcut> table = makeTable();
  return table;
}

std::string chordLabel(const Chord& chord) {
  return std::string(chord.ctrl ? "Ctrl+" : "") + (chord.shift ? "Shift+" : "") + chord.key;
}

std::string keysLabel(const Shortcut& shortcut) {
  std::string out;
  for (const Chord& c : shortcut.keys) out += (out.empty() ? "" : " or ") + chordLabel(c);
  return out;
}

}  // namespace meshtrace::viewer
