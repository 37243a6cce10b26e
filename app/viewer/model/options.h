#pragma once
// The viewer's command line.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "meshtrace/accel/trace_options.h"
#include "meshtrace/geometry/mesh.h"
#include "meshtrace/render/inspect.h"
#include "viewer/model/ab_compare.h"
#include "viewer/model/background_priority.h"
#include "viewer/model/views.h"

namespace meshtrace::viewer {

// What is drawn over the image for the pinned pixel, and the BVH cut.
struct DrawOptions {
  bool rays = true;        // its ray tree: primary ray, bounces, shadow rays
  bool meshBoxes = false;  // the mesh boxes its primary ray entered
  bool nodes = false;      // the BVH nodes its primary ray entered
  bool cut = false;        // every node of a BVH level at a depth
  BvhLevel level = BvhLevel::Triangles;
  int depth = 2;
};

struct ViewerOptions {
  std::string scene;  // optional .sce to open
  bool headless = false;
  std::string snapshot;  // PNG of the whole window (headless)
  // The window's size: exactly this with --size (sizeGiven), else at most
  // this, fitted to the screen (window_fit.h); headless, always this.
  int width = 1280, height = 800;
  bool sizeGiven = false;
  View view = View::Color;
  Overlay overlay = Overlay::None;
  double overlayOpacity = 0.6;
  std::optional<std::pair<int, int>> pin;  // image pixel, y = 0 the bottom row
  std::optional<double> zoom;              // image zoom (screen pixels per image pixel); unset: fit
  DrawOptions draw;
  bool depthGiven = false;  // --bvh-depth was given: it must exist in the scene's BVH
  bool observer = false;    // show the scene from the observer camera
  // A/B from the command line: B is rendered first with these changes to
  // the other settings and kept, then A with the other settings alone.
  std::vector<std::pair<std::string, Shading>> bShading;
  std::optional<TraceOptions> bTrace;
  AbMode abMode = AbMode::A;
  float wipe = 0.5f;
  bool keepB() const { return !bShading.empty() || bTrace.has_value(); }
  std::vector<std::pair<std::string, Shading>> shading;  // mesh (name or index) -> its mode
  std::vector<std::string> hide;                         // meshes to hide (name or index)
  int extraSamples = 0;  // anti-aliasing samples per pixel beyond the exact one
  std::vector<std::string> sceneDirs;
  bool noDefaultDirs = false;
  std::vector<std::string> open;  // panels to open (kPanels)
  std::string reference;          // reference image to compare with
  TraceOptions trace;             // --accel, --triangle, --precision
  int threads = 0;
  // Render threads' nice value: > 0, they yield to the UI thread (and,
  // within the viewer's autogroup, to nothing else; background_priority.h).
  int workerNice = kBackgroundNice;
  bool hideTimings = false;       // timing figures as "-" (stable snapshots)
  bool stats = false;             // print timing figures on exit
  bool frameLog = false;          // print each frame's duration (UI and GL parts)
  bool timeOpening = false;       // headless: open each listed scene in turn, print its times
  bool quitWhenDone = false;      // window: close once the scene is rendered (timing scripts)
  double timeoutSeconds = 600.0;  // headless: give up waiting for the render
  std::string describe;           // headless: write the last frame's text and regions here
};

// The panels --open names.
inline constexpr const char* kPanels[] = {"camera", "normals", "compare", "save", "draw", "ab"};

// "meshtrace viewer 0.1.0": the project's version (the top-level CMake
// project()), for --version and Help > About.
std::string versionLine();

// Parses argv; returns an exit code in `exitCode` when the program should
// stop (help, --version, or an error already printed).
std::optional<ViewerOptions> parseOptions(int argc, char** argv, int& exitCode);

}  // namespace meshtrace::viewer
