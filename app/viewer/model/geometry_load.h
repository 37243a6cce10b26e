#pragma once
// Opening a scene in two stages: first its geometry, every mesh read as
// FLAT, then (render_scene.h) the file's shading modes. The vertex normals
// of a PHONG mesh take about a third of a large mesh's load; read this way,
// a first look at the scene need not wait for them.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "meshtrace/geometry/scene.h"

namespace meshtrace::viewer {

struct LoadedScene {
  std::shared_ptr<const Scene> scene;  // every mesh FLAT
  std::vector<Shading> fileModes;      // per mesh, the mode the file gives it
  double ms = 0.0;                     // reading and parsing
  // For a bare mesh file, the .sce text made for it (mesh_scene.h), whose
  // mesh line is relative to the mesh's folder; empty for a scene file.
  std::string generatedText;
};

// Whether `file` is opened as a bare mesh: a mesh file framed as a scene
// the way raytrace frames it (mesh_scene.h), rather than a .sce file.
bool isBareMesh(const std::filesystem::path& file);

// Throws what loadScene throws (InputError naming the file and line) for a
// scene that does not load; for a bare mesh, what meshSceneText throws.
LoadedScene loadGeometry(const std::filesystem::path& file);

}  // namespace meshtrace::viewer
