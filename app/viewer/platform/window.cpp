// The real window: GLFW with an OpenGL 3.3 core context.
#define GLFW_INCLUDE_NONE  // GL comes from gl_api.h
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include <thread>

#include "../gl/gl_api.h"
#include "frame_loop.h"
#include "run.h"

namespace meshtrace::viewer {

namespace {
ViewerApp* dropTarget = nullptr;

void onDrop(GLFWwindow*, int count, const char** paths) {
  if (!dropTarget) return;
  std::vector<std::string> list(paths, paths + count);
  dropTarget->drop(list);
}

void* loadProc(const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }
}  // namespace

int runWindow(const ViewerOptions& options, const std::filesystem::path& executable) {
  glfwSetErrorCallback(
      [](int code, const char* text) { std::fprintf(stderr, "glfw error %d: %s\n", code, text); });
  if (!glfwInit()) {
    std::fprintf(stderr, "error: no display (use --headless --snapshot OUT.png without one)\n");
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  GLFWwindow* window =
      glfwCreateWindow(options.width, options.height, "meshtrace viewer", nullptr, nullptr);
  if (!window) {
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);
  if (const char* missing = gl::loadFunctions(&loadProc)) {
    std::fprintf(stderr, "error: the GL context lacks %s\n", missing);
    return 1;
  }
  initImGui();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  {
    int width, height;
    glfwGetFramebufferSize(window, &width, &height);
    warmUp(width, height);
    ViewerApp app(options, executable);
    dropTarget = &app;
    glfwSetDropCallback(window, onDrop);
    while (!glfwWindowShouldClose(window)) {
      const auto frameStart = std::chrono::steady_clock::now();
      // Sleep in the event queue when nothing is rendering.
      if (app.idle())
        glfwWaitEventsTimeout(0.25);
      else
        glfwPollEvents();
      glfwGetFramebufferSize(window, &width, &height);
      ImGui_ImplGlfw_NewFrame();
      drawFrame(app, width, height);
      glfwSwapBuffers(window);
      std::this_thread::sleep_until(frameStart +
                                    std::chrono::microseconds(int(1000 * app.framePeriodMs())));
    }
    if (options.stats) app.printStats();
    dropTarget = nullptr;
  }
  ImGui_ImplGlfw_Shutdown();
  shutdownImGui();
  glfwDestroyWindow(window);
  glfwTerminate();
  return 0;
}

}  // namespace meshtrace::viewer
