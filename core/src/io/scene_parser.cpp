#include "meshtrace/io/scene_parser.h"

#include <tbb/parallel_for.h>

#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "io/text.h"
#include "meshtrace/io/input_error.h"
#include "meshtrace/io/off_reader.h"

namespace meshtrace {

namespace {
constexpr std::uintmax_t kMaxSceneBytes = std::uintmax_t{256} << 20;
// Refuse images that would need gigabytes before allocating them: 2^25
// pixels holds 8K UHD (7680 x 4320) and needs 0.8 GB of double colour.
constexpr int kMaxImageSide = 16384;
constexpr long long kMaxImagePixels = 1LL << 25;
constexpr int kMaxDepth = 1000;

struct Token {
  std::string_view text;
  std::size_t line;
};

// A `mesh` line, read before any mesh file is.
struct MeshLine {
  std::filesystem::path file;
  Shading shading;
  Material material;
  std::size_t line;
};

class SceneParser {
 public:
  SceneParser(std::string_view text, const std::filesystem::path& file) : file_(file) {
    text::LineReader lines(text);
    std::string_view line;
    while (lines.nextNonEmpty(line)) {
      text::TokenReader words(line);
      std::string_view word;
      while (words.next(word)) tokens_.push_back({word, lines.lineNumber()});
    }
  }

  Scene parse() {
    Scene scene;
    scene.file = file_;
    bool haveCamera = false;
    CameraSpec cameraSpec;
    std::size_t cameraLine = 0;
    std::vector<MeshLine> meshLines;
    while (pos_ < tokens_.size()) {
      const Token keyword = tokens_[pos_++];
      entity_ = keyword;
      const std::string_view k = keyword.text;
      if (k == "camera") {
        cameraSpec = readCamera();
        cameraLine = keyword.line;
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
        failAt(keyword.line, "unknown keyword " + quoted(k));
      }
    }
    if (!haveCamera) throw InputError::inFile(file_, "no 'camera' line: a scene needs a camera");
    scene.camera = Camera(cameraSpec);
    if (scene.camera.upWasReplaced()) {
      scene.warnings.push_back(file_.string() + ":" + std::to_string(cameraLine) +
                               ": camera up vector is parallel to the view direction; "
                               "using another axis as up");
    }
    scene.meshes = loadMeshes(meshLines);
    return scene;
  }

 private:
  [[noreturn]] void failAt(std::size_t line, const std::string& what) const {
    throw InputError::atLine(file_, line, what);
  }

  const Token& take(const std::string& what) {
    if (pos_ >= tokens_.size()) {
      failAt(entity_.line, "'" + std::string(entity_.text) +
                               "' is incomplete: the file ends where the " + what + " belongs");
    }
    return tokens_[pos_++];
  }

  double readNumber(const std::string& what) {
    const Token& t = take(what);
    double v = 0.0;
    if (!text::parseDouble(t.text, v)) {
      failAt(t.line, "expected a number for the " + what + " of '" + std::string(entity_.text) +
                         "' (line " + std::to_string(entity_.line) + "), found " + quoted(t.text));
    }
    if (!std::isfinite(v)) failAt(t.line, "the " + what + " is not finite: " + quoted(t.text));
    return v;
  }

  int readInt(const std::string& what, long long lo, long long hi) {
    const Token& t = take(what);
    std::int64_t v = 0;
    if (!text::parseInt64(t.text, v))
      failAt(t.line, "expected a whole number for the " + what + ", found " + quoted(t.text));
    if (v < lo || v > hi) {
      failAt(t.line, "the " + what + " " + std::to_string(v) + " is outside " + std::to_string(lo) +
                         ".." + std::to_string(hi));
    }
    return static_cast<int>(v);
  }

  Vec3 readVec3(const std::string& what) {
    Vec3 v;
    for (int k = 0; k < 3; ++k) v[k] = readNumber(what);
    return v;
  }

  double readPositive(const std::string& what) {
    const std::size_t line = pos_ < tokens_.size() ? tokens_[pos_].line : entity_.line;
    const double v = readNumber(what);
    if (!(v > 0.0)) failAt(line, "the " + what + " must be positive, got " + std::to_string(v));
    return v;
  }

  Vec3 readDirection(const std::string& what) {
    const std::size_t line = pos_ < tokens_.size() ? tokens_[pos_].line : entity_.line;
    const Vec3 v = readVec3(what);
    const double len = glm::length(v);
    if (!(len > 0.0) || !std::isfinite(len)) failAt(line, "the " + what + " is the zero vector");
    return v / len;
  }

  Material readMaterial() {
    Material m;
    m.ambient = readVec3("ambient colour");
    m.diffuse = readVec3("diffuse colour");
    m.specular = readVec3("specular colour");
    m.shininess = readNumber("shininess");
    const std::size_t line = pos_ < tokens_.size() ? tokens_[pos_].line : entity_.line;
    m.mirror = readNumber("mirror reflectivity");
    if (m.mirror < 0.0 || m.mirror > 1.0)
      failAt(line, "the mirror reflectivity must lie in [0, 1], got " + std::to_string(m.mirror));
    return m;
  }

  CameraSpec readCamera() {
    CameraSpec c;
    c.eye = readVec3("camera eye");
    c.center = readVec3("camera center");
    c.up = readVec3("camera up vector");
    const std::size_t fovLine = pos_ < tokens_.size() ? tokens_[pos_].line : entity_.line;
    c.fovyDegrees = readNumber("camera fovy");
    c.width = readInt("image width", 1, kMaxImageSide);
    c.height = readInt("image height", 1, kMaxImageSide);
    if (static_cast<long long>(c.width) * c.height > kMaxImagePixels) {
      failAt(entity_.line, "image of " + std::to_string(c.width) + "x" + std::to_string(c.height) +
                               " pixels is larger than the " + std::to_string(kMaxImagePixels) +
                               " accepted");
    }
    if (!(c.fovyDegrees > 0.0 && c.fovyDegrees < 180.0))
      failAt(fovLine, "the camera fovy must lie strictly between 0 and 180 degrees");
    if (c.eye == c.center) failAt(entity_.line, "the camera eye and center are the same point");
    if (glm::length(c.up) == 0.0) failAt(entity_.line, "the camera up vector is the zero vector");
    return c;
  }

  MeshLine readMeshLine() {
    const Token& name = take("mesh file name");
    const Token& mode = take("shading mode");
    Shading shading{};
    try {
      shading = parseShading(mode.text);
    } catch (const std::invalid_argument& e) {
      failAt(mode.line, e.what());
    }
    const Material material = readMaterial();
    return {file_.parent_path() / std::string(name.text), shading, material, name.line};
  }

  // The meshes load side by side once the whole scene file has parsed (a
  // mistake anywhere in it is reported before any mesh is read): a mesh of
  // ~10k triangles loads mostly on one thread, so several small meshes load
  // faster together than in turn. Of the meshes that fail, the first in the
  // file is reported.
  std::vector<Mesh> loadMeshes(const std::vector<MeshLine>& lines) const {
    std::vector<std::optional<Mesh>> loaded(lines.size());
    std::vector<std::exception_ptr> failed(lines.size());
    tbb::parallel_for(std::size_t{0}, lines.size(), [&](std::size_t i) {
      const MeshLine& m = lines[i];
      try {
        loaded[i].emplace(m.file, readOff(m.file), m.shading, m.material);
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

  const std::filesystem::path& file_;
  std::vector<Token> tokens_;
  std::size_t pos_ = 0;
  Token entity_{};
};
}  // namespace

Scene parseScene(std::string_view text, const std::filesystem::path& file) {
  text::requireText(text, file);
  return SceneParser(text, file).parse();
}

Scene loadScene(const std::filesystem::path& file) {
  const text::FileBytes data = text::readFile(file, kMaxSceneBytes);
  if (data.text().find_first_not_of(" \t\r\n") == std::string_view::npos)
    throw InputError::inFile(file, "empty scene file");
  return parseScene(data.text(), file);
}

}  // namespace meshtrace
