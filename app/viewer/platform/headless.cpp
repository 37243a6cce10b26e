// Headless: the whole window drawn offscreen through OSMesa, written as PNG
// once the render (and its AA samples) is complete.
#include <imgui.h>

#include <thread>

#include "../gl/offscreen_context.h"
#include "frame_loop.h"
#include "run.h"

namespace meshtrace::viewer {

int runHeadless(const ViewerOptions& options, const std::filesystem::path& executable) {
  std::unique_ptr<gl::OffscreenContext> context;
  try {
    context = std::make_unique<gl::OffscreenContext>(options.width, options.height);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  initImGui();
  int status = 0;
  {
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(float(options.width), float(options.height));
    io.DeltaTime = 1.0f / 60.0f;
    warmUp(options.width, options.height);
    ViewerApp app(options, executable);
    const auto start = std::chrono::steady_clock::now();
    int settled = 0;
    // Frames paced as a window would draw them (framePeriodMs), until the
    // render is done and the layout has settled (a few frames).
    while (settled < 3) {
      const auto frameStart = std::chrono::steady_clock::now();
      drawFrame(app, options.width, options.height);
      settled = app.idle() ? settled + 1 : 0;
      if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >
          options.timeoutSeconds) {
        std::fprintf(stderr, "error: the render did not finish within %.0f s\n",
                     options.timeoutSeconds);
        status = 1;
        break;
      }
      std::this_thread::sleep_until(frameStart +
                                    std::chrono::microseconds(int(1000 * app.framePeriodMs())));
    }
    drawFrame(app, options.width, options.height);
    if (!saveFramebuffer(app, options.snapshot, options.width, options.height)) status = 1;
    if (options.stats) app.printStats();
  }
  shutdownImGui();
  return status;
}

}  // namespace meshtrace::viewer
