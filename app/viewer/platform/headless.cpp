// Headless: the whole window drawn offscreen through OSMesa, written as PNG
// once the render (and its AA samples) is complete; or, with --time-opening,
// every listed scene opened in turn and timed.
#include <imgui.h>

#include "viewer/gl/offscreen_context.h"
#include "viewer/platform/frame_loop.h"
#include "viewer/platform/run.h"

namespace meshtrace::viewer {

namespace {
// False if the scene did not open.
bool printOpeningTimes(ViewerApp& app, const std::filesystem::path& scene) {
  const ViewerState& state = app.state();
  const ShownTimes& shown = app.display().shownTimes();
  const FrameStats& frames = state.timing.renderingFrames;
  if (!state.session.loaded()) {
    std::printf("%-28s %s\n", scene.filename().string().c_str(), state.session.error().c_str());
    return false;
  }
  std::printf(
      "%-28s load %6.1f ms  first image %6.1f ms  exact image %7.1f ms  "
      "frames while rendering %3zu, longest %s, 99%% %s\n",
      scene.filename().string().c_str(), state.timing.loadMs, shown.firstImageMs,
      shown.exactImageMs, frames.count(), formatMs(frames.longest()).c_str(),
      formatMs(frames.percentile(99.0)).c_str());
  return true;
}

// --describe: the last frame's regions, then its text.
bool writeDescription(ViewerApp& app, const std::string& path) {
  std::FILE* out = std::fopen(path.c_str(), "w");
  if (!out) {
    std::fprintf(stderr, "error: cannot write %s\n", path.c_str());
    return false;
  }
  for (const auto& [name, r] : app.state().regions)
    std::fprintf(out, "region %s %.0f %.0f %.0f %.0f\n", name.c_str(), r[0], r[1], r[2], r[3]);
  std::fprintf(out, "text\n%s\n", app.state().frameText.c_str());
  const bool ok = std::fclose(out) == 0;
  if (!ok) std::fprintf(stderr, "error: cannot write %s\n", path.c_str());
  return ok;
}
}  // namespace

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
    // The wake-up ends the pause between frames and the wait that stands
    // for a window's wait for input, each with a flag of its own.
    WakeFlag handedOver, inputWait;
    ViewerApp app(options, executable, [&] {
      handedOver.raise();
      inputWait.raise();
    });
    app.captureText(!options.describe.empty());
    auto start = std::chrono::steady_clock::now();
    int settled = 0;
    FrameHost host;
    // Frames as a window would draw them, until the render is done and the
    // layout has settled (a few frames).
    host.keepRunning = [&] {
      if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >
          options.timeoutSeconds) {
        std::fprintf(stderr, "error: the render did not finish within %.0f s\n",
                     options.timeoutSeconds);
        status = 1;
        return false;
      }
      settled = app.idle() ? settled + 1 : 0;
      return settled <= 3;
    };
    // No input arrives here: once idle, nothing is worth waiting for.
    host.waitForInput = [&](double ms) {
      if (!app.idle()) inputWait.waitFor(ms);
    };
    host.beginFrame = [&] { return std::make_pair(options.width, options.height); };
    host.present = [] {};
    if (options.timeOpening) {
      for (const SceneFolder& folder : std::vector<SceneFolder>(app.state().folders))
        for (const std::filesystem::path& scene : folder.scenes) {
          app.drop({scene.string()});
          start = std::chrono::steady_clock::now();
          settled = 0;
          runFrames(app, host, handedOver);
          if (!printOpeningTimes(app, scene)) status = 1;
        }
    } else {
      runFrames(app, host, handedOver);
      // A failure is an error and an exit code, never a picture of it: the
      // output (an earlier snapshot, say) stays as it was.
      const std::vector<std::string> failures = app.failures();
      for (const std::string& f : failures) std::fprintf(stderr, "error: %s\n", f.c_str());
      if (!failures.empty()) {
        status = 1;
      } else if (status == 0) {
        drawFrame(app, options.width, options.height);
        if (!saveFramebuffer(app, options.snapshot, options.width, options.height)) status = 1;
        if (!options.describe.empty() && !writeDescription(app, options.describe)) status = 1;
      }
    }
    if (options.stats) app.printStats();
  }
  shutdownImGui();
  return status;
}

}  // namespace meshtrace::viewer
