#pragma once
// The colours of what the window says: errors red, warnings amber.
#include <imgui.h>

namespace meshtrace::viewer {

inline const ImVec4 kErrorColor{1.0f, 0.45f, 0.45f, 1.0f};
inline const ImVec4 kWarningColor{1.0f, 0.8f, 0.3f, 1.0f};

}  // namespace meshtrace::viewer
