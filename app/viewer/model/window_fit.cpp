#include "viewer/model/window_fit.h"

#include <algorithm>

namespace meshtrace::viewer {

ScreenArea fitWindow(int width, int height, const ScreenArea& area, const WindowFrame& frame) {
  if (area.width <= 0 || area.height <= 0) return {0, 0, width, height};
  // At least one pixel of content, however small the area.
  const int roomX = std::max(1, area.width - frame.left - frame.right);
  const int roomY = std::max(1, area.height - frame.top - frame.bottom);
  return {area.x + frame.left, area.y + frame.top, std::min(width, roomX), std::min(height, roomY)};
}

}  // namespace meshtrace::viewer
