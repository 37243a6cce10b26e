#include "viewer/model/options.h"

#include <CLI/CLI.hpp>

namespace meshtrace::viewer {

std::optional<ViewerOptions> parseOptions(int argc, char** argv, int& exitCode) {
  CLI::App cli{"meshtrace viewer: browse scenes, watch them render, inspect every pixel."};
  ViewerOptions o;
  std::string size, view = "color", overlay = "none", pin;
  std::vector<std::string> shading;
  cli.add_option("scene", o.scene, "Scene to open (.sce)");
  cli.add_flag("--headless", o.headless, "Render the window offscreen through OSMesa (no display)");
  cli.add_option("--snapshot", o.snapshot,
                 "Headless: write the whole window to this PNG once the render is done");
  cli.add_option("--size", size, "Window size WxH (default 1280x800)");
  cli.add_option(
      "--view", view,
      "color, normals, depth, object, triangle, boxes, cost, deviation, side-by-side, difference");
  cli.add_option("--overlay", overlay, "Heat map over the image: none, boxes, cost");
  cli.add_option("--opacity", o.overlayOpacity, "Overlay opacity 0..1")
      ->check(CLI::Range(0.0, 1.0));
  cli.add_option("--pin", pin, "Pin the inspector on image pixel X,Y (y = 0 the bottom row)");
  cli.add_option("--shading", shading, "MESH=FLAT|PHONG, MESH a mesh name (file stem) or index")
      ->allow_extra_args(false);
  cli.add_option("--hide", o.hide, "Hide a mesh (name or index)")->allow_extra_args(false);
  cli.add_option("--aa", o.extraSamples, "Anti-aliasing samples per pixel after the exact image")
      ->check(CLI::Range(0, 256));
  cli.add_option("--scenes", o.sceneDirs, "Extra folder of scenes for the list")
      ->allow_extra_args(false);
  cli.add_flag("--no-default-dirs", o.noDefaultDirs,
               "Do not list scenes/ and ../shared/seed/scenes");
  cli.add_option("--open", o.open, "Panels to open: camera, normals, compare, save")
      ->allow_extra_args(false);
  cli.add_option("--reference", o.reference, "Reference image to compare with");
  cli.add_option("--accel", o.accel, "Acceleration: none, aabb or bvh")->capture_default_str();
  cli.add_option("--threads", o.threads, "Render threads (0: all cores)")
      ->check(CLI::NonNegativeNumber);
  cli.add_option("--worker-nice", o.workerNice, "Lower the render threads' priority by N (0-19)")
      ->check(CLI::Range(0, 19));
  cli.add_flag("--hide-timings", o.hideTimings,
               "Show timing figures as '-' (for stable snapshots)");
  cli.add_flag("--stats", o.stats, "Print load, first image, exact image and frame times");
  cli.add_flag("--frame-log", o.frameLog,
               "Print each frame's duration, and when each render's images reach the texture, "
               "to stderr");
  cli.add_flag("--time-opening", o.timeOpening,
               "Headless: open every listed scene in turn, as a drop would, and print the time "
               "from opening to its first and its exact image in the texture");
  cli.add_option("--timeout", o.timeoutSeconds, "Headless: seconds to wait for the render");
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    exitCode = cli.exit(e);
    return std::nullopt;
  }
  const auto fail = [&](const std::string& message) -> std::optional<ViewerOptions> {
    std::fprintf(stderr, "error: %s\n", message.c_str());
    exitCode = 2;
    return std::nullopt;
  };
  if (!size.empty() && std::sscanf(size.c_str(), "%dx%d", &o.width, &o.height) != 2)
    return fail("--size expects WxH, got '" + size + "'");
  if (o.width < 320 || o.height < 240 || o.width > 8192 || o.height > 8192)
    return fail("--size must be between 320x240 and 8192x8192");
  if (const auto v = parseView(view))
    o.view = *v;
  else
    return fail("unknown view '" + view + "'");
  if (const auto v = parseOverlay(overlay))
    o.overlay = *v;
  else
    return fail("unknown overlay '" + overlay + "'");
  if (!pin.empty()) {
    int x, y;
    if (std::sscanf(pin.c_str(), "%d,%d", &x, &y) != 2)
      return fail("--pin expects X,Y, got '" + pin + "'");
    o.pin = {x, y};
  }
  for (const std::string& s : shading) {
    const auto eq = s.find('=');
    const std::string mode = eq == std::string::npos ? "" : s.substr(eq + 1);
    try {
      o.shading.emplace_back(s.substr(0, eq), parseShading(mode));
    } catch (const std::invalid_argument&) {
      return fail("--shading expects MESH=FLAT|PHONG, got '" + s + "'");
    }
  }
  if (o.headless && o.snapshot.empty() && !o.timeOpening)
    return fail("--headless needs --snapshot OUT.png or --time-opening");
  if (o.timeOpening && !o.headless) return fail("--time-opening needs --headless");
  exitCode = 0;
  return o;
}

}  // namespace meshtrace::viewer
