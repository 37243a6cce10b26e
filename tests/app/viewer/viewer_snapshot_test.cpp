// Headless snapshots of the whole viewer window (OSMesa). Each run also
// writes --describe: the text the window shows and where its image, plot
// and legend are. The tests assert that content, against figures computed
// here where they can be (a legend runs to the most boxes any ray meets, a
// readout gives the probe's depth, the image at 1:1 holds the pixels
// `raytrace` writes, the plot and the drawn rays have pixels of their
// colours); the picture is also compared with a stored PNG, a guard
// against changes nobody looked at. To store new ones:
// MESHTRACE_UPDATE_SNAPSHOTS=1, then look at every file.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>

#include "meshtrace/io/image.h"
#include "meshtrace/io/scene_parser.h"
#include "meshtrace/render/inspect.h"
#include "meshtrace/render/render.h"
#include "meshtrace/report/image_compare.h"
#include "support/files.h"
#include "support/paths.h"
#include "viewer/model/inspector_report.h"

namespace meshtrace {
namespace {

namespace fs = std::filesystem;

// Same software rasteriser, same fonts: snapshots agree to the pixel on one
// machine. Another Mesa build may round a few edges differently, so a little
// noise is allowed; a changed panel, text or image region is not.
constexpr double kMaxRmse = 2.0;
constexpr double kMaxFractionOver32 = 0.002;

fs::path testScenes() { return test::sourceDir() / "tests/app/viewer/scenes"; }

struct Region {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

struct Shot {
  int exitCode = -1;
  Image8 image;
  std::string text;
  std::map<std::string, Region> regions;
};

// The running test's scratch folder, emptied at its first use in the test
// only: what a test makes there stays for each of its snapshots.
fs::path shotDir() {
  static std::string test;
  static fs::path dir;
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string name = std::string(info->test_suite_name()) + "." + info->name();
  if (name != test) {
    dir = test::scratchDir();
    test = name;
  }
  return dir;
}

// Runs the headless viewer on a scene of tests/app/viewer/scenes (or a path
// relative to the source folder) and reads back what it wrote.
Shot snapshot(const std::string& name, const std::string& args,
              const std::string& scene = "tests/app/viewer/scenes/viewer_test.sce",
              const std::string& size = "1100x700") {
  const fs::path dir = shotDir();
  const fs::path png = dir / (name + ".png"), description = dir / (name + ".txt");
  // Relative paths, run from the source folder: the window shows no machine paths.
  const std::string command =
      "cd '" + test::sourceDir().string() + "' && '" MESHTRACE_VIEWER "'" + " --headless --size " +
      size + " --no-default-dirs --hide-timings --threads 2 " + args + " --snapshot '" +
      png.string() + "' --describe '" + description.string() + "' " + scene;
  Shot shot;
  const int status = std::system(command.c_str());
  shot.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (shot.exitCode != 0) return shot;
  shot.image = readImage(png);
  std::istringstream in(test::readFileBytes(description));
  std::string line;
  while (std::getline(in, line) && line != "text") {
    std::istringstream words(line);
    std::string kind, region;
    Region r;
    words >> kind >> region >> r.x0 >> r.y0 >> r.x1 >> r.y1;
    shot.regions[region] = r;
  }
  std::stringstream rest;
  rest << in.rdbuf();
  shot.text = rest.str();
  return shot;
}

void expectShows(const Shot& shot, const std::vector<std::string>& texts) {
  for (const std::string& t : texts)
    EXPECT_NE(shot.text.find(t), std::string::npos)
        << "the window should show '" << t << "'; it shows:\n"
        << shot.text;
}

// Pixels of `image` inside `r` for which `match(r, g, b)` holds.
template <typename Match>
int countPixels(const Image8& image, const Region& r, const Match& match) {
  int n = 0;
  for (int y = std::max(0, r.y0); y < std::min(image.height, r.y1); ++y)
    for (int x = std::max(0, r.x0); x < std::min(image.width, r.x1); ++x) {
      const std::uint8_t* p = &image.rgb[(static_cast<std::size_t>(y) * image.width + x) * 3];
      n += match(p[0], p[1], p[2]);
    }
  return n;
}

// Pixels inside `r` that differ between two shots by more than a little.
int changedPixels(const Shot& a, const Shot& b, const Region& r) {
  int n = 0;
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x)
      for (int k = 0; k < 3; ++k) {
        const std::size_t i = (static_cast<std::size_t>(y) * a.image.width + x) * 3 + k;
        if (std::abs(int(a.image.rgb[i]) - int(b.image.rgb[i])) > 24) {
          ++n;
          break;
        }
      }
  return n;
}

struct Snapshot {
  std::string name;
  std::string args;
  std::vector<std::string> shows;  // text the window must show
  // Regions left out of the comparison with the stored picture: figures at
  // rounding level, whose last digits any change of arithmetic moves (the
  // tests read them as text instead).
  std::vector<std::string> unstable = {};
};

// `shot` with the pixels of `r` taken from `stored`.
Image8 withRegionFrom(Image8 shot, const Image8& stored, const Region& r) {
  for (int y = std::max(0, r.y0); y < std::min({shot.height, stored.height, r.y1}); ++y)
    for (int x = std::max(0, r.x0); x < std::min({shot.width, stored.width, r.x1}); ++x)
      for (int k = 0; k < 3; ++k)
        shot.rgb[(std::size_t(y) * shot.width + x) * 3 + k] =
            stored.rgb[(std::size_t(y) * stored.width + x) * 3 + k];
  return shot;
}

class ViewerSnapshot : public ::testing::TestWithParam<Snapshot> {};

TEST_P(ViewerSnapshot, ShowsItsContentAndMatchesTheStoredImage) {
  const Snapshot& s = GetParam();
  const Shot shot = snapshot(s.name, s.args);
  ASSERT_EQ(shot.exitCode, 0);
  expectShows(shot, s.shows);
  ASSERT_TRUE(shot.regions.count("image")) << "the window shows an image";
  const fs::path stored = test::sourceDir() / "tests/app/viewer/snapshots" / (s.name + ".png");
  if (std::getenv("MESHTRACE_UPDATE_SNAPSHOTS")) {
    writeImage(shot.image, stored);
    GTEST_SKIP() << "stored " << stored << ": look at it before committing";
  }
  ASSERT_TRUE(fs::exists(stored)) << stored;
  const Image8 expected = readImage(stored);
  Image8 actual = shot.image;
  for (const std::string& region : s.unstable) {
    ASSERT_TRUE(shot.regions.count(region)) << "the window reports region " << region;
    actual = withRegionFrom(actual, expected, shot.regions.at(region));
  }
  const ImageDifference d = compareImages(actual, expected);
  std::printf("[ figures  ] %-22s RMSE %.3f  pixels off >32: %.4f%%\n", s.name.c_str(), d.rmse,
              100.0 * d.fractionOver32);
  EXPECT_LE(d.rmse, kMaxRmse) << "compare with " << stored;
  EXPECT_LE(d.fractionOver32, kMaxFractionOver32) << "compare with " << stored;
}

INSTANTIATE_TEST_SUITE_P(
    Views, ViewerSnapshot,
    ::testing::Values(
        Snapshot{"color", "", {"exact, 1 sample per pixel", "ball", "PHONG", "80 / 42"}},
        Snapshot{"normals", "--view normals", {"{ Normals } view"}},
        Snapshot{"depth", "--view depth", {"depth (t of the primary hit)"}},
        Snapshot{"object_id", "--view object", {"{ Object id } view"}},
        Snapshot{"triangle_id", "--view triangle", {"{ Triangle id } view"}},
        Snapshot{"box_hits", "--view boxes", {"mesh boxes the primary ray meets", "boxes"}},
        Snapshot{"traversal_cost", "--view cost", {"nodes + boxes + primitives tested"}},
        Snapshot{"normal_deviation",
                 "--view deviation --open normals",
                 {"vertex normal vs OpenMesh", "ball: max", "box: max"},
                 {"normals_figures"}},
        Snapshot{"heat_overlay",
                 "--overlay boxes --opacity 0.5",
                 {"{ box hits } overlay", "count of 0 clear"}},
        Snapshot{"inspector_phong",
                 "--pin 88,109",
                 {"pixel (88, 109) pinned", "mesh 'ball' #0", "interpolated", "light 1"}},
        Snapshot{"inspector_flat",
                 "--pin 88,109 --shading ball=FLAT",
                 {"FLAT: shading uses the flat normal", "[ FLAT ]"}},
        Snapshot{"reference_difference",
                 "--view difference --open compare",
                 {"RMSE", "PSNR", "RMSE of each pass against the reference"}},
        Snapshot{"camera_panel", "--open camera --hide box", {"camera 0 2.2 5.5 0 0.55 0"}},
        Snapshot{"pixel_grid", "--pin 88,109 --zoom 16", {"zoom 1600%", "depth 5.458"}},
        Snapshot{"ray_tree",
                 "--pin 150,70 --draw rays,boxes,nodes --open draw",
                 {"ray tree of the pinned pixel", "reflection 1"}},
        Snapshot{"bvh_cut", "--draw cut --bvh-depth 1 --open draw", {"boxes: nodes at depth 1"}},
        Snapshot{"observer", "--pin 150,70 --observer --open draw", {"look from the observer"}},
        Snapshot{"ab_wipe",
                 "--b-shading ball=FLAT --ab wipe --open ab",
                 {"B: ball FLAT", "A: the file's meshes", "A vs B: RMSE"}}),
    [](const auto& info) { return info.param.name; });

// The scene as the tests compute their own figures from it.
Scene testScene() { return loadScene(testScenes() / "viewer_test.sce"); }

TEST(ViewerContent, TheImageAtOneToOneHoldsThePixelsRaytraceWrites) {
  const Shot shot = snapshot("one_to_one", "--zoom 1");
  ASSERT_EQ(shot.exitCode, 0);
  const fs::path png = shotDir() / "raytrace.png";
  const std::string command = "'" MESHTRACE_RAYTRACE "' '" +
                              (testScenes() / "viewer_test.sce").string() + "' '" + png.string() +
                              "' > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0);
  const Image8 expected = readImage(png);
  const Region r = shot.regions.at("image");
  ASSERT_EQ(r.x1 - r.x0, expected.width);
  ASSERT_EQ(r.y1 - r.y0, expected.height);
  int differing = 0;
  for (int y = 0; y < expected.height; ++y)
    for (int x = 0; x < expected.width; ++x)
      for (int k = 0; k < 3; ++k)
        differing +=
            shot.image.rgb[((std::size_t(r.y0) + y) * shot.image.width + r.x0 + x) * 3 + k] !=
            expected.rgb[(std::size_t(y) * expected.width + x) * 3 + k];
  EXPECT_EQ(differing, 0);
}

// The normals check prints each mesh's largest and mean deviation from
// OpenMesh's angle-weighted normals: the two computations differ only by
// rounding (under 1e-9 degrees, a thousandth of the view's full scale),
// over every vertex of each mesh.
TEST(ViewerContent, TheNormalsCheckAgreesWithOpenMeshOverEveryVertex) {
  const Shot shot = snapshot("normal_figures", "--view deviation --open normals");
  ASSERT_EQ(shot.exitCode, 0);
  ASSERT_TRUE(shot.regions.count("normals_figures"));
  const Region r = shot.regions.at("normals_figures");
  EXPECT_GT(r.x1 - r.x0, 100);
  EXPECT_GT(r.y1 - r.y0, 10);
  const Scene scene = testScene();
  std::map<std::string, std::size_t> vertices;
  for (const Mesh& m : scene.meshes) vertices[m.file().stem().string()] = m.vertices().size();
  std::istringstream lines(shot.text);
  std::string line;
  std::size_t reported = 0;
  while (std::getline(lines, line)) {
    char name[64];
    double maxDegrees = -1.0, meanDegrees = -1.0;
    std::size_t compared = 0;
    if (std::sscanf(line.c_str(), "%63[^:]: max %lf deg, mean %lf deg over %zu vertices", name,
                    &maxDegrees, &meanDegrees, &compared) != 4)
      continue;
    ++reported;
    ASSERT_TRUE(vertices.count(name)) << line;
    EXPECT_EQ(compared, vertices[name]) << line;
    EXPECT_GE(meanDegrees, 0.0) << line;
    EXPECT_LE(meanDegrees, maxDegrees) << line;
    EXPECT_LT(maxDegrees, 1e-9) << line;
  }
  EXPECT_EQ(reported, scene.meshes.size()) << shot.text;
}

TEST(ViewerContent, TheComparePlotDrawsAPointPerPassAcrossItsWidth) {
  const Shot shot = snapshot("compare_plot", "--open compare");
  ASSERT_EQ(shot.exitCode, 0);
  expectShows(shot, {"RMSE of each pass against the reference", "pass"});
  ASSERT_TRUE(shot.regions.count("plot"));
  const Region plot = shot.regions.at("plot");
  ASSERT_GT(plot.x1 - plot.x0, 150) << "the plot fills the panel's width";
  ASSERT_LE(plot.y1, shot.image.height) << "and is in view";
  // The line's orange, in columns across most of the plot.
  std::vector<bool> columns(plot.x1 - plot.x0, false);
  const int drawn = countPixels(shot.image, plot, [](int r, int g, int b) {
    return r > 230 && g > 120 && g < 180 && b < 80;
  });
  for (int x = plot.x0; x < plot.x1; ++x)
    columns[x - plot.x0] =
        countPixels(shot.image, Region{x, plot.y0, x + 1, plot.y1}, [](int r, int g, int b) {
          return r > 230 && g > 120 && g < 180 && b < 80;
        }) > 0;
  const auto spanned = std::count(columns.begin(), columns.end(), true);
  EXPECT_GT(drawn, 100);
  EXPECT_GT(spanned, (plot.x1 - plot.x0) * 6 / 10);
}

TEST(ViewerContent, TheBoxLegendRunsToTheMostBoxesAnyPrimaryRayMeets) {
  const Scene scene = testScene();
  const SceneIntersector intersector(scene, TraceOptions{});
  int most = 0;
  for (int y = 0; y < scene.camera.height(); ++y)
    for (int x = 0; x < scene.camera.width(); ++x)
      most = std::max<int>(most, probePixel(intersector, scene.camera, x, y).boxHits);
  ASSERT_GT(most, 0);
  ASSERT_LT(most, 2) << "the test scene's boxes do not overlap in view: a scale to the number "
                        "of meshes would differ";
  const Shot shot = snapshot("box_legend", "--view boxes");
  ASSERT_EQ(shot.exitCode, 0);
  expectShows(shot, {"\n0 ", std::to_string(most) + " boxes"});
  EXPECT_EQ(shot.text.find("2 boxes"), std::string::npos) << shot.text;
}

TEST(ViewerContent, TheReadoutGivesThePinnedPixelsValuesInEveryView) {
  const Scene scene = testScene();
  const SceneIntersector intersector(scene, TraceOptions{});
  const PixelProbe p = probePixel(intersector, scene.camera, 88, 109);
  char depth[32];
  std::snprintf(depth, sizeof depth, "depth %.4g", p.depth);
  for (const char* view : {"color", "normals", "cost"}) {
    const Shot shot =
        snapshot(std::string("readout_") + view, std::string("--pin 88,109 --view ") + view);
    ASSERT_EQ(shot.exitCode, 0);
    expectShows(shot, {"pinned (88, 109)", depth, "triangle " + std::to_string(p.triangle),
                       "boxes " + std::to_string(p.boxHits), "cost " + std::to_string(p.cost)});
  }
}

TEST(ViewerContent, AWipeShowsAOnTheLeftBOnTheRightAndTheirRmse) {
  // A: the file's PHONG ball; B: the ball FLAT. Each rendered here too.
  Scene a = testScene();
  Scene b = testScene();
  b.meshes[0].setShading(Shading::Flat);
  const Image8 imageA = quantize(render(a, {})), imageB = quantize(render(b, {}));
  const ImageDifference expected = compareImages(imageA, imageB);
  ASSERT_GT(expected.rmse, 0.5);
  const Shot shot = snapshot("ab_wipe_1to1",
                             "--b-shading ball=FLAT --ab wipe --wipe 0.5 "
                             "--open ab --zoom 1");
  ASSERT_EQ(shot.exitCode, 0);
  char rmse[64];
  std::snprintf(rmse, sizeof rmse, "A vs B: RMSE %.3f", expected.rmse);
  expectShows(shot, {rmse});
  const Region r = shot.regions.at("image");
  ASSERT_EQ(r.x1 - r.x0, imageA.width);
  // Columns clear of the line (its handle reaches 8 pixels either side).
  int wrongA = 0, wrongB = 0;
  for (int y = 0; y < imageA.height; ++y)
    for (int x = 0; x < imageA.width; ++x) {
      if (std::abs(x - imageA.width / 2) <= 8 || y < 20) continue;  // the line and its labels
      const std::uint8_t* shown =
          &shot.image.rgb[((std::size_t(r.y0) + y) * shot.image.width + r.x0 + x) * 3];
      const Image8& expect = x < imageA.width / 2 ? imageA : imageB;
      const std::uint8_t* want = &expect.rgb[(std::size_t(y) * expect.width + x) * 3];
      const bool same = std::equal(shown, shown + 3, want);
      (x < imageA.width / 2 ? wrongA : wrongB) += !same;
    }
  EXPECT_EQ(wrongA, 0) << "A, the file's modes, left of the line";
  EXPECT_EQ(wrongB, 0) << "B, the ball FLAT, right of it";
}

TEST(ViewerContent, FindingsAreDrawnOverTheImageOnlyWhenAsked) {
  // Pixel (150, 70) sees the mirror box: a ray tree with a bounce.
  const Shot none = snapshot("findings_none", "--pin 150,70 --draw none");
  const Shot rays = snapshot("findings_rays", "--pin 150,70 --draw rays");
  const Shot nodes = snapshot("findings_nodes", "--pin 150,70 --draw nodes");
  const Shot cut = snapshot("findings_cut", "--draw cut --bvh-depth 1");
  for (const Shot* s : {&none, &rays, &nodes, &cut}) ASSERT_EQ(s->exitCode, 0);
  const Region image = none.regions.at("image");
  const auto magenta = [](int r, int g, int b) { return r > 230 && g < 120 && b > 230; };
  EXPECT_EQ(countPixels(none.image, image, magenta), 0);
  EXPECT_GT(countPixels(rays.image, image, magenta), 20) << "the reflection is drawn";
  EXPECT_GT(changedPixels(none, nodes, image), 200) << "the nodes entered are drawn";
  EXPECT_GT(changedPixels(none, cut, image), 200) << "the cut is drawn";
}

TEST(ViewerContent, FindingsStopAtTheImagesEdge) {
  // From (150, 70) the lit shadow rays run up and to the right, out of the
  // image: their yellow reaches its top edge and no further.
  const Shot rays = snapshot("findings_clipped", "--pin 150,70 --draw rays");
  ASSERT_EQ(rays.exitCode, 0);
  const Region image = rays.regions.at("image");
  const auto lit = [](int r, int g, int b) { return r > 230 && g > 190 && g < 240 && b < 110; };
  const int edge = countPixels(rays.image, Region{image.x0, image.y0, image.x1, image.y0 + 3}, lit);
  ASSERT_GT(edge, 0) << "a shadow ray reaches the image's top edge";
  // Above the image, the view's empty band (the toolbar ends 40 px lower
  // than the window's top).
  const Region above{image.x0, 70, image.x1, image.y0};
  ASSERT_GT(above.y1 - above.y0, 50);
  EXPECT_EQ(countPixels(rays.image, above, lit), 0);
}

TEST(ViewerContent, TheObserverShowsTheMainCamerasFrustum) {
  const Shot main = snapshot("observer_off", "--pin 150,70");
  const Shot observer = snapshot("observer_on", "--pin 150,70 --observer");
  ASSERT_EQ(main.exitCode, 0);
  ASSERT_EQ(observer.exitCode, 0);
  const Region image = observer.regions.at("image");
  const auto frustum = [](int r, int g, int b) {
    return std::abs(r - 190) < 20 && std::abs(g - 200) < 20 && b > 235;
  };
  EXPECT_LT(countPixels(main.image, image, frustum), 20);
  EXPECT_GT(countPixels(observer.image, image, frustum), 100);
}

// The text between `first` and the next panel header ("### A/B ###"), a
// line each.
std::vector<std::string> linesFrom(const std::string& text, const std::string& first) {
  std::vector<std::string> lines;
  std::istringstream in(text.substr(std::min(text.find(first), text.size())));
  for (std::string line; std::getline(in, line) && line.rfind("###", 0) != 0;)
    lines.push_back(line);
  return lines;
}

TEST(ViewerContent, TheObjectsListStaysInViewWhateverTheSceneFolders) {
  // Three folders of eight scenes and the scene's own folder: 26 rows, more
  // than the panel's height at 1280x720 and at 900x600.
  std::string folders;
  for (const char* name : {"alpha", "beta", "gamma"}) {
    const fs::path dir = shotDir() / name;
    fs::create_directories(dir);
    for (int i = 0; i < 8; ++i) test::writeFile(dir / ("scene_" + std::to_string(i) + ".sce"), "");
    folders += " --scenes '" + dir.string() + "'";
  }
  for (const char* size : {"1280x720", "900x600"}) {
    SCOPED_TRACE(size);
    const Shot shot = snapshot(std::string("folders_") + size, folders,
                               "tests/app/viewer/scenes/viewer_test.sce", size);
    ASSERT_EQ(shot.exitCode, 0);
    expectShows(shot, {"### gamma (8) ###", "scene_7.sce", "Objects", "Save scene"});
    ASSERT_TRUE(shot.regions.count("objects"));
    const Region objects = shot.regions.at("objects"), list = shot.regions.at("scene_list");
    EXPECT_LE(objects.y1, shot.image.height) << "the whole Objects list is in the window";
    EXPECT_GE(objects.y0, list.y1) << "below the scene list";
    EXPECT_GE(list.y1 - list.y0, 0.4 * (shot.image.height - list.y0))
        << "the scene list keeps a fair share";
  }
}

TEST(ViewerContent, NarrowPanelsBreakLinesBetweenFieldsAndCutLongNamesShort) {
  // The test scene with the ball under a long name.
  const fs::path dir = shotDir() / "long_name";
  fs::create_directories(dir);
  const fs::path scenes = test::sourceDir() / "tests/app/viewer/scenes";
  fs::copy_file(scenes / "box.off", dir / "box.off", fs::copy_options::overwrite_existing);
  fs::copy_file(scenes / "ball.off", dir / "a_ball_with_a_long_name.off",
                fs::copy_options::overwrite_existing);
  std::string text = test::readFileBytes(scenes / "viewer_test.sce");
  text.replace(text.find("ball.off"), 8, "a_ball_with_a_long_name.off");
  test::writeFile(dir / "long.sce", text);

  const Shot wide = snapshot("wide_panels", "", (dir / "long.sce").string(), "1280x720");
  ASSERT_EQ(wide.exitCode, 0);
  expectShows(wide,
              {"| show | mesh | shading | tris / verts |", "\nload -  first image -  exact -\n",
               "\nframes while rendering:  longest -  99% -\n"});

  // At 900x600 the counts go under each name, and the long name is cut
  // short; at 640x480 the Render panel's lines break between fields.
  const Shot small = snapshot("narrow_panels", "", (dir / "long.sce").string(), "900x600");
  ASSERT_EQ(small.exitCode, 0);
  expectShows(
      small, {"| | mesh | shading |\n", "| [x] | a_ball_", "...\n80 tris", "| [x] | box\n12 tris"});
  EXPECT_EQ(small.text.find("a_ball_with_a_long_name"), std::string::npos) << small.text;
  const Shot tiny = snapshot("tiny_panels", "", (dir / "long.sce").string(), "640x480");
  ASSERT_EQ(tiny.exitCode, 0);
  expectShows(tiny, {"\nload -  first image -\nexact -\n", "\nframes while rendering:\n"});
}

TEST(ViewerContent, TheInspectorsPaneKeepsItsPlaceWhateverThePixelShows) {
  // (150, 70): the mirror box, a reflection and a shadowed light; (20, 10):
  // the floor, one ray.
  const Shot mirror = snapshot("inspector_mirror", "--pin 150,70");
  const Shot floor = snapshot("inspector_floor", "--pin 20,10");
  ASSERT_EQ(mirror.exitCode, 0);
  ASSERT_EQ(floor.exitCode, 0);
  ASSERT_TRUE(mirror.regions.count("inspector")) << "the inspector has a pane of its own";
  const Region a = mirror.regions.at("inspector"), b = floor.regions.at("inspector");
  const std::size_t linesA = linesFrom(mirror.text, "pixel (150, 70)").size(),
                    linesB = linesFrom(floor.text, "pixel (20, 10)").size();
  ASSERT_GT(linesA, linesB + 10) << "the two pixels' accounts differ in length";
  EXPECT_EQ(a.y0, b.y0);
  EXPECT_EQ(a.y1, b.y1) << "what lies below the pane stays put";
  EXPECT_GT(a.y1 - a.y0, 150) << "the pane fills the panel's room";
  // Below the pane: its splitter and the five closed headers, in the window.
  EXPECT_LE(a.y1 + 10 + 5 * 23, mirror.image.height);
}

TEST(ViewerContent, DescribeHasEveryInspectorLineWhenThePaneScrolls) {
  // At 900x600 the pane shows a few of the pixel's lines; --describe has
  // them all, each on its own line, as the inspector words them.
  const Shot small = snapshot("inspector_small", "--pin 150,70",
                              "tests/app/viewer/scenes/viewer_test.sce", "900x600");
  ASSERT_EQ(small.exitCode, 0);
  const Region pane = small.regions.at("inspector");
  ASSERT_LT(pane.y1 - pane.y0, 20 * 17) << "the pane is too small for every line";
  const Scene scene = testScene();
  const SceneIntersector intersector(scene, TraceOptions{});
  const PixelInspection in = inspectPixel(intersector, Camera(scene.camera), 150, 70);
  const viewer::InspectorReport report = viewer::inspectorReport(
      in, 150, 70, true, [](const PrimitiveRef&) { return std::string("object"); });
  std::vector<std::string> expected;
  std::istringstream words(viewer::reportText(report));
  for (std::string line; std::getline(words, line);) expected.push_back(line);
  ASSERT_GT(expected.size(), 30u);
  const std::vector<std::string> shown = linesFrom(small.text, "pixel (150, 70) pinned");
  ASSERT_EQ(shown.size(), expected.size()) << small.text;
  EXPECT_EQ(shown.front(), expected.front());
  EXPECT_EQ(shown.back(), "    entered no mesh box");
  expectShows(small, {"\n> reflection 1 (weight 0.400)\n",
                      "\n    light 1  n.l 0.513 shadowed by sphere #0 at t 0.7441\n"});
}

}  // namespace
}  // namespace meshtrace
