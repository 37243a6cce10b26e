#include "meshtrace/io/mesh_scene.h"

#include <atomic>
#include <cmath>
#include <memory>

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

FramedMesh frameMesh(const std::filesystem::path& mesh, MemoryBudget& budget) {
  const std::string name = mesh.filename().string();
  if (!isSceneWord(name))
    throw InputError::inFile(mesh,
                             "a scene's mesh line cannot name this file: scene files separate "
                             "words by white space and start comments with '#'; rename the "
                             "mesh, or link it under a name without them");
  // The arrays, until the scene's mesh line takes them.
  struct Held {
    MeshData data;
    std::atomic<bool> taken{false};
  };
  auto held = std::make_shared<Held>();
  held->data = readMesh(mesh, budget);
  Aabb bounds;
  for (const Vec3& v : held->data.vertices) bounds.extend(v);
  if (bounds.empty()) throw InputError::inFile(mesh, "the mesh has no vertices to frame");
  // The mesh line names the file beside the scene (meshScenePath): the
  // first line that names it gets the arrays read here; anything else is
  // read from its file.
  const auto key = [](const std::filesystem::path& p) {
    return std::filesystem::absolute(p).lexically_normal();
  };
  return {meshSceneText(bounds, name),
          [held, file = key(mesh), key](const std::filesystem::path& path, MemoryBudget& b) {
            if (key(path) != file || held->taken.exchange(true)) return readMesh(path, b);
            return std::move(held->data);
          }};
}

std::string meshSceneText(const std::filesystem::path& mesh, MemoryBudget& budget) {
  // Its own plan: the arrays are freed before anything else loads.
  MemoryBudget probe(budget.limit());
  return frameMesh(mesh, probe).text;
}

std::filesystem::path meshScenePath(const std::filesystem::path& mesh) {
  auto sceneFile = mesh;
  return sceneFile.replace_extension(".sce");
}

Scene loadMeshAsScene(const std::filesystem::path& mesh, MemoryBudget& budget) {
  const FramedMesh framed = frameMesh(mesh, budget);
  return parseScene(framed.text, meshScenePath(mesh), budget, framed.meshes);
}

}  // namespace meshtrace
