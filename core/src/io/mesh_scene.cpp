#include "meshtrace/io/mesh_scene.h"

#include <cmath>

#include "meshtrace/io/input_error.h"
#include "meshtrace/io/mesh_reader.h"
#include "meshtrace/io/scene_parser.h"
#include "meshtrace/util/quoted.h"

namespace meshtrace {

namespace {
constexpr double kFovyDegrees = 40.0;
// The view comes from the front, a little from the right and above.
const Vec3 kViewFrom(0.35, 0.45, 1.0);

std::string vectorText(const Vec3& v) {
  return shortestText(v.x) + " " + shortestText(v.y) + " " + shortestText(v.z);
}
}  // namespace

bool isSceneFile(const std::filesystem::path& file) { return file.extension() == ".sce"; }

std::string meshSceneText(const Aabb& bounds, const std::string& meshName) {
  const Vec3 center = bounds.center();
  // The box's bounding sphere; a mesh of one point still gets a view.
  double radius = 0.5 * glm::length(bounds.extent());
  if (!(radius > 0.0)) radius = 1.0;
  // Far enough for the sphere to fill 90 % of the image's height.
  const double distance = radius / std::sin(glm::radians(kFovyDegrees / 2.0)) / 0.9;
  const Vec3 eye = center + distance * glm::normalize(kViewFrom);
  const Vec3 light = center + radius * Vec3(2.0, 4.0, 3.0);
  const Vec3 floor(center.x, bounds.min.y, center.z);
  return "# " + meshName + " framed: edit and render it as any scene\n" + "camera " +
         vectorText(eye) + "  " + vectorText(center) + "  0 1 0  " + shortestText(kFovyDegrees) +
         "  800 600\n" +
         "depth 1\n"
         "background 0.1 0.1 0.15\n"
         "ambience 0.2 0.2 0.2\n"
         "light " +
         vectorText(light) +
         "  1 1 1\n"
         "plane " +
         vectorText(floor) +
         "  0 1 0  0.2 0.2 0.2  0.5 0.5 0.5  0 0 0  1  0\n"
         "mesh " +
         meshName + " PHONG  0.2 0.2 0.2  0.7 0.6 0.5  0.5 0.5 0.5  40  0\n";
}

std::string meshSceneText(const std::filesystem::path& mesh, MemoryBudget& budget) {
  const std::string name = mesh.filename().string();
  if (!isSceneWord(name))
    throw InputError::inFile(mesh,
                             "a scene's mesh line cannot name this file: scene files separate "
                             "words by white space and start comments with '#'; rename the "
                             "mesh, or link it under a name without them");
  Aabb bounds;
  {
    // Its own plan: this copy is freed before the scene loads its own.
    MemoryBudget probe(budget.limit());
    for (const Vec3& v : readMesh(mesh, probe).vertices) bounds.extend(v);
  }
  if (bounds.empty()) throw InputError::inFile(mesh, "the mesh has no vertices to frame");
  return meshSceneText(bounds, name);
}

std::filesystem::path meshScenePath(const std::filesystem::path& mesh) {
  auto sceneFile = mesh;
  return sceneFile.replace_extension(".sce");
}

Scene loadMeshAsScene(const std::filesystem::path& mesh, MemoryBudget& budget) {
  return parseScene(meshSceneText(mesh, budget), meshScenePath(mesh), budget);
}

}  // namespace meshtrace
