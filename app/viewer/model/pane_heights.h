#pragma once
// The heights of the side panels' scrolling panes: the scene list, above the
// Objects list, and the inspector. Each is the height the user dragged it to
// (kept in the settings) or one that follows from the room the panel has;
// the inspector's never follows what it holds, so the headers below it stay
// put while the hovered pixel changes, and the scene list's stops at a share
// of the room, so folders added to it never push the Objects list away.
namespace meshtrace::viewer {

inline constexpr float kMinPane = 80.0f;
// Of the room below the scene list's top, what the list may take unless
// dragged, however long the Objects list below it is.
inline constexpr float kSceneListShare = 0.45f;

// `room`: the panel's height from the pane's top to its bottom, less what
// must stay visible below the pane; `chosen`: the dragged height, 0 if none.

// The inspector: the chosen height, else all of the room; at least kMinPane.
float paneHeight(float chosen, float room);
// The scene list, `content` pixels long, above what drew `below` pixels
// (the Objects list): as long as its content but for that, and it may
// always take kSceneListShare of the room; or the chosen height but for
// kMinPane of the room. Never less than kMinPane, or the content if shorter.
float sceneListHeight(float chosen, float content, float room, float below);

}  // namespace meshtrace::viewer
