#include "viewer/model/pane_heights.h"

#include <algorithm>

namespace meshtrace::viewer {

float paneHeight(float chosen, float room) {
  return std::max(kMinPane, chosen > 0 ? chosen : room);
}

}  // namespace meshtrace::viewer
