// Headless snapshots of the whole viewer window (OSMesa), compared with the
// stored PNGs in snapshots/. Each was looked at before it was stored. To
// store new ones: MESHTRACE_UPDATE_SNAPSHOTS=1, then look at every file.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "meshtrace/io/image.h"
#include "meshtrace/report/image_compare.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

namespace fs = std::filesystem;

// Same software rasteriser, same fonts: snapshots agree to the pixel on one
// machine. Another Mesa build may round a few edges differently, so a little
// noise is allowed; a changed panel, text or image region is not.
constexpr double kMaxRmse = 2.0;
constexpr double kMaxFractionOver32 = 0.002;

struct Snapshot {
  std::string name;
  std::string args;
  std::string scene = "viewer_test.sce";
};

class ViewerSnapshot : public ::testing::TestWithParam<Snapshot> {};

TEST_P(ViewerSnapshot, MatchesTheStoredImage) {
  const Snapshot& s = GetParam();
  const fs::path out = test::scratchDir() / (s.name + ".png");
  // Relative paths, run from the source folder: the window shows no machine paths.
  const std::string command =
      "cd '" + test::sourceDir().string() + "' && '" MESHTRACE_VIEWER "'" +
      " --headless --size 1100x700 --no-default-dirs --hide-timings --threads 2 " + s.args +
      " --snapshot '" + out.string() + "' tests/app/viewer/scenes/" + s.scene;
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const fs::path stored = test::sourceDir() / "tests/app/viewer/snapshots" / (s.name + ".png");
  if (std::getenv("MESHTRACE_UPDATE_SNAPSHOTS")) {
    fs::copy_file(out, stored, fs::copy_options::overwrite_existing);
    GTEST_SKIP() << "stored " << stored << ": look at it before committing";
  }
  ASSERT_TRUE(fs::exists(stored)) << stored;
  const ImageDifference d = compareImages(readImage(out), readImage(stored));
  std::printf("[ figures  ] %-22s RMSE %.3f  pixels off >32: %.4f%%\n", s.name.c_str(), d.rmse,
              100.0 * d.fractionOver32);
  EXPECT_LE(d.rmse, kMaxRmse) << "compare " << out << " with " << stored;
  EXPECT_LE(d.fractionOver32, kMaxFractionOver32) << "compare " << out << " with " << stored;
}

INSTANTIATE_TEST_SUITE_P(
    Views, ViewerSnapshot,
    ::testing::Values(Snapshot{"color", ""}, Snapshot{"normals", "--view normals"},
                      Snapshot{"depth", "--view depth"}, Snapshot{"object_id", "--view object"},
                      Snapshot{"triangle_id", "--view triangle"},
                      Snapshot{"box_hits", "--view boxes"},
                      Snapshot{"traversal_cost", "--view cost"},
                      Snapshot{"normal_deviation", "--view deviation --open normals"},
                      Snapshot{"heat_overlay", "--overlay boxes --opacity 0.5"},
                      Snapshot{"inspector_phong", "--pin 88,109"},
                      Snapshot{"inspector_flat", "--pin 88,109 --shading ball=FLAT"},
                      Snapshot{"reference_difference", "--view difference --open compare"},
                      Snapshot{"camera_panel", "--open camera --hide box"},
                      Snapshot{"broken_scene", "", "broken.sce"}),
    [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace meshtrace
