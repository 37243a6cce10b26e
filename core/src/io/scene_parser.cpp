#include "meshtrace/io/scene_parser.h"

#include <tbb/parallel_for.h>

#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "io/file_source.h"
#include "io/text.h"
#include "io/token_stream.h"
#include "meshtrace/io/input_error.h"
#include "meshtrace/io/load_observer.h"
#include "meshtrace/io/mesh_reader.h"

namespace meshtrace {

namespace {
constexpr std::uintmax_t kMaxSceneBytes = std::uintmax_t{256} << 20;
// Refuse images that would need gigabytes before allocating them: 2^25
// pixels holds 8K UHD (7680 x 4320) and needs 0.8 GB of double colour.
constexpr int kMaxImageSide = 16384;
constexpr long long kMaxImagePixels = 1LL << 25;
constexpr int kMaxDepth = 1000;

// A `mesh` line, read before any mesh file is.
struct MeshLine {
  std::filesystem::path file;
  Shading shading;
  Material material;
  std::size_t line;
};

class SceneParser {
 public:
  SceneParser(text::TokenStream& words, const std::filesystem::path& file, MemoryBudget& budget,
              const MeshSource& meshes)
      : file_(file), words_(words), budget_(budget), meshes_(meshes) {}

  Scene parse() {
    Scene scene;
    scene.file = file_;
    bool haveCamera = false;
    CameraSpec cameraSpec;
    std::size_t cameraLine = 0;
    std::vector<MeshLine> meshLines;
    text::Word word;
    while (words_.next(word)) {
      entity_.assign(word.text);
      entityLine_ = word.line;
      const std::string_view k = entity_;
      if (k == "camera") {
        cameraSpec = readCamera();
        cameraLine = entityLine_;
        haveCamera = true;
      } else if (k == "depth") {
        scene.depth = readInt("depth", 0, kMaxDepth);
      } else if (k == "background") {
        scene.background = readVec3("background colour");
      } else if (k == "ambience") {
        scene.ambience = readVec3("ambience colour");
      } else if (k == "light") {
        Light light;
        light.position = readVec3("light position");
        light.color = readVec3("light colour");
        scene.lights.push_back(light);
        lightLines_.push_back(entityLine_);
      } else if (k == "sphere") {
        Sphere s;
        s.center = readVec3("sphere center");
        s.radius = readPositive("sphere radius");
        s.material = readMaterial();
        scene.spheres.push_back(s);
      } else if (k == "plane") {
        Plane p;
        p.point = readVec3("plane point");
        p.normal = readDirection("plane normal");
        p.material = readMaterial();
        scene.planes.push_back(p);
      } else if (k == "cylinder") {
        Cylinder c;
        c.center = readVec3("cylinder center");
        c.radius = readPositive("cylinder radius");
        c.axis = readDirection("cylinder axis");
        c.height = readPositive("cylinder height");
        c.material = readMaterial();
        scene.cylinders.push_back(c);
      } else if (k == "mesh") {
        meshLines.push_back(readMeshLine());
      } else {
        failAt(entityLine_, "unknown keyword " + quoted(k));
      }
    }
    if (!haveCamera && !words_.sawText()) throw InputError::inFile(file_, "empty scene file");
    if (!haveCamera) throw InputError::inFile(file_, "no 'camera' line: a scene needs a camera");
    scene.camera = Camera(cameraSpec);
    if (scene.camera.upWasReplaced()) {
      scene.warnings.push_back(file_.string() + ":" + std::to_string(cameraLine) +
                               ": camera up vector is parallel to the view direction; "
                               "using another axis as up");
    }
    std::vector<std::size_t> untiled(meshLines.size());
    scene.meshes = loadMeshes(meshLines, untiled);
    // A file of vertices and no faces (a point cloud, or a PLY whose face
    // element is named otherwise) is a mesh, but draws nothing: say so, or
    // the user sees an empty scene and no reason.
    for (std::size_t i = 0; i < meshLines.size(); ++i)
      if (scene.meshes[i].triangles().empty())
        scene.warnings.push_back(file_.string() + ":" + std::to_string(meshLines[i].line) +
                                 ": mesh " + meshLines[i].file.filename().string() +
                                 " has no faces: it draws nothing");
    // A face that winds both ways (a bow tie) has no triangulation; the
    // user should know why its triangles spill over its outline.
    for (std::size_t i = 0; i < meshLines.size(); ++i) {
      if (untiled[i] == 0) continue;
      const bool one = untiled[i] == 1;
      scene.warnings.push_back(
          file_.string() + ":" + std::to_string(meshLines[i].line) + ": mesh " +
          meshLines[i].file.filename().string() + " has " + std::to_string(untiled[i]) +
          (one ? " face that no triangles cover exactly (it crosses itself, or is too intricate "
                 "to cut): its triangles may cover area outside it"
               : " faces that no triangles cover exactly (they cross themselves, or are too "
                 "intricate to cut): their triangles may cover area outside them"));
    }
    checkLights(scene);
    return scene;
  }

 private:
  [[noreturn]] void failAt(std::size_t line, const std::string& what) const {
    throw InputError::atLine(file_, line, what);
  }

  // The next word of the current entity.
  text::Word take(const std::string& what) {
    text::Word word;
    if (!words_.next(word)) {
      failAt(entityLine_, meshtrace::quoted(entity_) + " is incomplete: the file ends where the " +
                              what + " belongs");
    }
    return word;
  }

  struct Number {
    double value;
    std::size_t line;
  };

  Number readNumber(const std::string& what) {
    const text::Word w = take(what);
    double v = 0.0;
    if (!text::parseDouble(w.text, v)) {
      failAt(w.line, "expected a number for the " + what + " of " + meshtrace::quoted(entity_) +
                         " (line " + std::to_string(entityLine_) + "), found " + quoted(w.text));
    }
    if (!std::isfinite(v)) failAt(w.line, "the " + what + " is not finite: " + quoted(w.text));
    return {v, w.line};
  }

  int readInt(const std::string& what, long long lo, long long hi) {
    const text::Word w = take(what);
    std::int64_t v = 0;
    if (!text::parseInt64(w.text, v))
      failAt(w.line, "expected a whole number for the " + what + ", found " + quoted(w.text));
    if (v < lo || v > hi) {
      failAt(w.line, "the " + what + " " + std::to_string(v) + " is outside " + std::to_string(lo) +
                         ".." + std::to_string(hi));
    }
    return static_cast<int>(v);
  }

  // Three numbers, and the line of the first.
  Vec3 readVec3(const std::string& what, std::size_t* line = nullptr) {
    Vec3 v;
    for (int k = 0; k < 3; ++k) {
      const Number n = readNumber(what);
      if (k == 0 && line) *line = n.line;
      v[k] = n.value;
    }
    return v;
  }

  double readPositive(const std::string& what) {
    const Number n = readNumber(what);
    if (!(n.value > 0.0))
      failAt(n.line, "the " + what + " must be positive, got " + std::to_string(n.value));
    return n.value;
  }

  // A unit vector from three numbers of any size: (1e-200, 0, 0) is the x
  // axis, only (0, 0, 0) has no direction.
  Vec3 readDirection(const std::string& what) {
    std::size_t line = 0;
    const Vec3 v = readVec3(what, &line);
    if (v == Vec3(0.0)) failAt(line, "the " + what + " is the zero vector");
    const Vec3 scaled = scaledToUnitRange(v);
    return scaled / glm::length(scaled);
  }

  Material readMaterial() {
    Material m;
    m.ambient = readVec3("ambient colour");
    m.diffuse = readVec3("diffuse colour");
    m.specular = readVec3("specular colour");
    m.shininess = readNumber("shininess").value;
    const Number mirror = readNumber("mirror reflectivity");
    m.mirror = mirror.value;
    if (m.mirror < 0.0 || m.mirror > 1.0)
      failAt(mirror.line,
             "the mirror reflectivity must lie in [0, 1], got " + std::to_string(m.mirror));
    return m;
  }

  CameraSpec readCamera() {
    CameraSpec c;
    c.eye = readVec3("camera eye");
    c.center = readVec3("camera center");
    c.up = readVec3("camera up vector");
    const Number fovy = readNumber("camera fovy");
    c.fovyDegrees = fovy.value;
    c.width = readInt("image width", 1, kMaxImageSide);
    c.height = readInt("image height", 1, kMaxImageSide);
    if (static_cast<long long>(c.width) * c.height > kMaxImagePixels) {
      failAt(entityLine_, "image of " + std::to_string(c.width) + "x" + std::to_string(c.height) +
                              " pixels is larger than the " + std::to_string(kMaxImagePixels) +
                              " accepted");
    }
    if (!(c.fovyDegrees > 0.0 && c.fovyDegrees < 180.0))
      failAt(fovy.line, "the camera fovy must lie strictly between 0 and 180 degrees");
    const std::string problem = cameraProblem(c);
    if (!problem.empty()) failAt(entityLine_, problem);
    return c;
  }

  MeshLine readMeshLine() {
    const text::Word name = take("mesh file name");
    const std::filesystem::path file = file_.parent_path() / std::string(name.text);
    const std::size_t line = name.line;
    const text::Word mode = take("shading mode");
    Shading shading{};
    try {
      shading = parseShading(mode.text);
    } catch (const std::invalid_argument& e) {
      failAt(mode.line, e.what());
    }
    const Material material = readMaterial();
    return {file, shading, material, line};
  }

  // The meshes load side by side once the whole scene file has parsed (a
  // mistake anywhere in it is reported before any mesh is read): a mesh of
  // ~10k triangles loads mostly on one thread, so several small meshes load
  // faster together than in turn. Of the meshes that fail, the first in the
  // file is reported.
  // untiled[i]: mesh i's faces that no triangulation tiles.
  std::vector<Mesh> loadMeshes(const std::vector<MeshLine>& lines,
                               std::vector<std::size_t>& untiled) const {
    std::vector<std::optional<Mesh>> loaded(lines.size());
    std::vector<std::exception_ptr> failed(lines.size());
    tbb::parallel_for(std::size_t{0}, lines.size(), [&](std::size_t i) {
      const MeshLine& m = lines[i];
      try {
        MeshData data = meshes_ ? meshes_(m.file, budget_) : readMesh(m.file, budget_);
        untiled[i] = data.untiledPolygons;
        budget_.reserve(normalsBytes(data, m.shading), "load",
                        "the normals of " + m.file.filename().string());
        if (LoadObserver* observer = budget_.loadObserver()) observer->phase(m.file, "normals");
        loaded[i].emplace(m.file, std::move(data), m.shading, m.material);
      } catch (const InputError& e) {
        failed[i] = std::make_exception_ptr(
            InputError::atLine(file_, m.line, std::string("mesh: ") + e.what()));
      } catch (...) {
        failed[i] = std::current_exception();
      }
    });
    std::vector<Mesh> meshes;
    meshes.reserve(lines.size());
    for (std::size_t i = 0; i < lines.size(); ++i) {
      if (failed[i]) std::rethrow_exception(failed[i]);
      meshes.push_back(std::move(*loaded[i]));
    }
    return meshes;
  }

  // Shading normalises the direction from each lit point to each light: its
  // squared length must stay finite, so no light may be farther than this
  // from a point of the scene (3 x 1e306 < 1.8e308, the largest double).
  static constexpr double kMaxLightReach = 1e153;

  // Each light against the farthest point the scene can shade: the eye,
  // the plane points and the corners of every bounded object's box.
  void checkLights(const Scene& scene) const {
    Aabb reach;
    reach.extend(scene.camera.spec().eye);
    for (const Plane& p : scene.planes) reach.extend(p.point);
    for (const Sphere& s : scene.spheres) {
      reach.extend(s.center - Vec3(s.radius));
      reach.extend(s.center + Vec3(s.radius));
    }
    for (const Cylinder& c : scene.cylinders) {
      const Vec3 half(c.radius + 0.5 * c.height);
      reach.extend(c.center - half);
      reach.extend(c.center + half);
    }
    for (const Mesh& m : scene.meshes)
      if (!m.bounds().empty()) reach.extend(m.bounds());
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
      const Vec3& light = scene.lights[i].position;
      const double far =
          std::max(maxAbsComponent(light - reach.min), maxAbsComponent(light - reach.max));
      if (!(far <= kMaxLightReach)) {
        failAt(lightLines_[i], "the light is too far from the scene: " + shortestText(far) +
                                   " from its farthest point, where directions to it overflow "
                                   "double precision (at most 1e+153)");
      }
    }
  }

  // What a Mesh computes from `data`: for PHONG, a normal per vertex, with
  // the arrays that sum them (mesh.cpp); a FLAT mesh nothing.
  static std::uint64_t normalsBytes(const MeshData& data, Shading shading) {
    if (shading != Shading::Phong) return 0;
    const std::uint64_t triangles = data.triangles.size(), vertices = data.vertices.size();
    return vertices * (sizeof(Vec3) + 8) + triangles * 14;
  }

  const std::filesystem::path& file_;
  text::TokenStream& words_;
  MemoryBudget& budget_;
  const MeshSource& meshes_;             // empty: readMesh
  std::vector<std::size_t> lightLines_;  // the line of each light
  std::string entity_;                   // the keyword being read, for messages
  std::size_t entityLine_ = 0;
};
}  // namespace

Scene parseScene(std::string_view text, const std::filesystem::path& file, MemoryBudget& budget,
                 const MeshSource& meshes) {
  text::TokenStream words(text, file);
  return SceneParser(words, file, budget, meshes).parse();
}

Scene parseScene(std::string_view text, const std::filesystem::path& file, MemoryBudget& budget) {
  return parseScene(text, file, budget, MeshSource());
}

Scene parseScene(std::string_view text, const std::filesystem::path& file) {
  MemoryBudget budget(defaultMemoryLimit());
  return parseScene(text, file, budget);
}

Scene loadScene(const std::filesystem::path& file, MemoryBudget& budget) {
  text::FileSource source(file, kMaxSceneBytes);
  text::TokenStream words(source);
  return SceneParser(words, file, budget, MeshSource()).parse();
}

Scene loadScene(const std::filesystem::path& file) {
  MemoryBudget budget(defaultMemoryLimit());
  return loadScene(file, budget);
}

bool isSceneWord(std::string_view text) {
  if (text.empty()) return false;
  for (const char c : text)
    if (text::endsWord(c)) return false;
  return true;
}

}  // namespace meshtrace
