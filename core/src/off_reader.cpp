#include "meshtrace/off_reader.h"

#include <string>

#include "meshtrace/input_error.h"
#include "text.h"

namespace meshtrace {

namespace {
// Meshes beyond this are refused rather than loaded into memory.
constexpr std::uintmax_t kMaxOffBytes = std::uintmax_t{4} << 30;
// The shortest lines that can hold a vertex ("0 0 0\n") and a triangle
// ("3 0 1 2\n"): counts needing more bytes than the file has are refused
// before anything is reserved.
constexpr std::uintmax_t kMinVertexBytes = 6;
constexpr std::uintmax_t kMinFaceBytes = 8;

class OffParser {
 public:
  OffParser(std::string_view text, const std::filesystem::path& file)
      : file_(file), lines_(text), size_(text.size()) {}

  MeshData parse() {
    std::int64_t counts[3] = {0, 0, 0};
    readHeader(counts);
    const std::int64_t nv = counts[0], nf = counts[1];
    // Divide rather than multiply: counts near 2^63 would wrap the product
    // around to a small number and pass.
    const auto vertexCount = static_cast<std::uintmax_t>(nv);
    const auto faceCount = static_cast<std::uintmax_t>(nf);
    if (vertexCount > size_ / kMinVertexBytes || faceCount > size_ / kMinFaceBytes ||
        vertexCount * kMinVertexBytes + faceCount * kMinFaceBytes > size_) {
      fail("header announces " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
           " faces, more than a " + std::to_string(size_) + "-byte file can hold");
    }
    MeshData mesh;
    mesh.vertices.reserve(static_cast<std::size_t>(nv));
    mesh.triangles.reserve(static_cast<std::size_t>(nf));
    for (std::int64_t i = 0; i < nv; ++i) readVertex(i, nv, mesh);
    for (std::int64_t i = 0; i < nf; ++i) readFace(i, nf, mesh);
    return mesh;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError::atLine(file_, lines_.lineNumber(), what);
  }

  std::string_view requireLine(const std::string& element, std::int64_t index,
                               std::int64_t count) {
    std::string_view line;
    if (!lines_.nextNonEmpty(line)) {
      throw InputError::inFile(file_, "file ends at " + element + " " + std::to_string(index) +
                                          " of " + std::to_string(count) +
                                          " announced in the header");
    }
    return line;
  }

  void readHeader(std::int64_t counts[3]) {
    std::string_view line;
    if (!lines_.nextNonEmpty(line)) throw InputError::inFile(file_, "empty file: no OFF header");
    text::TokenReader tokens(line);
    std::string_view token;
    tokens.next(token);
    // "OFF", or its variants with per-vertex colours/normals ("COFF", "NOFF",
    // "CNOFF"): the extra vertex values are ignored.
    if (token.size() < 3 || token.substr(token.size() - 3) != "OFF" || token.size() > 5) {
      fail("bad header " + text::quoted(token) + ": an OFF file starts with 'OFF'");
    }
    int found = 0;
    while (found < 3 && tokens.next(token)) parseCount(token, counts[found++]);
    while (found < 2) {  // counts on the following line
      if (!lines_.nextNonEmpty(line)) fail("file ends before the vertex and face counts");
      text::TokenReader more(line);
      while (found < 3 && more.next(token)) parseCount(token, counts[found++]);
    }
  }

  void parseCount(std::string_view token, std::int64_t& out) {
    if (!text::parseInt64(token, out)) fail("bad count " + text::quoted(token) + " in header");
    if (out < 0) fail("negative count " + std::to_string(out) + " in header");
  }

  void readVertex(std::int64_t index, std::int64_t count, MeshData& mesh) {
    text::TokenReader tokens(requireLine("vertex", index, count));
    Vec3 v;
    for (int k = 0; k < 3; ++k) {
      std::string_view token;
      if (!tokens.next(token)) fail("vertex " + std::to_string(index) + " has fewer than 3 coordinates");
      if (!text::parseDouble(token, v[k]))
        fail("vertex " + std::to_string(index) + ": " + text::quoted(token) + " is not a number");
      if (!std::isfinite(v[k]))
        fail("vertex " + std::to_string(index) + " has a non-finite coordinate " + text::quoted(token));
    }
    mesh.vertices.push_back(v);
  }

  void readFace(std::int64_t index, std::int64_t count, MeshData& mesh) {
    text::TokenReader tokens(requireLine("face", index, count));
    const std::string face = "face " + std::to_string(index);
    std::string_view token;
    std::int64_t corners = 0;
    tokens.next(token);
    if (!text::parseInt64(token, corners)) fail(face + ": bad corner count " + text::quoted(token));
    if (corners < 3) fail(face + " has " + std::to_string(corners) + " corners; at least 3 are needed");
    const auto nv = static_cast<std::int64_t>(mesh.vertices.size());
    std::uint32_t first = 0, previous = 0;
    for (std::int64_t k = 0; k < corners; ++k) {
      std::int64_t v = 0;
      if (!tokens.next(token))
        fail(face + " announces " + std::to_string(corners) + " corners but lists " + std::to_string(k));
      if (!text::parseInt64(token, v)) fail(face + ": bad vertex index " + text::quoted(token));
      if (v < 0 || v >= nv) {
        fail(face + ": vertex index " + std::to_string(v) + " out of range (the mesh has " +
             std::to_string(nv) + " vertices)");
      }
      const auto current = static_cast<std::uint32_t>(v);
      if (k == 0) first = current;
      if (k >= 2) mesh.triangles.push_back({first, previous, current});  // fan
      previous = current;
    }
    // Any further values on the line (face colours) are ignored.
  }

  const std::filesystem::path& file_;
  text::LineReader lines_;
  std::uintmax_t size_;
};
}  // namespace

MeshData readOff(const std::filesystem::path& file) {
  const std::string data = text::readFile(file, kMaxOffBytes);
  text::requireText(data, file);
  return OffParser(data, file).parse();
}

}  // namespace meshtrace
