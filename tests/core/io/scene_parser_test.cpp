// The .sce parser: every keyword in any order, and bad scenes refused with an
// InputError naming the file, the line and what is wrong.
#include "meshtrace/io/scene_parser.h"

#include <gtest/gtest.h>

#include "support/files.h"
#include "support/input_errors.h"
#include "support/paths.h"
#include "support/scene_snippets.h"

namespace meshtrace {
namespace {

using test::expectMentions;
using test::kCameraLine;
using test::kMaterial;

const std::filesystem::path kSceneName = "bad.sce";
// A one-triangle OFF whose face (line 6) names vertex 7 of 3.
const std::string kBadIndexOff = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n";

// The message of the error parsing `text` as if read from bad.sce.
std::string sceneErrorOf(const std::string& text) {
  return test::inputErrorOf([&] { parseScene(text, kSceneName); });
}

TEST(SceneParser, ReadsEveryKeywordInAnyOrderWithComments) {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "tri.off", test::kTriangleOff);
  const Scene scene = parseScene(
      "# a comment line\n"
      "sphere 1 2 3  0.5  " +
          kMaterial +
          "  # trailing comment\n"
          "light 1 1 1  0.5 0.5 0.5\n"
          "plane 0 -1 0  0 2 0  " +
          kMaterial + "\n" + kCameraLine + "cylinder 0 0 0  0.25  0 0 3  2  " + kMaterial +
          "\n"
          "mesh tri.off PHONG " +
          kMaterial +
          "\n"
          "depth 3\nbackground 0.1 0.2 0.3\nambience 0.4 0.5 0.6\n"
          "light 2 2 2  1 1 1\n",
      dir / "scene.sce");
  EXPECT_EQ(scene.depth, 3);
  EXPECT_EQ(scene.background, Color(0.1, 0.2, 0.3));
  EXPECT_EQ(scene.ambience, Color(0.4, 0.5, 0.6));
  ASSERT_EQ(scene.lights.size(), 2u);
  EXPECT_EQ(scene.lights[1].position, Vec3(2, 2, 2));
  ASSERT_EQ(scene.spheres.size(), 1u);
  EXPECT_EQ(scene.spheres[0].center, Vec3(1, 2, 3));
  EXPECT_EQ(scene.spheres[0].radius, 0.5);
  EXPECT_EQ(scene.spheres[0].material.diffuse, Color(0.6));
  EXPECT_EQ(scene.spheres[0].material.shininess, 20.0);
  ASSERT_EQ(scene.planes.size(), 1u);
  EXPECT_EQ(scene.planes[0].normal, Vec3(0, 1, 0)) << "the plane normal is normalised";
  ASSERT_EQ(scene.cylinders.size(), 1u);
  EXPECT_EQ(scene.cylinders[0].axis, Vec3(0, 0, 1)) << "the cylinder axis is normalised";
  EXPECT_EQ(scene.cylinders[0].height, 2.0);
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].shading(), Shading::Phong);
  EXPECT_EQ(scene.meshes[0].triangles().size(), 1u);
  EXPECT_EQ(scene.camera.width(), 8);
  EXPECT_EQ(scene.camera.height(), 6);
  EXPECT_TRUE(scene.warnings.empty());
}

TEST(SceneParser, UsesTheDefaultsWhenKeywordsAreAbsent) {
  const Scene scene = parseScene(kCameraLine, kSceneName);
  EXPECT_EQ(scene.depth, 0);
  EXPECT_EQ(scene.background, Color(0.0));
  EXPECT_EQ(scene.ambience, Color(0.0));
  EXPECT_TRUE(scene.lights.empty());
  EXPECT_EQ(scene.objectCount(), 0u);
}

TEST(SceneParser, LaterSettingsReplaceEarlierOnes) {
  const Scene scene =
      parseScene(kCameraLine +
                     "depth 2\nbackground 1 1 1\n"
                     "camera 0 0 9  0 0 0  0 1 0  30  20 10\ndepth 5\nbackground 0 0 1\n",
                 kSceneName);
  EXPECT_EQ(scene.camera.width(), 20);
  EXPECT_EQ(scene.camera.spec().eye, Vec3(0, 0, 9));
  EXPECT_EQ(scene.depth, 5);
  EXPECT_EQ(scene.background, Color(0, 0, 1));
}

TEST(SceneParser, AcceptsCrlfLineEndsAndCountsLinesRight) {
  const Scene scene = parseScene(
      "# dos\r\n" + std::string("camera 0 0 5 0 0 0 0 1 0 45 8 6\r\n") + "depth 2\r\n", kSceneName);
  EXPECT_EQ(scene.depth, 2);
  expectMentions(sceneErrorOf("camera 0 0 5 0 0 0 0 1 0 45 8 6\r\n\r\nbogus\r\n"),
                 {"bad.sce:3", "'bogus'"});
}

// A lone CR ends a line (and a comment), as editors show it.
TEST(SceneParser, TakesALoneCrAsALineEnd) {
  const Scene scene =
      parseScene("# old Mac line ends\rcamera 0 0 5 0 0 0 0 1 0 45 8 6\rdepth 3\r", kSceneName);
  EXPECT_EQ(scene.depth, 3);
  expectMentions(sceneErrorOf("# a\rcamera 0 0 5 0 0 0 0 1 0 45 8 6\r\n\rbogus\n"),
                 {"bad.sce:4", "'bogus'"});
}

// A scene file is read a block at a time: words that cross a block's end
// and the lines after many blocks come out as written.
TEST(SceneParser, ReadsASceneOfManyBlocks) {
  const auto dir = test::scratchDir();
  std::string text = kCameraLine;
  for (int i = 0; i < 6000; ++i)
    text += "sphere " + std::to_string(i) + ".125 -" + std::to_string(i) + " 0.5  " +
            std::to_string(i + 1) + "  " + kMaterial + (i % 7 == 0 ? "\r\n" : "\n");
  ASSERT_GT(text.size(), std::size_t{4} << 16) << "several blocks";
  const Scene scene = loadScene(test::writeFile(dir / "many.sce", text));
  ASSERT_EQ(scene.spheres.size(), 6000u);
  for (int i : {0, 1234, 5999}) {
    EXPECT_EQ(scene.spheres[i].center, Vec3(i + 0.125, -i, 0.5)) << i;
    EXPECT_EQ(scene.spheres[i].radius, i + 1.0) << i;
  }
  expectMentions(
      test::inputErrorOf([&] { loadScene(test::writeFile(dir / "bad.sce", text + "x\n")); }),
      {"bad.sce:6002", "'x'"});
}

TEST(SceneParser, RejectsAWordLongerThanAnyPath) {
  expectMentions(test::inputErrorOf([&] {
                   loadScene(test::writeFile(test::scratchDir() / "bad.sce",
                                             kCameraLine + "\nmesh " + std::string(100000, 'm')));
                 }),
                 {"bad.sce:3", "more than 65536 bytes"});
}

TEST(SceneParser, SaysASymlinkLoopIsOne) {
  const auto dir = test::scratchDir();
  std::filesystem::create_symlink("loop.sce", dir / "loop.sce");
  const std::string message = test::inputErrorOf([&] { loadScene(dir / "loop.sce"); });
  expectMentions(message, {"loop.sce", "symbolic links"});
  EXPECT_EQ(message.find("not found"), std::string::npos) << message;
}

TEST(SceneParser, NamesTheLineOfANulByte) {
  expectMentions(sceneErrorOf(kCameraLine + "depth 2\n\n" + std::string("sph\0ere", 7)),
                 {"bad.sce:4", "NUL"});
}

// Directions of any length: only the zero vector has none.
TEST(SceneParser, TakesDirectionsOfAnyLength) {
  const Scene scene = parseScene(kCameraLine + "plane 0 0 0  1e-200 0 0  " + kMaterial +
                                     "\ncylinder 0 0 0 1  0 1e200 1e200  2 " + kMaterial +
                                     "\ncamera 0 0 5  0 0 0  1e-200 0 0  45 8 6\n",
                                 kSceneName);
  EXPECT_EQ(scene.planes[0].normal, Vec3(1, 0, 0));
  EXPECT_NEAR(glm::length(scene.cylinders[0].axis), 1.0, 1e-15);
  EXPECT_EQ(scene.cylinders[0].axis.y, scene.cylinders[0].axis.z);
  EXPECT_FALSE(scene.camera.upWasReplaced());
}

TEST(SceneParser, AllowsAnEntitySpreadOverSeveralLines) {
  const Scene scene = parseScene(kCameraLine + "sphere 0 0 0\n 1\n" + kMaterial + "\n", kSceneName);
  EXPECT_EQ(scene.spheres.size(), 1u);
}

TEST(SceneParser, ResolvesMeshPathsAgainstTheSceneFolder) {
  const auto dir = test::scratchDir();
  std::filesystem::create_directories(dir / "scenes" / "meshes");
  test::writeFile(dir / "scenes" / "meshes" / "tri.off", test::kTriangleOff);
  const auto sceneFile = test::writeFile(
      dir / "scenes" / "s.sce", kCameraLine + "mesh meshes/tri.off FLAT " + kMaterial + "\n");
  const Scene scene = loadScene(sceneFile);
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].shading(), Shading::Flat);
  EXPECT_TRUE(scene.meshes[0].vertexNormals().empty()) << "a FLAT mesh needs no vertex normals";
}

TEST(SceneParser, WarnsButAcceptsAnUpVectorParallelToTheView) {
  const Scene scene =
      parseScene("# looking straight down\ncamera 0 5 0  0 0 0  0 1 0  45  8 6\n", kSceneName);
  ASSERT_EQ(scene.warnings.size(), 1u);
  expectMentions(scene.warnings[0], {"bad.sce:2", "up", "parallel"});
  EXPECT_TRUE(scene.camera.upWasReplaced());
}

TEST(SceneParser, WarnsButAcceptsAMeshWithoutFaces) {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "points.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
  test::writeFile(dir / "tri.off", test::kTriangleOff);
  const auto sceneFile =
      test::writeFile(dir / "s.sce", kCameraLine + "mesh tri.off FLAT " + kMaterial +
                                         "\nmesh points.off FLAT " + kMaterial + "\n");
  const Scene scene = loadScene(sceneFile);
  ASSERT_EQ(scene.meshes.size(), 2u);
  ASSERT_EQ(scene.warnings.size(), 1u);
  expectMentions(scene.warnings[0], {"s.sce:3", "points.off", "no faces"});
}

// A bow tie (its four corners cross) has no triangulation: its triangles
// cover area it does not, and the user is told which mesh line has it.
TEST(SceneParser, WarnsAboutAFaceThatCrossesItself) {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "bowtie.off", "OFF\n4 1 0\n0 0 0\n1 1 0\n1 0 0\n0 1 0\n4 0 1 2 3\n");
  const auto sceneFile =
      test::writeFile(dir / "s.sce", kCameraLine + "mesh bowtie.off FLAT " + kMaterial + "\n");
  const Scene scene = loadScene(sceneFile);
  ASSERT_EQ(scene.warnings.size(), 1u);
  expectMentions(scene.warnings[0],
                 {"s.sce:2", "bowtie.off", "has 1 face", "it crosses itself", "outside it"});
}

// --- bad scene files -------------------------------------------------------

TEST(SceneParser, RejectsAMissingSceneFileNamingIt) {
  const auto file = test::scratchDir() / "absent.sce";
  expectMentions(test::inputErrorOf([&] { loadScene(file); }), {"absent.sce", "not found"});
}

TEST(SceneParser, RejectsASceneThatIsADirectory) {
  const auto dir = test::scratchDir() / "folder.sce";
  std::filesystem::create_directory(dir);
  expectMentions(test::inputErrorOf([&] { loadScene(dir); }), {"folder.sce", "directory"});
}

TEST(SceneParser, RejectsAnEmptySceneFile) {
  const auto file = test::writeFile(test::scratchDir() / "empty.sce", " \n\t\n");
  expectMentions(test::inputErrorOf([&] { loadScene(file); }), {"empty.sce", "empty"});
}

TEST(SceneParser, RejectsASceneWithoutCamera) {
  expectMentions(sceneErrorOf("# nothing but a sphere\n" + test::kSphereLine),
                 {"bad.sce", "camera"});
}

TEST(SceneParser, RejectsBinaryGarbage) {
  expectMentions(sceneErrorOf(std::string("camera\0\x01\x02", 9)), {"bad.sce", "binary"});
}

TEST(SceneParser, RejectsAnUnknownKeywordNamingTheLine) {
  expectMentions(sceneErrorOf(kCameraLine + "\nspehre 0 0 0 1 " + kMaterial + "\n"),
                 {"bad.sce:3", "unknown keyword", "spehre"});
}

TEST(SceneParser, RejectsATruncatedEntityNamingItsLine) {
  expectMentions(sceneErrorOf(kCameraLine + "sphere 0 0 0  1  0.1 0.1 0.1\n"),
                 {"bad.sce:2", "sphere", "incomplete"});
}

TEST(SceneParser, RejectsAnEntityCutShortByTheNextKeyword) {
  expectMentions(sceneErrorOf("light 1 1 1 1 1\n" + kCameraLine),
                 {"bad.sce:2", "number", "light", "camera"});
}

TEST(SceneParser, RejectsAWordWhereANumberBelongsNamingTheLine) {
  expectMentions(sceneErrorOf(kCameraLine + "sphere 0 zero 0  1  " + kMaterial + "\n"),
                 {"bad.sce:2", "number", "'zero'"});
}

class SceneParserNonFinite : public ::testing::TestWithParam<const char*> {};

TEST_P(SceneParserNonFinite, RejectsNonFiniteNumbersNamingTheLine) {
  expectMentions(sceneErrorOf(kCameraLine + "light 1 " + GetParam() + " 1  1 1 1\n"),
                 {"bad.sce:2", "not finite", GetParam()});
}

INSTANTIATE_TEST_SUITE_P(NanAndInf, SceneParserNonFinite,
                         ::testing::Values("nan", "NaN", "-nan", "inf", "-inf", "infinity"));

TEST(SceneParser, RejectsANumberTooLargeForADouble) {
  expectMentions(sceneErrorOf(kCameraLine + "light 1 1e999 1  1 1 1\n"), {"bad.sce:2", "1e999"});
}

// One bad line, always line 2 (after a valid camera: a later camera line
// replaces it and is checked the same way).
struct BadLine {
  const char* name;
  std::string line;
  const char* complaint;  // a word the message must contain
};

class SceneParserBadLine : public ::testing::TestWithParam<BadLine> {};

TEST_P(SceneParserBadLine, RejectsNamingTheLineAndTheProblem) {
  expectMentions(sceneErrorOf(kCameraLine + GetParam().line + "\n"),
                 {"bad.sce:2", GetParam().complaint});
}

INSTANTIATE_TEST_SUITE_P(
    Cases, SceneParserBadLine,
    ::testing::Values(
        BadLine{"ZeroWidth", "camera 0 0 5 0 0 0 0 1 0 45 0 6", "width"},
        BadLine{"NegativeWidth", "camera 0 0 5 0 0 0 0 1 0 45 -8 6", "width"},
        BadLine{"ZeroHeight", "camera 0 0 5 0 0 0 0 1 0 45 8 0", "height"},
        BadLine{"NegativeHeight", "camera 0 0 5 0 0 0 0 1 0 45 8 -6", "height"},
        BadLine{"AbsurdSize", "camera 0 0 5 0 0 0 0 1 0 45 100000 100000", "width"},
        BadLine{"AbsurdHeight", "camera 0 0 5 0 0 0 0 1 0 45 8 100000", "height"},
        // Each side allowed, but together gigabytes of pixels.
        BadLine{"AbsurdPixelCount", "camera 0 0 5 0 0 0 0 1 0 45 16384 16384", "larger"},
        BadLine{"FractionalWidth", "camera 0 0 5 0 0 0 0 1 0 45 8.5 6", "width"},
        BadLine{"EyeEqualsCenter", "camera 1 2 3 1 2 3 0 1 0 45 8 6", "same point"},
        BadLine{"FovyZero", "camera 0 0 5 0 0 0 0 1 0 0 8 6", "fovy"},
        BadLine{"FovyNegative", "camera 0 0 5 0 0 0 0 1 0 -30 8 6", "fovy"},
        BadLine{"Fovy180", "camera 0 0 5 0 0 0 0 1 0 180 8 6", "fovy"},
        BadLine{"ZeroUp", "camera 0 0 5 0 0 0 0 0 0 45 8 6", "up"},
        BadLine{"EyeAndCenterATinyBitApart", "camera 0 0 0 5e-324 0 0 0 1 0 45 8 6",
                "eye and center are 5e-324 apart: too close to define a view direction"},
        BadLine{"EyeFarOutWithAWideView", "camera 1e308 0 0 0 0 0 0 1 0 90 8 6", "too large"},
        BadLine{"LightTooFarToShade", "light 1e200 0 0 1 1 1", "too far"},
        BadLine{"NegativeDepth", "depth -1", "depth"},
        BadLine{"FractionalDepth", "depth 1.5", "depth"},
        BadLine{"NegativeSphereRadius", "sphere 0 0 0 -1 " + kMaterial, "radius"},
        BadLine{"ZeroSphereRadius", "sphere 0 0 0 0 " + kMaterial, "radius"},
        BadLine{"NegativeCylinderRadius", "cylinder 0 0 0 -1 0 1 0 2 " + kMaterial, "radius"},
        BadLine{"NegativeCylinderHeight", "cylinder 0 0 0 1 0 1 0 -2 " + kMaterial, "height"},
        BadLine{"ZeroPlaneNormal", "plane 0 0 0 0 0 0 " + kMaterial, "zero vector"},
        BadLine{"ZeroCylinderAxis", "cylinder 0 0 0 1 0 0 0 2 " + kMaterial, "zero vector"},
        BadLine{"MirrorAboveOne", "sphere 0 0 0 1 0 0 0 0 0 0 0 0 0 1 1.5", "mirror"},
        BadLine{"UnknownShadingMode", "mesh tri.off SMOOTH " + kMaterial, "SMOOTH"},
        BadLine{"MissingMeshFile", "mesh absent.off FLAT " + kMaterial, "absent.off"}),
    [](const auto& info) { return std::string(info.param.name); });

// Mesh errors name both the scene line and the mesh file with its own line.
TEST(SceneParser, RejectsABadMeshNamingTheSceneLineAndTheMeshLine) {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "broken.off", kBadIndexOff);
  const auto scene =
      test::writeFile(dir / "s.sce", kCameraLine + "mesh broken.off FLAT " + kMaterial + "\n");
  expectMentions(test::inputErrorOf([&] { loadScene(scene); }),
                 {"s.sce:2", "broken.off:6", "face 0", "out of range"});
}

// The meshes load side by side; the scene lists them in file order.
TEST(SceneParser, KeepsTheMeshesInFileOrder) {
  const auto dir = test::scratchDir();
  const std::string fan = "OFF\n5 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n-1 1 0\n";
  std::string lines = kCameraLine;
  for (int corners = 3; corners <= 5; ++corners) {
    const std::string name = "fan" + std::to_string(corners) + ".off";
    std::string face = std::to_string(corners);
    for (int k = 0; k < corners; ++k) face.append(" ").append(std::to_string(k));
    test::writeFile(dir / name, fan + face + "\n");
    lines += "mesh " + name + " FLAT " + kMaterial + "\n";
  }
  const Scene scene = loadScene(test::writeFile(dir / "s.sce", lines));
  ASSERT_EQ(scene.meshes.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(scene.meshes[i].triangles().size(), i + 1);
    EXPECT_EQ(scene.meshes[i].file().filename(), "fan" + std::to_string(i + 3) + ".off");
  }
}

// Of several bad meshes, the error names the first in the scene file,
// whichever finished loading first.
TEST(SceneParser, ReportsTheFirstBadMeshOfTheScene) {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "tri.off", test::kTriangleOff);
  test::writeFile(dir / "early.off", kBadIndexOff);
  test::writeFile(dir / "late.off", "OFF\n3 1 0\n0 0 0\n1 0 x\n0 1 0\n3 0 1 2\n");
  const auto scene = test::writeFile(dir / "s.sce", kCameraLine + "mesh tri.off FLAT " + kMaterial +
                                                        "\nmesh early.off FLAT " + kMaterial +
                                                        "\nmesh late.off FLAT " + kMaterial + "\n");
  for (int run = 0; run < 10; ++run)
    expectMentions(test::inputErrorOf([&] { loadScene(scene); }),
                   {"s.sce:3", "early.off:6", "out of range"});
}

// The whole scene file is checked before any mesh is read: a mistake after a
// mesh line is reported without waiting for the mesh.
TEST(SceneParser, ReportsAMistakeInTheSceneBeforeReadingAnyMesh) {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "broken.off", kBadIndexOff);
  const auto scene = test::writeFile(
      dir / "s.sce", kCameraLine + "mesh broken.off FLAT " + kMaterial + "\nsphere 0 0 0\n");
  const std::string message = test::inputErrorOf([&] { loadScene(scene); });
  expectMentions(message, {"s.sce:3", "sphere"});
  EXPECT_EQ(message.find("broken.off"), std::string::npos) << message;
}

TEST(SceneParser, RejectsAMeshPathThatIsADirectory) {
  const auto dir = test::scratchDir();
  std::filesystem::create_directory(dir / "meshdir.off");
  const auto scene =
      test::writeFile(dir / "s.sce", kCameraLine + "mesh meshdir.off PHONG " + kMaterial + "\n");
  expectMentions(test::inputErrorOf([&] { loadScene(scene); }),
                 {"s.sce:2", "meshdir.off", "directory"});
}

TEST(SceneWords, AreWhatTheSceneReaderTakesAsOneWord) {
  for (const char* word : {"torus.off", "../meshes/knot.ply", "/abs/path/m.obj", "a,b;c"})
    EXPECT_TRUE(isSceneWord(word)) << word;
  for (const char* word : {"", "my torus.off", "a\tb", "a#b", "a\nb", "a\rb"})
    EXPECT_FALSE(isSceneWord(word)) << word;
}

}  // namespace
}  // namespace meshtrace
