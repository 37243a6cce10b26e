#include "viewer/model/options.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdlib>

#include "viewer/model/image_viewport.h"

namespace meshtrace::viewer {

namespace {
std::string panelList() {
  std::string list;
  for (const char* p : kPanels) list += (list.empty() ? "" : ", ") + std::string(p);
  return list;
}
}  // namespace

std::string versionLine() { return std::string("meshtrace viewer ") + MESHTRACE_VERSION; }

std::optional<ViewerOptions> parseOptions(int argc, char** argv, int& exitCode) {
  CLI::App cli{"meshtrace viewer: browse scenes, watch them render, inspect every pixel."};
  cli.set_version_flag("--version", versionLine());
  ViewerOptions o;
  std::vector<std::string> draw, bShading;
  std::string bTriangle, bPrecision, abMode = "a";
  std::string bvhLevel = "triangles";
  std::string size, view = "color", overlay = "none", pin, zoom = "fit", accel = "bvh",
                    triangle = "watertight", precision = "double";
  std::vector<std::string> shading;
  cli.add_option("scene", o.scene,
                 "Scene to open (.sce), or a mesh file, framed as raytrace frames it");
  cli.add_flag("--headless", o.headless, "Render the window offscreen through OSMesa (no display)");
  cli.add_option("--snapshot", o.snapshot,
                 "Headless: write the whole window to this PNG once the render is done");
  cli.add_option("--size", size,
                 "Window size WxH (default 1280x800, made smaller to fit the screen)");
  cli.add_option(
      "--view", view,
      "color, normals, depth, object, triangle, boxes, cost, deviation, side-by-side, difference");
  cli.add_option("--overlay", overlay, "Heat map over the image: none, boxes, cost");
  cli.add_option("--opacity", o.overlayOpacity, "Overlay opacity 0..1")
      ->check(CLI::Range(0.0, 1.0));
  cli.add_option("--pin", pin, "Pin the inspector on image pixel X,Y (y = 0 the bottom row)");
  cli.add_option("--zoom", zoom,
                 "Image zoom: fit, or screen pixels per image pixel (1/16 to 64), about the "
                 "pinned pixel if any")
      ->capture_default_str();
  cli.add_option("--draw", draw,
                 "Draw over the image, for the pinned pixel: rays (its ray tree, the default), "
                 "boxes (mesh boxes entered), nodes (BVH nodes entered), cut (a BVH level at "
                 "--bvh-depth), none")
      ->delimiter(',')
      ->allow_extra_args(false);
  cli.add_option("--bvh-level", bvhLevel, "The BVH level of --draw cut: objects or triangles")
      ->capture_default_str();
  cli.add_option("--bvh-depth", o.draw.depth, "The depth of --draw cut (the level's root at 0)")
      ->check(CLI::NonNegativeNumber);
  cli.add_flag("--observer", o.observer,
               "Show the scene from the observer camera, with the main camera's frustum");
  cli.add_option("--b-shading", bShading,
                 "Render B with MESH=FLAT|PHONG first and keep it, then A without (A/B)")
      ->allow_extra_args(false);
  cli.add_option("--b-triangle", bTriangle, "Render B with this triangle test first (A/B)");
  cli.add_option("--b-precision", bPrecision, "Render B with this precision first (A/B)");
  cli.add_option("--ab", abMode,
                 "Show A, B, their wipe or their difference: a, b, wipe, difference")
      ->capture_default_str();
  cli.add_option("--wipe", o.wipe, "Where the wipe's line is, 0 (all B) to 1 (all A)")
      ->check(CLI::Range(0.0, 1.0));
  cli.add_option("--shading", shading, "MESH=FLAT|PHONG, MESH a mesh name (file stem) or index")
      ->allow_extra_args(false);
  cli.add_option("--hide", o.hide, "Hide a mesh (name or index)")->allow_extra_args(false);
  cli.add_option("--aa", o.extraSamples, "Anti-aliasing samples per pixel after the exact image")
      ->check(CLI::Range(0, 256));
  cli.add_option("--scenes", o.sceneDirs, "Extra folder of scenes for the list")
      ->allow_extra_args(false);
  cli.add_flag("--no-default-dirs", o.noDefaultDirs,
               "Do not list scenes/ and ../shared/seed/scenes");
  cli.add_option("--open", o.open, "Panels to open: " + panelList())->allow_extra_args(false);
  cli.add_option("--reference", o.reference, "Reference image to compare with");
  cli.add_option("--accel", accel, "Acceleration: none, aabb or bvh")->capture_default_str();
  cli.add_option("--triangle", triangle, "Triangle test: watertight, cramer or mt")
      ->capture_default_str();
  cli.add_option("--precision", precision, "Arithmetic of the triangle test: double or single")
      ->capture_default_str();
  cli.add_option("--threads", o.threads, "Render threads (0: all cores)")
      ->check(CLI::NonNegativeNumber);
  cli.add_option("--worker-nice", o.workerNice,
                 "The render threads' nice value, 0-19: above 0 they yield to the UI thread")
      ->capture_default_str()
      ->check(CLI::Range(0, 19));
  cli.add_flag("--hide-timings", o.hideTimings,
               "Show timing figures as '-' (for stable snapshots)");
  cli.add_flag("--stats", o.stats, "Print load, first image, exact image and frame times");
  cli.add_flag("--frame-log", o.frameLog,
               "Print each frame's duration and the UI thread's use of the machine in it, and "
               "when each render's images reach the texture, to stderr");
  cli.add_flag("--time-opening", o.timeOpening,
               "Headless: open every listed scene in turn, as a drop would, and print the time "
               "from opening to its first and its exact image in the texture");
  cli.add_flag("--quit-when-done", o.quitWhenDone,
               "Close the window once the scene is rendered and nothing runs in the background "
               "(for timing scripts)");
  cli.add_option("--timeout", o.timeoutSeconds, "Headless: seconds to wait for the render");
  cli.add_option("--describe", o.describe,
                 "Headless: write the text the last frame shows, and where its image, plot and "
                 "legends are, to this file (for tests)");
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
  o.sizeGiven = !size.empty();
  if (o.sizeGiven && std::sscanf(size.c_str(), "%dx%d", &o.width, &o.height) != 2)
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
  try {
    o.trace.accel = parseAccelMethod(accel);
    o.trace.triangle.test = parseTriangleTest(triangle);
    o.trace.triangle.precision = parsePrecision(precision);
  } catch (const std::invalid_argument& e) {
    return fail(e.what());
  }
  for (const std::string& panel : o.open)
    if (std::find_if(std::begin(kPanels), std::end(kPanels),
                     [&](const char* p) { return panel == p; }) == std::end(kPanels))
      return fail("--open: no panel '" + panel + "' (panels: " + panelList() + ")");
  if (zoom != "fit") {
    char* end = nullptr;
    const double z = std::strtod(zoom.c_str(), &end);
    if (end == zoom.c_str() || *end ||
        !(z >= ImageViewport::kMinZoom && z <= ImageViewport::kMaxZoom))
      return fail("--zoom expects fit or a number from 0.0625 to 64, got '" + zoom + "'");
    o.zoom = z;
  }
  if (!draw.empty()) {
    o.draw.rays = false;
    for (const std::string& d : draw) {
      if (d == "rays")
        o.draw.rays = true;
      else if (d == "boxes")
        o.draw.meshBoxes = true;
      else if (d == "nodes")
        o.draw.nodes = true;
      else if (d == "cut")
        o.draw.cut = true;
      else if (d != "none")
        return fail("--draw: no '" + d + "' to draw (rays, boxes, nodes, cut or none)");
    }
  }
  if (bvhLevel == "objects")
    o.draw.level = BvhLevel::Objects;
  else if (bvhLevel != "triangles")
    return fail("--bvh-level expects objects or triangles, got '" + bvhLevel + "'");
  o.depthGiven = cli.count("--bvh-depth") > 0;
  const auto meshModes = [&](const char* option, const std::vector<std::string>& given,
                             std::vector<std::pair<std::string, Shading>>& out) {
    for (const std::string& s : given) {
      const auto eq = s.find('=');
      const std::string mode = eq == std::string::npos ? "" : s.substr(eq + 1);
      try {
        out.emplace_back(s.substr(0, eq), parseShading(mode));
      } catch (const std::invalid_argument&) {
        fail(std::string(option) + " expects MESH=FLAT|PHONG, got '" + s + "'");
        return false;
      }
    }
    return true;
  };
  if (!meshModes("--shading", shading, o.shading) ||
      !meshModes("--b-shading", bShading, o.bShading))
    return std::nullopt;
  try {
    if (!bTriangle.empty() || !bPrecision.empty()) {
      o.bTrace = o.trace;
      if (!bTriangle.empty()) o.bTrace->triangle.test = parseTriangleTest(bTriangle);
      if (!bPrecision.empty()) o.bTrace->triangle.precision = parsePrecision(bPrecision);
    }
  } catch (const std::invalid_argument& e) {
    return fail(e.what());
  }
  if (const auto m = parseAbMode(abMode))
    o.abMode = *m;
  else
    return fail("--ab expects a, b, wipe or difference, got '" + abMode + "'");
  if (o.headless && o.snapshot.empty() && !o.timeOpening)
    return fail("--headless needs --snapshot OUT.png or --time-opening");
  if (o.timeOpening && !o.headless) return fail("--time-opening needs --headless");
  exitCode = 0;
  return o;
}

}  // namespace meshtrace::viewer
