// Fuzzes the OFF reader and the BVH over what it reads. Each input is read
// twice: as given, and with a block of comment lines the size of the
// reader's 256 KiB parse chunks inserted at one of its line breaks, which
// moves the chunk boundaries into the input's own lines. Comment lines
// change nothing, so both readings must give the same mesh, bit for bit,
// or both throw InputError. A mesh that loads is shaded PHONG and rendered
// from a camera that frames it, in quads with packets through the BVH, and
// each pixel must equal brute force's (packets_match.h).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>

#include "meshtrace/io/input_error.h"
#include "meshtrace/io/off_reader.h"
#include "packets_match.h"

namespace {

using namespace meshtrace;

constexpr std::size_t kChunkBytes = std::size_t{1} << 18;

std::filesystem::path scratchFile(const char* name) {
  return std::filesystem::temp_directory_path() /
         ("meshtrace-fuzz-" + std::to_string(getpid()) + "-" + name + ".off");
}

std::optional<MeshData> read(std::string_view bytes, const std::filesystem::path& file) {
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  try {
    return readOff(file);
  } catch (const InputError&) {
    return std::nullopt;
  }
}

// The input with comment lines inserted after one of its line breaks,
// using that break's own line end: a chunk's worth of them less up to 4 KiB
// (the longest input), so that the chunk boundary falls a little past the
// insertion. The hash of the input picks the break and the shortfall.
std::string padded(std::string_view text) {
  std::uint64_t hash = 14695981039346656037u;
  for (char c : text) hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211u;
  std::size_t breaks = 0;
  for (char c : text) breaks += c == '\n';
  if (breaks == 0) return std::string(text);
  std::size_t at = 0;
  for (std::size_t n = hash % breaks + 1; n > 0; --n) at = text.find('\n', at) + 1;
  const bool crlf = at >= 2 && text[at - 2] == '\r';
  const std::string line = std::string(62, '#') + (crlf ? "\r\n" : "\n");
  std::string out(text.substr(0, at));
  for (std::size_t bytes = 0; bytes + (hash >> 32) % 4096 < kChunkBytes; bytes += line.size())
    out += line;
  out += text.substr(at);
  return out;
}

bool same(const MeshData& a, const MeshData& b) {
  return a.vertices.size() == b.vertices.size() && a.triangles == b.triangles &&
         (a.vertices.empty() ||
          std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(Vec3)) == 0);
}

// A scene of the mesh alone, seen from outside its box along a diagonal,
// lit from the eye; none if the box is too large or too flat for a camera.
std::optional<Scene> framing(Mesh mesh) {
  const Aabb box = mesh.bounds();
  const Vec3 center = box.center();
  const double size = glm::length(box.extent());
  const Vec3 eye = center + 1.5 * size * glm::normalize(Vec3(0.3, 0.4, 1.0));
  if (!(size > 0.0) || !isFinite(eye) || !isFinite(center) || eye == center) return std::nullopt;
  Scene scene;
  scene.file = "fuzz.sce";
  scene.camera = Camera(CameraSpec{eye, center, {0.0, 1.0, 0.0}, 50.0, 16, 16});
  scene.ambience = Color(0.2);
  scene.lights.push_back({eye, Color(0.8)});
  scene.meshes.push_back(std::move(mesh));
  return scene;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path plainFile = scratchFile("plain"),
                                     paddedFile = scratchFile("padded");
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::optional<MeshData> mesh = read(text, plainFile);
  const std::optional<MeshData> again = read(padded(text), paddedFile);
  if (mesh.has_value() != again.has_value() || (mesh && !same(*mesh, *again))) {
    std::fprintf(stderr, "the comment lines changed the reading: %s\n",
                 !mesh    ? "only the padded input loads"
                 : !again ? "only the plain input loads"
                          : "the meshes differ");
    std::abort();
  }
  if (!mesh) return 0;
  Material material{Color(0.2), Color(0.6), Color(0.3), 20.0, 0.0};
  if (std::optional<Scene> scene =
          framing(Mesh("fuzz.off", std::move(*mesh), Shading::Phong, material)))
    fuzz::expectPacketsMatchBruteForce(*scene);
  return 0;
}
