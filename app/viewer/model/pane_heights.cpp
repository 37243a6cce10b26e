#include "viewer/model/pane_heights.h"

#include <algorithm>

namespace meshtrace::viewer {

float paneHeight(float chosen, float room) {
  return std::max(kMinPane, chosen > 0 ? chosen : room);
}

float sceneListHeight(float chosen, float content, float room, float below) {
  const float height = chosen > 0
                           ? std::min(chosen, room - kMinPane)
                           : std::min(content, std::max(kSceneListShare * room, room - below));
  return std::max(height, std::min(content, kMinPane));
}

}  // namespace meshtrace::viewer
