#include "meshtrace/io/off_reader.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <exception>
#include <string>
#include <vector>

#include "io/text.h"
#include "meshtrace/io/input_error.h"

namespace meshtrace {

namespace {
// Meshes beyond this are refused rather than loaded into memory.
constexpr std::uintmax_t kMaxOffBytes = std::uintmax_t{4} << 30;
// The shortest lines that can hold a vertex ("0 0 0\n") and a triangle
// ("3 0 1 2\n"): counts needing more bytes than the file has are refused
// before anything is reserved.
constexpr std::uintmax_t kMinVertexBytes = 6;
constexpr std::uintmax_t kMinFaceBytes = 8;

// The body (the vertex and face lines after the header) is parsed in
// chunks of whole lines, in parallel: a first pass counts each chunk's lines
// and non-empty lines, which tells every chunk the line number and the
// element (vertex or face) its first line has; a second pass parses. A
// chunk stops at its first bad line, and the error of the earliest bad line
// in the file is the one reported, as a serial reader would report it.
constexpr std::size_t kChunkBytes = std::size_t{1} << 18;

class OffParser {
 public:
  OffParser(std::string_view text, const std::filesystem::path& file) : file_(file), text_(text) {}

  MeshData parse() {
    text::LineReader header(text_);
    std::int64_t counts[3] = {0, 0, 0};
    readHeader(header, counts);
    nv_ = counts[0];
    nf_ = counts[1];
    // Divide rather than multiply: counts near 2^63 would wrap the product
    // around to a small number and pass.
    const auto vertexCount = static_cast<std::uintmax_t>(nv_);
    const auto faceCount = static_cast<std::uintmax_t>(nf_);
    const std::uintmax_t size = text_.size();
    if (vertexCount > size / kMinVertexBytes || faceCount > size / kMinFaceBytes ||
        vertexCount * kMinVertexBytes + faceCount * kMinFaceBytes > size) {
      throw InputError::atLine(file_, header.lineNumber(),
                               "header announces " + std::to_string(nv_) + " vertices and " +
                                   std::to_string(nf_) + " faces, more than a " +
                                   std::to_string(size) + "-byte file can hold");
    }
    MeshData mesh;
    mesh.vertices.resize(static_cast<std::size_t>(nv_));
    std::vector<Chunk> chunks = split(text_.substr(header.offset()));
    tbb::parallel_for(std::size_t(0), chunks.size(), [&](std::size_t c) { count(chunks[c]); });
    std::int64_t elements = 0;
    std::size_t lineBefore = header.lineNumber();
    for (Chunk& c : chunks) {
      c.firstElement = elements;
      elements += c.elements;
      c.lineBefore = lineBefore;
      lineBefore += c.lines;
    }
    tbb::parallel_for(std::size_t(0), chunks.size(),
                      [&](std::size_t c) { parseChunk(chunks[c], mesh.vertices); });
    for (const Chunk& c : chunks)
      if (c.error) std::rethrow_exception(c.error);
    if (elements < nv_ + nf_) {
      const bool vertex = elements < nv_;
      throw InputError::inFile(file_, "file ends at " + std::string(vertex ? "vertex " : "face ") +
                                          std::to_string(vertex ? elements : elements - nv_) +
                                          " of " + std::to_string(vertex ? nv_ : nf_) +
                                          " announced in the header");
    }
    std::size_t triangles = 0;
    for (const Chunk& c : chunks) triangles += c.triangles.size();
    mesh.triangles.reserve(triangles);
    for (const Chunk& c : chunks)
      mesh.triangles.insert(mesh.triangles.end(), c.triangles.begin(), c.triangles.end());
    return mesh;
  }

 private:
  struct Chunk {
    std::string_view text;       // whole lines
    std::size_t lines = 0;       // all its lines
    std::int64_t elements = 0;   // its non-empty lines
    std::size_t lineBefore = 0;  // the number of the line before its first
    std::int64_t firstElement = 0;
    std::vector<TriangleIndices> triangles;
    std::exception_ptr error;
  };

  // Pieces of about kChunkBytes, each ending after a line break (or at the
  // end of the text).
  static std::vector<Chunk> split(std::string_view body) {
    std::vector<Chunk> chunks;
    std::size_t begin = 0;
    while (begin < body.size()) {
      std::size_t end = begin + kChunkBytes;
      if (end >= body.size()) {
        end = body.size();
      } else {
        end = body.find('\n', end);
        end = end == std::string_view::npos ? body.size() : end + 1;
      }
      Chunk c;
      c.text = body.substr(begin, end - begin);
      chunks.push_back(std::move(c));
      begin = end;
    }
    return chunks;
  }

  static void count(Chunk& c) {
    text::LineReader lines(c.text);
    std::string_view line;
    while (lines.nextNonEmpty(line)) ++c.elements;
    c.lines = lines.lineNumber();
  }

  void parseChunk(Chunk& c, std::vector<Vec3>& vertices) const {
    text::LineReader lines(c.text);
    std::string_view line;
    for (std::int64_t e = c.firstElement; e < nv_ + nf_ && lines.nextNonEmpty(line); ++e) {
      try {
        const std::size_t lineNumber = c.lineBefore + lines.lineNumber();
        if (e < nv_)
          vertices[static_cast<std::size_t>(e)] = readVertex(line, e, lineNumber);
        else
          readFace(line, e - nv_, lineNumber, c.triangles);
      } catch (const InputError&) {
        c.error = std::current_exception();
        return;
      }
    }
  }

  void readHeader(text::LineReader& lines, std::int64_t counts[3]) const {
    std::string_view line;
    if (!lines.nextNonEmpty(line)) throw InputError::inFile(file_, "empty file: no OFF header");
    const auto fail = [&](const std::string& what) {
      throw InputError::atLine(file_, lines.lineNumber(), what);
    };
    text::TokenReader tokens(line);
    std::string_view token;
    tokens.next(token);
    // "OFF", or its variants with per-vertex colours/normals ("COFF", "NOFF",
    // "CNOFF"): the extra vertex values are ignored.
    if (token.size() < 3 || token.substr(token.size() - 3) != "OFF" || token.size() > 5) {
      fail("bad header " + quoted(token) + ": an OFF file starts with 'OFF'");
    }
    const auto parseCount = [&](std::string_view t, std::int64_t& out) {
      if (!text::parseInt64(t, out)) fail("bad count " + quoted(t) + " in header");
      if (out < 0) fail("negative count " + std::to_string(out) + " in header");
    };
    int found = 0;
    while (found < 3 && tokens.next(token)) parseCount(token, counts[found++]);
    while (found < 2) {  // counts on the following line
      if (!lines.nextNonEmpty(line)) fail("file ends before the vertex and face counts");
      text::TokenReader more(line);
      while (found < 3 && more.next(token)) parseCount(token, counts[found++]);
    }
  }

  Vec3 readVertex(std::string_view line, std::int64_t index, std::size_t lineNumber) const {
    const auto fail = [&](const std::string& what) {
      throw InputError::atLine(file_, lineNumber, "vertex " + std::to_string(index) + what);
    };
    text::TokenReader tokens(line);
    Vec3 v;
    for (int k = 0; k < 3; ++k) {
      std::string_view token;
      if (!tokens.next(token)) fail(" has fewer than 3 coordinates");
      if (!text::parseDouble(token, v[k])) fail(": " + quoted(token) + " is not a number");
      if (!std::isfinite(v[k])) fail(" has a non-finite coordinate " + quoted(token));
    }
    return v;
  }

  void readFace(std::string_view line, std::int64_t index, std::size_t lineNumber,
                std::vector<TriangleIndices>& triangles) const {
    const auto fail = [&](const std::string& what) {
      throw InputError::atLine(file_, lineNumber, "face " + std::to_string(index) + what);
    };
    text::TokenReader tokens(line);
    std::string_view token;
    std::int64_t corners = 0;
    tokens.next(token);
    if (!text::parseInt64(token, corners)) fail(": bad corner count " + quoted(token));
    if (corners < 3) fail(" has " + std::to_string(corners) + " corners; at least 3 are needed");
    std::uint32_t first = 0, previous = 0;
    for (std::int64_t k = 0; k < corners; ++k) {
      std::int64_t v = 0;
      if (!tokens.next(token))
        fail(" announces " + std::to_string(corners) + " corners but lists " + std::to_string(k));
      if (!text::parseInt64(token, v)) fail(": bad vertex index " + quoted(token));
      if (v < 0 || v >= nv_) {
        fail(": vertex index " + std::to_string(v) + " out of range (the mesh has " +
             std::to_string(nv_) + " vertices)");
      }
      const auto current = static_cast<std::uint32_t>(v);
      if (k == 0) first = current;
      if (k >= 2) triangles.push_back({first, previous, current});  // fan
      previous = current;
    }
    // Any further values on the line (face colours) are ignored.
  }

  const std::filesystem::path& file_;
  std::string_view text_;
  std::int64_t nv_ = 0, nf_ = 0;
};
}  // namespace

MeshData readOff(const std::filesystem::path& file) {
  const text::FileBytes data = text::readFile(file, kMaxOffBytes);
  text::requireText(data.text(), file);
  return OffParser(data.text(), file).parse();
}

}  // namespace meshtrace
