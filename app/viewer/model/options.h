#pragma once
// The viewer's command line.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "meshtrace/geometry/mesh.h"
#include "viewer/model/views.h"

namespace meshtrace::viewer {

struct ViewerOptions {
  std::string scene;  // optional .sce to open
  bool headless = false;
  std::string snapshot;            // PNG of the whole window (headless)
  int width = 1280, height = 800;  // window size
  View view = View::Color;
  Overlay overlay = Overlay::None;
  double overlayOpacity = 0.6;
  std::optional<std::pair<int, int>> pin;                // image pixel, y = 0 the bottom row
  std::vector<std::pair<std::string, Shading>> shading;  // mesh (name or index) -> its mode
  std::vector<std::string> hide;                         // meshes to hide (name or index)
  int extraSamples = 0;  // anti-aliasing samples per pixel beyond the exact one
  std::vector<std::string> sceneDirs;
  bool noDefaultDirs = false;
  std::vector<std::string> open;  // panels to open: camera, normals, compare, save
  std::string reference;          // reference image to compare with
  std::string accel = "bvh";
  int threads = 0;
  int workerNice = 0;             // > 0: render threads yield to the UI thread
  bool hideTimings = false;       // timing figures as "-" (stable snapshots)
  bool stats = false;             // print timing figures on exit
  bool frameLog = false;          // print each frame's duration (UI and GL parts)
  bool timeOpening = false;       // headless: open each listed scene in turn, print its times
  double timeoutSeconds = 600.0;  // headless: give up waiting for the render
};

// Parses argv; returns an exit code in `exitCode` when the program should
// stop (help, or an error already printed).
std::optional<ViewerOptions> parseOptions(int argc, char** argv, int& exitCode);

}  // namespace meshtrace::viewer
