// The real window: GLFW with an OpenGL 3.3 core context.
#define GLFW_INCLUDE_NONE  // GL comes from gl_api.h
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include "viewer/gl/gl_api.h"
#include "viewer/platform/drop.h"
#include "viewer/platform/frame_loop.h"
#include "viewer/platform/run.h"

namespace meshtrace::viewer {

namespace {
ViewerApp* windowApp = nullptr;

void onDrop(GLFWwindow*, int count, const char** paths) {
  if (windowApp) dropPaths(*windowApp, count, paths);
}

// ImGui's backend calls this after its own. Presses are queued for the
// shortcuts: ImGui 1.86 sees only the keys down at a frame's start, and a
// quick press and release between two frames would be lost.
void onKey(GLFWwindow*, int key, int, int action, int mods) {
  if (windowApp && action == GLFW_PRESS)
    windowApp->state().keyPresses.push_back({key, (mods & GLFW_MOD_CONTROL) != 0,
                                             (mods & GLFW_MOD_SHIFT) != 0,
                                             (mods & GLFW_MOD_ALT) != 0});
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
  glfwSetKeyCallback(window, onKey);
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  {
    int width, height;
    glfwGetFramebufferSize(window, &width, &height);
    warmUp(width, height);
    // The render reaching its first or exact image posts an empty event,
    // which ends the wait for input.
    ViewerApp app(options, executable, [] { glfwPostEmptyEvent(); });
    windowApp = &app;
    app.useSettings(settingsFile());
    glfwSetDropCallback(window, onDrop);
    FrameHost host;
    int idleFrames = 0;
    host.keepRunning = [&] {
      idleFrames = app.idle() ? idleFrames + 1 : 0;
      return !glfwWindowShouldClose(window) && !app.state().quitRequested &&
             !(options.quitWhenDone && idleFrames > 3);
    };
    host.waitForInput = [](double ms) {
      if (ms > 0)
        glfwWaitEventsTimeout(ms / 1000.0);
      else
        glfwPollEvents();
    };
    host.beginFrame = [&] {
      glfwGetFramebufferSize(window, &width, &height);
      ImGui_ImplGlfw_NewFrame();
      return std::make_pair(width, height);
    };
    host.present = [&] { glfwSwapBuffers(window); };
    runFrames(app, host);
    if (options.stats) app.printStats();
    windowApp = nullptr;
  }
  ImGui_ImplGlfw_Shutdown();
  shutdownImGui();
  glfwDestroyWindow(window);
  glfwTerminate();
  return 0;
}

}  // namespace meshtrace::viewer
