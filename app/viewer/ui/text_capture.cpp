// The text a frame shows, for --describe: ImGui's log records the text of
// every widget drawn between beginCapture and endCapture. Depth 0 opens no
// closed tree node. To the clipboard: Debian's 1.86 records nothing logging
// to its buffer.
#include <imgui.h>
#include <imgui_internal.h>  // the log's buffer

#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

void beginCapture(ViewerState& state) {
  if (state.captureText) ImGui::LogToClipboard(0);
}

void endCapture(ViewerState& state) {
  if (!state.captureText) return;
  state.frameText += GImGui->LogBuffer.c_str();
  state.frameText += '\n';
  ImGui::LogFinish();
}

void drawCapturedAs(ViewerState& state, const std::string& text,
                    const std::function<void()>& draw) {
  if (!state.captureText) return draw();
  endCapture(state);
  state.frameText += text;
  draw();
  beginCapture(state);
}

}  // namespace meshtrace::viewer
