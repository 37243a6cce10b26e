#pragma once
// The viewer's commands and their keys, in one table: the menus, the help
// overlay and the keyboard all read it, so a key shown is the key that works.
#include <string>
#include <vector>

namespace meshtrace::viewer {

enum class Command {
  Open,
  Reload,
  SaveRender,
  SaveLayers,  // the render's layers as one EXR file (render/layers.h)
  SaveScene,
  SaveWindow,
  Quit,
  ShowView,  // the view numbered `view` (views.h)
  NextOverlay,
  ZoomFit,
  ZoomActualPixels,
  ZoomIn,
  ZoomOut,
  Unpin,
  ToggleScenePanel,
  ToggleDetailsPanel,
  Restart,
  PauseResume,
  MoreSamples,
  FewerSamples,
  Help,
};

// A key with its modifiers. `key` is a letter or digit ("S", "1"), a sign
// ("-", "=", "?") or a named key ("Space", "Esc", "F1", "F5", "F12").
struct Chord {
  std::string key;
  bool ctrl = false;
  bool shift = false;
  bool operator==(const Chord&) const = default;
};

struct Shortcut {
  std::string menu;   // File, View, Render or Help
  std::string label;  // as the menu shows it
  Command command;
  std::vector<Chord> keys;  // the first is shown in the menu
  int view = 0;             // for ShowView
};

const std::vector<Shortcut>& shortcuts();

// "Ctrl+Shift+S", "F1": as menus and the help show a chord.
std::string chordLabel(const Chord& chord);
// Every chord of the entry, joined with " or ".
std::string keysLabel(const Shortcut& shortcut);

}  // namespace meshtrace::viewer
