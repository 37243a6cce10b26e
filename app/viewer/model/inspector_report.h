#pragma once
// The inspector's account of one pixel as data: what inspectPixel records,
// worded for people, line by line. The inspector panel draws it in a
// scrolling pane and --describe writes it whole, so what the pane shows and
// what the tests read come from the same words, whichever lines the pane
// has scrolled out of view.
#include <functional>
#include <string>
#include <vector>

#include "meshtrace/render/inspect.h"

namespace meshtrace::viewer {

enum class LineTone {
  Plain,
  Dim,    // what does not apply: FLAT shading, a light behind the surface
  Alert,  // a shadowed light
};

struct InspectorLine {
  std::string lead;  // plain text before `text` on the same line, if any
  std::string text;
  LineTone tone = LineTone::Plain;
  bool bullet = false;  // an item of the list the line before begins
};

// A ray of the pixel's tree: the primary ray or a reflection bounce.
struct InspectorBounce {
  std::string title;  // "primary ray", "reflection 1 (weight 0.400)"
  std::vector<InspectorLine> lines;
};

struct InspectorReport {
  std::string pixel;  // "pixel (150, 70) pinned  y = 0 is the bottom row"
  Color color;        // shown as a swatch before `summary`
  std::string summary;
  std::vector<InspectorBounce> bounces;
};

// `describe` names what a ray hit ("mesh 'ball' #0"); (x, y) is the image
// pixel, y = 0 the bottom row.
InspectorReport inspectorReport(const PixelInspection& inspection, int x, int y, bool pinned,
                                const std::function<std::string(const PrimitiveRef&)>& describe);

// The whole report as text, a line each, a bounce's lines indented under
// its title.
std::string reportText(const InspectorReport& report);

}  // namespace meshtrace::viewer
