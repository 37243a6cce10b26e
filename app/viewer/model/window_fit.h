#pragma once
// The window's default size on the screen it opens on: the size asked for,
// made smaller where the monitor's work area (the screen less its panels
// and docks) is smaller, so that no part of the window starts off screen.
// Without a window manager nothing would shrink a window too tall for the
// screen; with one, its frame (title bar, borders) counts too.

namespace meshtrace::viewer {

struct ScreenArea {
  int x = 0, y = 0, width = 0, height = 0;
};

// What the window manager draws around the window's content, in pixels.
struct WindowFrame {
  int left = 0, top = 0, right = 0, bottom = 0;
};

// The content's size and place: `width` x `height` at most, inside `area`
// with its frame; at the area's top-left corner (its frame's corner there).
// An empty area (no monitor known) leaves the size as asked.
ScreenArea fitWindow(int width, int height, const ScreenArea& area, const WindowFrame& frame);

}  // namespace meshtrace::viewer
