// The real window: GLFW with an OpenGL 3.3 core context.
#define GLFW_INCLUDE_NONE  // GL comes from gl_api.h
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include "viewer/gl/gl_api.h"
#include "viewer/model/window_fit.h"
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

// The primary monitor's work area; its whole video mode if the system
// gives no work area; empty if there is no monitor.
ScreenArea workArea() {
  GLFWmonitor* monitor = glfwGetPrimaryMonitor();
  if (!monitor) return {};
  ScreenArea area;
  glfwGetMonitorWorkarea(monitor, &area.x, &area.y, &area.width, &area.height);
  if (area.width > 0 && area.height > 0) return area;
  const GLFWvidmode* mode = glfwGetVideoMode(monitor);
  if (!mode) return {};
  glfwGetMonitorPos(monitor, &area.x, &area.y);
  return {area.x, area.y, mode->width, mode->height};
}

// The window made smaller and moved to fit the work area, once its frame
// is known; moved only if it did not fit as it was.
void fitToWorkArea(GLFWwindow* window, const ScreenArea& area, int width, int height) {
  WindowFrame frame;
  glfwGetWindowFrameSize(window, &frame.left, &frame.top, &frame.right, &frame.bottom);
  const ScreenArea fitted = fitWindow(width, height, area, frame);
  int x, y, w, h;
  glfwGetWindowPos(window, &x, &y);
  glfwGetWindowSize(window, &w, &h);
  if (w != fitted.width || h != fitted.height)
    glfwSetWindowSize(window, fitted.width, fitted.height);
  const bool outside = x - frame.left < area.x || y - frame.top < area.y ||
                       x + fitted.width + frame.right > area.x + area.width ||
                       y + fitted.height + frame.bottom > area.y + area.height;
  if (area.width > 0 && outside) glfwSetWindowPos(window, fitted.x, fitted.y);
}
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
  // --size is taken as given; the default size is fitted to the screen.
  const ScreenArea area = options.sizeGiven ? ScreenArea{} : workArea();
  const ScreenArea first = fitWindow(options.width, options.height, area, {});
  // Shown once the shaders are compiled (warmUp): until then it could draw
  // nothing and would not answer.
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  GLFWwindow* window =
      glfwCreateWindow(first.width, first.height, "meshtrace viewer", nullptr, nullptr);
  if (!window) {
    glfwTerminate();
    return 1;
  }
  if (!options.sizeGiven) fitToWorkArea(window, area, options.width, options.height);
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
    const double warmUpMs = warmUp(width, height);
    glfwShowWindow(window);
    if (options.frameLog)
      std::fprintf(stderr, "window shown after %.1f ms of drawing to compile the shaders\n",
                   warmUpMs);
    // The render reaching its first or exact image, or background work
    // handing something over, ends the pause between frames and posts an
    // empty event, which ends the wait for input.
    WakeFlag handedOver;
    ViewerApp app(options, executable, [&handedOver] {
      handedOver.raise();
      glfwPostEmptyEvent();
    });
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
    runFrames(app, host, handedOver);
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
