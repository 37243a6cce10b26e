#include "viewer/model/geometry_load.h"

#include <chrono>
#include <fstream>
#include <sstream>

#include "meshtrace/io/mesh_reader.h"
#include "meshtrace/io/mesh_scene.h"
#include "meshtrace/io/scene_parser.h"
#include "viewer/model/scene_writer.h"

namespace meshtrace::viewer {

namespace {
// The mesh entities' modes of `text`, when this reader can tell them.
bool readModes(const std::string& text, std::vector<Shading>& modes) {
  try {
    modes = meshModes(text);
  } catch (const std::runtime_error&) {
    return false;
  }
  return true;
}

// Larger scene files are left to loadScene, which knows its limits.
constexpr std::uintmax_t kMaxStagedBytes = std::uintmax_t{16} << 20;

// The file's text and its mesh modes, when this reader can tell them: for
// anything else (a missing or huge file, words it does not know) loadScene
// reads the file and reports what is wrong in its own words.
bool readStaged(const std::filesystem::path& file, std::string& text, std::vector<Shading>& modes) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (ec || size > kMaxStagedBytes || !std::filesystem::is_regular_file(file, ec)) return false;
  std::ifstream in(file, std::ios::binary);
  if (!in) return false;
  std::stringstream buffer;
  buffer << in.rdbuf();
  text = buffer.str();
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) return false;
  return readModes(text, modes);
}
}  // namespace

bool isBareMesh(const std::filesystem::path& file) {
  return isMeshFile(file) && !isSceneFile(file);
}

LoadedScene loadGeometry(const std::filesystem::path& file) {
  const auto start = std::chrono::steady_clock::now();
  LoadedScene out;
  std::string text;
  // A bare mesh is read as the scene raytrace makes for it, as if that
  // scene were saved beside the mesh.
  std::filesystem::path sceneFile = file;
  MemoryBudget budget(defaultMemoryLimit());
  MeshSource meshes;  // a bare mesh's arrays, read once to frame it
  if (isBareMesh(file)) {
    FramedMesh framed = frameMesh(file, budget);
    out.generatedText = std::move(framed.text);
    meshes = std::move(framed.meshes);
    text = out.generatedText;
    sceneFile = meshScenePath(file);
  }
  if (!out.generatedText.empty() ? readModes(text, out.fileModes)
                                 : readStaged(file, text, out.fileModes)) {
    // The shading words rewritten in place: lines, and so the messages of
    // bad input, stay those of the file.
    const std::vector<Shading> flat(out.fileModes.size(), Shading::Flat);
    const std::vector<bool> visible(flat.size(), true);
    out.scene = std::make_shared<const Scene>(parseScene(
        rewriteMeshes(text, flat, visible, sceneFile.parent_path(), sceneFile.parent_path()),
        sceneFile, budget, meshes));
  } else {
    auto scene = std::make_shared<Scene>(loadScene(file, budget));
    out.fileModes.clear();
    for (Mesh& m : scene->meshes) {
      out.fileModes.push_back(m.shading());
      m.setShading(Shading::Flat);
    }
    out.scene = std::move(scene);
  }
  out.ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace meshtrace::viewer
