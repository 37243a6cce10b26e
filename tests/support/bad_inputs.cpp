#include "support/bad_inputs.h"

#include "support/scene_snippets.h"

namespace meshtrace::test {

namespace {

BadInput badScene(std::string name, std::string sceneText, std::vector<std::string> mentions) {
  return {std::move(name), std::move(sceneText), "", std::move(mentions)};
}

// A valid scene whose one mesh, mesh.off, holds `offText`.
BadInput badMesh(std::string name, std::string offText, std::vector<std::string> mentions) {
  mentions.insert(mentions.begin(), {"bad.sce:2", "mesh.off"});
  return {std::move(name), kCameraLine + "mesh mesh.off FLAT " + kMaterial + "\n",
          std::move(offText), std::move(mentions)};
}

// A camera line with the given fovy, width and height after a fixed eye,
// center and up.
std::string camera(const std::string& eyeCenterUp, const std::string& rest) {
  return "camera " + eyeCenterUp + " " + rest + "\n";
}
const std::string kView = "0 0 5  0 0 0  0 1 0";

std::vector<BadInput> makeBadInputs() {
  const std::string sphere = "sphere 0 0 0 1 " + kMaterial;
  return {
      badScene("MissingScene", "", {"bad.sce", "not found"}),
      badScene("EmptyScene", "\n\n", {"bad.sce", "empty"}),
      badScene("NoCamera", sphere + "\n", {"bad.sce", "camera"}),
      badScene("UnknownKeyword", kCameraLine + "teapot 1 2 3\n", {"bad.sce:2", "teapot"}),
      badScene("TruncatedEntity", kCameraLine + "sphere 0 0 0 1 0.1\n",
               {"bad.sce:2", "incomplete"}),
      badScene("WordForNumber", kCameraLine + "light 1 one 1 1 1 1\n", {"bad.sce:2", "'one'"}),
      badScene("NaN", kCameraLine + "light 1 nan 1 1 1 1\n", {"bad.sce:2", "not finite"}),
      badScene("Infinity", kCameraLine + "ambience inf 0 0\n", {"bad.sce:2", "not finite"}),
      badScene("ZeroWidth", camera(kView, "45 0 6"), {"bad.sce:1", "width"}),
      badScene("NegativeHeight", camera(kView, "45 8 -6"), {"bad.sce:1", "height"}),
      badScene("AbsurdSize", camera(kView, "45 100000 100000"), {"bad.sce:1", "width"}),
      badScene("EyeEqualsCenter", camera("1 1 1  1 1 1  0 1 0", "45 8 6"), {"bad.sce:1", "eye"}),
      badScene("FovyZero", camera(kView, "0 8 6"), {"bad.sce:1", "fovy"}),
      // Cameras whose rays would not be finite: a NaN camera renders black.
      badScene("EyeAndCenterATinyBitApart", camera("0 0 0  5e-324 0 0  0 1 0", "45 8 6"),
               {"bad.sce:1", "5e-324 apart", "too close to define a view direction"}),
      badScene("EyeFarOutWithAWideView", camera("1e308 0 0  0 0 0  0 1 0", "90 8 6"),
               {"bad.sce:1", "1e+308 apart", "too large"}),
      badScene("LightTooFarToShade", kCameraLine + "light 1e200 0 0  1 1 1\n" + sphere + "\n",
               {"bad.sce:2", "light", "too far"}),
      badScene("NegativeDepth", kCameraLine + "depth -2\n", {"bad.sce:2", "depth"}),
      badScene("NegativeRadius", kCameraLine + "sphere 0 0 0 -1 " + kMaterial + "\n",
               {"bad.sce:2", "radius"}),
      badScene("ZeroPlaneNormal", kCameraLine + "plane 0 0 0 0 0 0 " + kMaterial + "\n",
               {"bad.sce:2", "normal"}),
      badScene("ZeroCylinderAxis", kCameraLine + "cylinder 0 0 0 1 0 0 0 2 " + kMaterial + "\n",
               {"bad.sce:2", "axis"}),
      badScene("UnknownShadingMode", kCameraLine + "mesh mesh.off GOURAUD " + kMaterial + "\n",
               {"bad.sce:2", "GOURAUD"}),
      badScene("MissingMesh", kCameraLine + "mesh absent.off FLAT " + kMaterial + "\n",
               {"bad.sce:2", "absent.off", "not found"}),
      badScene("MeshIsADirectory", kCameraLine + "mesh folder.off FLAT " + kMaterial + "\n",
               {"bad.sce:2", "folder.off", "directory"}),
      badMesh("OffBadHeader", "OFX\n3 1 0\n", {"mesh.off:1", "header"}),
      // Long enough that the counts pass the file-size check.
      badMesh("OffTooFewVertexLines", "OFF\n3 1 0\n0.0000 0.0000 0.0000\n1.0000 0.0000 0.0000\n",
              {"vertex 2 of 3"}),
      badMesh("OffTooFewFaceLines", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", {"face 1 of 2"}),
      badMesh("OffIndexOutOfRange", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
              {"mesh.off:6", "out of range"}),
      badMesh("OffNegativeIndex", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -2 1\n",
              {"mesh.off:6", "out of range"}),
      badMesh("OffFaceOfMoreCornersThanVertices", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n5 0 1 2 0 1\n",
              {"mesh.off:6", "5 corners"}),
      badMesh("OffLoneCrJoiningNothing", "OFF\r\n3 1 0\r\n0 0 0\r\n1 0\r0\r\n0 1 0\r\n3 0 1 2\r\n",
              {"mesh.off:4", "vertex 1"}),
      badMesh("OffNanVertex", "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n",
              {"mesh.off:4", "vertex 1"}),
      badMesh("OffCountsInTheBillions", "OFF\n4000000000 8000000000 0\n0 0 0\n",
              {"4000000000 vertices"}),
      badMesh("OffBinaryGarbage",
              std::string("\x7f"
                          "ELF\x02\x01\0\0\x03\0",
                          10),
              {"binary"}),
      badMesh("OffNulOnALine",
              [] {
                const char text[] = "OFF\n3 1 0\n0.0 0.0 0.0\n1.0 \0 0\n0 1 0\n3 0 1 2\n";
                return std::string(text, sizeof text - 1);
              }(),
              {"mesh.off:4", "NUL"}),
  };
}

}  // namespace

const std::vector<BadInput>& badInputs() {
  static const std::vector<BadInput> cases = makeBadInputs();
  return cases;
}

}  // namespace meshtrace::test
