#include "viewer/platform/frame_loop.h"

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <sys/resource.h>
#include <time.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <vector>

#include "viewer/gl/gl_api.h"
#include "viewer/gl/offscreen_context.h"
#include "viewer/gl/texture.h"
#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

namespace {
using Clock = std::chrono::steady_clock;

double msBetween(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

// However fast the input comes, no more presented frames than a display shows.
constexpr auto kShortestFrame = std::chrono::microseconds(1000000 / 60);

// The colour the translucent panels were drawn over, and what they made of it.
constexpr float kBehindPanels[3] = {0.08f, 0.08f, 0.09f};
float background[3] = {0.0f, 0.0f, 0.0f};
}  // namespace

void initImGui() {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui::StyleColorsDark();
  // The panels cover the whole window: clearing it to their background
  // colour and drawing them without one gives the same picture, and a
  // software rasteriser fills the window once per frame instead of twice.
  ImVec4& panel = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
  const float panelRgb[3] = {panel.x, panel.y, panel.z};
  for (int k = 0; k < 3; ++k)
    background[k] = panelRgb[k] * panel.w + kBehindPanels[k] * (1.0f - panel.w);
  panel.w = 0.0f;
  ImGui_ImplOpenGL3_Init("#version 330 core");
}

double warmUp(int width, int height) {
  const Clock::time_point start = Clock::now();
  ImGui::GetIO().DisplaySize = ImVec2(float(width), float(height));
  ImGui_ImplOpenGL3_NewFrame();  // creates the font texture
  // Glyphs sit on whole pixels and every other shape samples one white
  // texel (thick lines get their soft edges from geometry, not from the
  // atlas): nearest sampling looks the same as the backend's linear
  // filtering and costs a software rasteriser about a sixth less per frame.
  ImGui::GetStyle().AntiAliasedLinesUseTex = false;
  glBindTexture(GL_TEXTURE_2D,
                static_cast<GLuint>(reinterpret_cast<std::intptr_t>(ImGui::GetIO().Fonts->TexID)));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  // A software rasteriser (llvmpipe) compiles code for each kind of texture
  // on its first use (gl::textureKinds): each kind is drawn here, magnified
  // and minified as the image view draws images, so that no frame compiles.
  const std::vector<std::unique_ptr<gl::Texture>> kinds = gl::textureKinds();
  ImGui::NewFrame();
  // As large as the window: the first frame to fill it is slow too.
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImGui::GetIO().DisplaySize);
  ImGui::Begin("warm-up");
  ImGui::TextUnformatted("-");
  for (const auto& kind : kinds) {
    const auto id = reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(kind->id()));
    ImGui::Image(id, ImVec2(16, 16));
    ImGui::Image(id, ImVec2(1, 1), ImVec2(0, 0), ImVec2(1, 1), ImVec4(1, 1, 1, 0.5f));
  }
  ImGui::End();
  ImGui::Render();
  glViewport(0, 0, width, height);
  glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  glFinish();
  return msBetween(start, Clock::now());
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

void drawFrame(ViewerApp& app, int width, int height) {
  glViewport(0, 0, width, height);
  glClearColor(background[0], background[1], background[2], 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  glFinish();
  if (const std::string shot = app.takeScreenshotRequest(); !shot.empty())
    saveFramebuffer(app, shot, width, height);
}

namespace {
// The processor time the machine's host has taken from this virtual
// machine so far (steal, summed over its processors; 0 on bare metal), in
// ms, from /proc/stat's ticks (USER_HZ, 100 a second on Linux). A frame
// whose thread was slow while steal grew was slowed by the host, not by
// our code.
double hostStealMs() {
  std::FILE* f = std::fopen("/proc/stat", "r");
  if (!f) return 0.0;
  unsigned long long user, nice, system, idle, iowait, irq, softirq, steal = 0;
  const int read = std::fscanf(f, "cpu %llu %llu %llu %llu %llu %llu %llu %llu", &user, &nice,
                               &system, &idle, &iowait, &irq, &softirq, &steal);
  std::fclose(f);
  return read == 8 ? static_cast<double>(steal) * 10.0 : 0.0;
}

// The UI thread's own use of the machine so far: processor time (all, and
// the kernel's share), page faults, and the times it gave up its core
// (waiting) or had it taken (preempted); and the host's steal.
struct ThreadUse {
  double cpuMs = 0.0, systemMs = 0.0;
  long faults = 0, waits = 0, preemptions = 0;
  double stealMs = 0.0;

  static ThreadUse now() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    rusage r{};
    getrusage(RUSAGE_THREAD, &r);
    return {t.tv_sec * 1e3 + t.tv_nsec * 1e-6,
            r.ru_stime.tv_sec * 1e3 + r.ru_stime.tv_usec * 1e-3,
            r.ru_minflt + r.ru_majflt,
            r.ru_nvcsw,
            r.ru_nivcsw,
            hostStealMs()};
  }
};

// When a frame took its input, was built, drawn and shown, and with
// --frame-log the UI thread's use of the machine before and after it.
struct FrameMoments {
  Clock::time_point input, built, drawn, end;
  ThreadUse useStart, useEnd;
};

// What --frame-log has printed: the renders whose first and exact images
// it reported, and when the frames began.
struct FrameLogState {
  Clock::time_point start = Clock::now();
  std::uint64_t firstShownJob = 0, exactShownJob = 0;
};

// --frame-log: each frame's parts and when it ended (ms from the first
// frame), whether it showed a render's first image (a new camera's, while
// orbiting), and once per render when its exact image reached the texture.
void logFrame(ViewerApp& app, const FrameMoments& m, bool presented, bool rendering,
              FrameLogState& log) {
  const ShownTimes& shown = app.display().shownTimes();
  const ProgressiveStatus s = app.display().status();
  const bool firstShown = shown.firstImageMs >= 0 && s.job != log.firstShownJob;
  if (firstShown) log.firstShownJob = s.job;
  const ThreadUse& a = m.useStart;
  const ThreadUse& b = m.useEnd;
  std::fprintf(stderr,
               "frame %.1f ms: ui %.1f, draw %.1f, present %.1f, ui thread cpu %.1f (kernel %.1f; "
               "%ld page faults, %ld waits, %ld preemptions), host steal %.0f, at %.1f%s%s%s\n",
               msBetween(m.input, m.end), msBetween(m.input, m.built), msBetween(m.built, m.drawn),
               msBetween(m.drawn, m.end), b.cpuMs - a.cpuMs, b.systemMs - a.systemMs,
               b.faults - a.faults, b.waits - a.waits, b.preemptions - a.preemptions,
               b.stealMs - a.stealMs, msBetween(log.start, m.end), presented ? "" : ", not presented",
               rendering ? ", while rendering" : "", firstShown ? ", shows a first image" : "");
  if (shown.exactImageMs < 0 || s.job == log.exactShownJob) return;
  log.exactShownJob = s.job;
  std::fprintf(stderr,
               "render %s: first image %.1f ms, exact image %.1f ms after asked for; "
               "its first pass %.1f ms, exact pass %.1f ms after it started\n",
               app.state().session.file().filename().c_str(), shown.firstImageMs,
               shown.exactImageMs, s.firstCoarseMs, s.exactMs);
}
}  // namespace

void runFrames(ViewerApp& app, const FrameHost& host, WakeFlag& handedOver) {
  Clock::time_point lastInput = Clock::now() - std::chrono::seconds(1);
  FrameLogState log;
  // The log's times count from here; this line places that zero on the
  // system's monotonic clock (steady_clock is CLOCK_MONOTONIC on Linux), so
  // that a frame can be matched with what another process recorded then.
  if (app.state().options.frameLog)
    std::fprintf(stderr, "log times count from %.1f ms of CLOCK_MONOTONIC\n",
                 std::chrono::duration<double, std::milli>(log.start.time_since_epoch()).count());
  bool presented = true;
  while (host.keepRunning()) {
    if (presented && !app.display().imageWaiting())
      handedOver.waitUntil(lastInput + kShortestFrame);
    host.waitForInput(app.waitBeforeNextFrameMs(lastInput));
    FrameMoments m;
    lastInput = m.input = Clock::now();
    const bool frameLog = app.state().options.frameLog;
    if (frameLog) m.useStart = ThreadUse::now();
    app.display().frameBegins();
    const auto [width, height] = host.beginFrame();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    app.frame(m.input);
    ImGui::Render();
    m.built = m.drawn = Clock::now();
    presented = app.shouldPresent();
    if (presented) {
      drawFrame(app, width, height);
      m.drawn = Clock::now();
      host.present();
    }
    app.display().frameEnds();
    m.end = Clock::now();
    if (frameLog) m.useEnd = ThreadUse::now();
    const bool rendering = app.frameDone(msBetween(m.input, m.end));
    if (frameLog) logFrame(app, m, presented, rendering, log);
  }
}

}  // namespace meshtrace::viewer
