#include "frame_loop.h"

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "../gl/gl_api.h"
#include "../gl/offscreen_context.h"
#include "../ui/panels.h"

namespace meshtrace::viewer {

void initImGui() {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui::StyleColorsDark();
  ImGui_ImplOpenGL3_Init("#version 330 core");
}

void warmUp(int width, int height) {
  ImGui::GetIO().DisplaySize = ImVec2(float(width), float(height));
  ImGui_ImplOpenGL3_NewFrame();
  ImGui::NewFrame();
  ImGui::Begin("warm-up");
  ImGui::TextUnformatted("-");
  ImGui::End();
  ImGui::Render();
  glViewport(0, 0, width, height);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  glFinish();
}

void shutdownImGui() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui::DestroyContext();
}

bool saveFramebuffer(ViewerApp& app, const std::string& path, int width, int height) {
  Image8 shot;
  shot.width = width;
  shot.height = height;
  shot.rgb = gl::readFramebufferRgb(width, height);
  try {
    writeImage(shot, path);
    setMessage(app.state(), "saved the window to " + path, false);
    return true;
  } catch (const std::exception& e) {
    setMessage(app.state(), e.what(), true);
    return false;
  }
}

double drawFrame(ViewerApp& app, int width, int height) {
  const auto start = std::chrono::steady_clock::now();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui::NewFrame();
  app.frame();
  ImGui::Render();
  const auto built = std::chrono::steady_clock::now();
  glViewport(0, 0, width, height);
  glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  glFinish();
  const auto end = std::chrono::steady_clock::now();
  const double ms = std::chrono::duration<double, std::milli>(end - start).count();
  if (app.state().options.frameLog)
    std::fprintf(stderr, "frame %.1f ms: ui %.1f, gl %.1f\n", ms,
                 std::chrono::duration<double, std::milli>(built - start).count(),
                 std::chrono::duration<double, std::milli>(end - built).count());
  if (const std::string shot = app.takeScreenshotRequest(); !shot.empty())
    saveFramebuffer(app, shot, width, height);
  app.frameDrawn(ms);
  return ms;
}

}  // namespace meshtrace::viewer
