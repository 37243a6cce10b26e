// The viewer's layout without a window: the inspector's words as data (what
// its pane draws and --describe writes), lines broken only at spaces, and
// the panes' heights.
#include <gtest/gtest.h>

#include <sstream>

#include "meshtrace/io/scene_parser.h"
#include "meshtrace/render/render.h"
#include "support/files.h"
#include "support/paths.h"
#include "viewer/model/inspector_report.h"
#include "viewer/model/line_breaks.h"
#include "viewer/model/pane_heights.h"
#include "viewer/model/pixel_readout.h"

namespace meshtrace::viewer {
namespace {

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(InspectorReport, GivesEachBounceItsLinesAndWritesThemAllOneALine) {
  // A mirror faced by the camera, a light behind a sphere: a reflection and
  // a shadowed light.
  const Scene scene = parseScene(
      "camera 0 0 5  0 0 0  0 1 0  45  2 2\ndepth 1\n"
      "light 0 3 3  1 1 1\nlight 3 0 3  1 1 1\n"
      "plane 0 0 0  0 0 1  0.1 0.1 0.1  0.5 0.5 0.5  0 0 0  1 0.5\n"
      "sphere 0 1.5 1.5 0.3  0.1 0.1 0.1  0.5 0.5 0.5  0 0 0  1 0\n",
      "report.sce");
  const SceneIntersector intersector(scene, TraceOptions{});
  const PixelInspection in = inspectPixel(intersector, Camera(scene.camera), 1.0, 1.0);
  const InspectorReport r = inspectorReport(in, 1, 1, true, [](const PrimitiveRef& ref) {
    return ref.kind == ObjectKind::Sphere ? std::string("the sphere") : std::string("the mirror");
  });
  EXPECT_EQ(r.pixel, "pixel (1, 1) pinned  y = 0 is the bottom row");
  ASSERT_EQ(r.bounces.size(), 2u);
  EXPECT_EQ(r.bounces[0].title, "primary ray");
  EXPECT_EQ(r.bounces[1].title, "reflection 1 (weight 0.500)");
  int shadowed = 0;
  for (const InspectorLine& line : r.bounces[0].lines)
    if (line.tone == LineTone::Alert) {
      ++shadowed;
      EXPECT_EQ(line.lead.rfind("light 0  n.l", 0), 0u) << line.lead;
      EXPECT_EQ(line.text.rfind("shadowed by the sphere at t ", 0), 0u) << line.text;
    }
  EXPECT_EQ(shadowed, 1);

  const std::vector<std::string> text = linesOf(reportText(r));
  std::size_t expected = 2;
  for (const InspectorBounce& b : r.bounces) expected += 1 + b.lines.size();
  ASSERT_EQ(text.size(), expected) << reportText(r);
  EXPECT_EQ(text[0], r.pixel);
  EXPECT_EQ(text[1], r.summary);
  EXPECT_EQ(text[2], "> primary ray");
  EXPECT_EQ(text[3 + r.bounces[0].lines.size()], "> reflection 1 (weight 0.500)");
  EXPECT_EQ(text.back(), "    " + r.bounces[1].lines.back().text);
}

TEST(LineBreaks, BreakOnlyAtSpacesAndFitTheWidth) {
  const auto measure = [](const std::string& s) { return 7.0f * s.size(); };
  const std::string line = "ray direction  (-0.23415, 0.02705, -0.97182)";
  EXPECT_EQ(breakAtSpaces(line, 1000, 1000, measure), std::vector<std::string>{line});
  const std::vector<std::string> pieces = breakAtSpaces(line, 7 * 20, 7 * 12, measure);
  EXPECT_EQ(pieces,
            (std::vector<std::string>{"ray direction", "(-0.23415,", "0.02705,", "-0.97182)"}));
  EXPECT_EQ(breakAtSpaces("colour (0.25, 0.34)  rays: 4 shadow", 7 * 22, 7 * 30, measure),
            (std::vector<std::string>{"colour (0.25, 0.34)", "rays: 4 shadow"}));
  EXPECT_EQ(breakAtSpaces("   diffuse (0.0908, 0.2270)", 7 * 20, 7 * 20, measure),
            (std::vector<std::string>{"   diffuse (0.0908,", "0.2270)"}))
      << "leading spaces are kept";
  EXPECT_EQ(breakAtSpaces("averyveryverylongword", 7 * 5, 7 * 5, measure),
            std::vector<std::string>{"averyveryverylongword"});
  EXPECT_EQ(breakAtSpaces("", 10, 10, measure), std::vector<std::string>{""});
}

TEST(LineBreaks, FieldsBreakBetweenThemNeverInside) {
  const auto measure = [](const std::string& s) { return 7.0f * s.size(); };
  const std::vector<std::string> fields{"load 9.1 ms", "first image 71.0 ms", "exact 584.5 ms"};
  EXPECT_EQ(breakBetweenFields(fields, "  ", 1000, measure),
            std::vector<std::string>{"load 9.1 ms  first image 71.0 ms  exact 584.5 ms"});
  EXPECT_EQ(breakBetweenFields(fields, "  ", 7 * 34, measure),
            (std::vector<std::string>{"load 9.1 ms  first image 71.0 ms", "exact 584.5 ms"}));
  EXPECT_EQ(breakBetweenFields(fields, "  ", 7 * 12, measure), fields)
      << "a field wider than the line stands alone";
  EXPECT_EQ(breakBetweenFields({}, "  ", 10, measure), std::vector<std::string>{""});
}

TEST(LineBreaks, ANameTooWideIsCutShortWithDots) {
  const auto measure = [](const std::string& s) { return 7.0f * s.size(); };
  EXPECT_EQ(elide("icosphere", 7 * 9, measure), "icosphere");
  EXPECT_EQ(elide("icosphere", 7 * 8, measure), "icosp...");
  EXPECT_EQ(elide("icosphere", 7 * 2, measure), "i...") << "its first letter at least";
  EXPECT_EQ(elide("\xc3\xa9t\xc3\xa9-mesh", 7 * 6, measure), "\xc3\xa9t...")
      << "never inside a UTF-8 character";
}

TEST(PaneHeights, TheInspectorFillsItsRoomUnlessDraggedAndNeverVanishes) {
  EXPECT_EQ(paneHeight(0, 300), 300);
  EXPECT_EQ(paneHeight(150, 300), 150);
  EXPECT_EQ(paneHeight(500, 300), 500) << "a dragged height is kept; the panel scrolls";
  EXPECT_EQ(paneHeight(0, 20), kMinPane);
  EXPECT_EQ(paneHeight(10, 300), kMinPane);
}

TEST(PaneHeights, TheSceneListLeavesTheObjectsListItsRoomAndKeepsAShare) {
  // Short: as long as its content.
  EXPECT_EQ(sceneListHeight(0, 120, 600, 150), 120);
  // Long: all but the Objects list's room ...
  EXPECT_EQ(sceneListHeight(0, 900, 600, 150), 450);
  // ... but never less than its share, however long the Objects list.
  EXPECT_EQ(sceneListHeight(0, 900, 600, 500), kSceneListShare * 600);
  // Dragged: as dragged, leaving the Objects list at least kMinPane.
  EXPECT_EQ(sceneListHeight(200, 900, 600, 150), 200);
  EXPECT_EQ(sceneListHeight(800, 900, 600, 150), 600 - kMinPane);
  EXPECT_EQ(sceneListHeight(0, 900, 100, 150), kMinPane) << "never vanishes";
  EXPECT_EQ(sceneListHeight(0, 30, 100, 150), 30);
}

// Face 0 is a triangle out of view, face 1 an L (four triangles), face 2 a
// triangle: triangle 5. The middle row sees y = 1; a unit is 100 / (10 tan
// 10 deg) = 56.7 pixels either side of x = 1.5 at column 150: column 93
// sees x = 0.5, in the L's upright, column 195 x = 2.3, in the last
// triangle.
Scene sceneWithAnL() {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "l.off",
                  "OFF\n11 3 0\n50 50 0\n51 50 0\n50 51 0\n"
                  "0 0 0\n2 0 0\n2 1 0\n1 1 0\n1 2 0\n0 2 0\n"
                  "3 1 0\n2 2 0\n"
                  "3 0 1 2\n6 3 4 5 6 7 8\n3 4 9 10\n");
  return loadScene(
      test::writeFile(dir / "l.sce",
                      "camera 1.5 1 10  1.5 1 0  0 1 0  20  300 200\nlight 1 1 10  1 1 1\n"
                      "mesh l.off FLAT  0.1 0.1 0.1  0.5 0.5 0.5  0 0 0  1 0\n"));
}

// A polygon's triangles are numbered apart from the file's faces: the
// inspector names the face a hit triangle was cut from, so that the user
// can find it in the file.
TEST(InspectorReport, NamesTheFaceOfTheFileATriangleWasCutFrom) {
  const Scene scene = sceneWithAnL();
  const SceneIntersector intersector(scene, TraceOptions{});
  const auto triangleLine = [&](double x, double y) {
    const PixelInspection in = inspectPixel(intersector, Camera(scene.camera), x, y);
    const InspectorReport r =
        inspectorReport(in, 0, 0, true, [](const PrimitiveRef&) { return std::string("l"); });
    for (const InspectorLine& line : r.bounces.at(0).lines)
      if (line.text.rfind("triangle", 0) == 0) return line.text;
    return std::string("no triangle line");
  };
  const std::string inL = triangleLine(93.0, 100.0);
  EXPECT_NE(inL.find("of face 1 (6 corners)"), std::string::npos) << inL;
  EXPECT_EQ(triangleLine(195.0, 100.0), "triangle      5 (face 2)");
}

// The readout under the image names the face as the inspector does.
TEST(PixelReadout, NamesTheFaceOfTheFileATriangleWasCutFrom) {
  const auto scene = std::make_shared<const Scene>(sceneWithAnL());
  const PreparedScene prepared(scene, TraceOptions{});
  const auto triangleField = [&](int x, int y) {
    const PixelReadout r =
        readPixel(prepared, Camera(scene->camera), ProgressiveFrame{}, x, y, FalseColorScales{});
    for (const std::string& f : readoutFields(r, [](const PixelProbe&) { return "l"; }))
      if (f.rfind("triangle", 0) == 0) return f;
    return std::string("no triangle field");
  };
  const std::string inL = triangleField(93, 100);
  EXPECT_NE(inL.find("of face 1 (6 corners)"), std::string::npos) << inL;
  EXPECT_EQ(triangleField(195, 100), "triangle 5 (face 2)");
}

}  // namespace
}  // namespace meshtrace::viewer
