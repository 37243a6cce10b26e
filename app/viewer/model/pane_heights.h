#pragma once
// The heights of the side panels' scrolling panes, such as the inspector's:
// the height the user dragged the pane to (kept in the settings) or one
// that follows from the room the panel has, never from what the pane holds,
// so the headers below it stay put while the hovered pixel changes.
namespace meshtrace::viewer {

inline constexpr float kMinPane = 80.0f;

// `room`: the panel's height from the pane's top to its bottom, less what
// must stay visible below the pane; `chosen`: the dragged height, 0 if none.
// The chosen height, else all of the room; at least kMinPane.
float paneHeight(float chosen, float room);

}  // namespace meshtrace::viewer
