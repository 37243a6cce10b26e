#include "meshtrace/io/off_reader.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "io/element_lines.h"
#include "io/element_problems.h"
#include "io/file_source.h"
#include "io/line_pieces.h"
#include "io/mesh_arrays.h"
#include "io/text.h"
#include "io/vertex_line.h"
#include "meshtrace/geometry/polygon.h"
#include "meshtrace/io/input_error.h"
#include "meshtrace/io/mesh_reader.h"

namespace meshtrace {

namespace {
// Meshes beyond this are refused rather than loaded into memory.
constexpr std::uintmax_t kMaxOffBytes = std::uintmax_t{4} << 30;
static_assert(kMaxOffBytes <= std::uintmax_t{1} << 32, "line offsets are held in 32 bits");
// The shortest lines that can hold a vertex ("0 0 0\n") and a triangle
// ("3 0 1 2\n"): counts needing more bytes than the file has are refused
// before anything is reserved.
constexpr std::uintmax_t kMinVertexBytes = 6;
constexpr std::uintmax_t kMinFaceBytes = 8;

// The body (the vertex and face lines after the header) is read by
// text::readElementLines: counted and parsed in parallel, gathered in order.

class OffParser {
 public:
  OffParser(text::FileSource& source, MemoryBudget& budget)
      : file_(source.file()), source_(source), budget_(budget) {}

  MeshData parse() {
    text::LinePieces pieces(source_, text::kPieceBytes);
    auto first = std::make_unique<Chunk>();
    if (!pieces.next(first->piece) && !first->piece.nulAfter())
      throw InputError::inFile(file_, "empty file: no OFF header");
    std::int64_t counts[3] = {0, 0, 0};
    std::size_t headerLines = readHeader(pieces, *first, counts);
    nv_ = counts[0];
    nf_ = counts[1];
    // Divide rather than multiply: counts near 2^63 would wrap the product
    // around to a small number and pass.
    const auto vertexCount = static_cast<std::uintmax_t>(nv_);
    const auto faceCount = static_cast<std::uintmax_t>(nf_);
    const std::uintmax_t size = source_.size();
    if (vertexCount > size / kMinVertexBytes || faceCount > size / kMinFaceBytes ||
        vertexCount * kMinVertexBytes + faceCount * kMinFaceBytes > size) {
      throw InputError::atLine(file_, headerLines,
                               "header announces " + std::to_string(nv_) + " vertices and " +
                                   std::to_string(nf_) + " faces, more than a " +
                                   std::to_string(size) + "-byte file can hold");
    }
    mesh_arrays::sizeVertices(mesh_, budget_, static_cast<std::size_t>(nv_), file_);
    // Exact for a triangle mesh.
    mesh_arrays::growTriangles(mesh_, budget_, static_cast<std::size_t>(nf_), file_);
    readBody(pieces, std::move(first), headerLines);
    if (elements_ < nv_ + nf_) {
      const bool vertex = elements_ < nv_;
      throw InputError::inFile(file_, "file ends at " + std::string(vertex ? "vertex " : "face ") +
                                          std::to_string(vertex ? elements_ : elements_ - nv_) +
                                          " of " + std::to_string(vertex ? nv_ : nf_) +
                                          " announced in the header");
    }
    finishPolygons(mesh_, budget_, file_);
    return std::move(mesh_);
  }

 private:
  using Chunk = text::ElementChunk;

  InputError nulError(std::size_t line) const {
    return InputError::atLine(file_, line, text::kNulByteMessage);
  }

  // Reads the header from the first pieces (usually all of it is in the
  // first); `chunk` is left holding the piece where the body starts, at
  // its start. Returns the number of the header's last line.
  std::size_t readHeader(text::LinePieces& pieces, Chunk& chunk, std::int64_t counts[3]) {
    std::size_t lineBefore = 0;
    text::LineReader lines(chunk.piece.text());
    const auto nextLine = [&](std::string_view& line) {
      while (!lines.nextNonEmpty(line)) {
        lineBefore += lines.lineNumber();
        if (chunk.piece.nulAfter()) throw nulError(lineBefore + 1);
        if (!pieces.next(chunk.piece) && !chunk.piece.nulAfter()) return false;
        lines = text::LineReader(chunk.piece.text());
      }
      return true;
    };
    const auto fail = [&](const std::string& what) {
      throw InputError::atLine(file_, lineBefore + lines.lineNumber(), what);
    };
    std::string_view line;
    if (!nextLine(line)) throw InputError::inFile(file_, "empty file: no OFF header");
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
      if (!nextLine(line)) fail("file ends before the vertex and face counts");
      text::TokenReader more(line);
      while (found < 3 && more.next(token)) parseCount(token, counts[found++]);
    }
    chunk.begin = lines.offset();
    chunk.lineBefore = lineBefore + lines.lineNumber();
    return chunk.lineBefore;
  }

  void readBody(text::LinePieces& pieces, std::unique_ptr<Chunk> first, std::size_t lineBefore) {
    elements_ = text::readElementLines(
        pieces, std::move(first), lineBefore, nv_ + nf_, mesh_, budget_, file_,
        [&](std::string_view line, std::int64_t e, std::size_t lineNumber, Chunk& c) {
          if (e < nv_)
            mesh_.vertices[static_cast<std::size_t>(e)] = vertexOf(line, e, lineNumber);
          else
            readFace(line, e - nv_, lineNumber, c);
        },
        [&](std::int64_t e) { return std::max<std::int64_t>(0, e - nv_); });
  }

  Vec3 vertexOf(std::string_view line, std::int64_t index, std::size_t lineNumber) const {
    text::TokenReader tokens(line);
    return text::readVertexCoordinates(tokens, file_, lineNumber, index);
  }

  void readFace(std::string_view line, std::int64_t index, std::size_t lineNumber, Chunk& c) const {
    const auto fail = [&](const std::string& what) {
      throw InputError::atLine(file_, lineNumber, "face " + std::to_string(index) + what);
    };
    text::TokenReader tokens(line);
    std::string_view token;
    std::int64_t count = 0;
    if (tokens.nextInt64(count, token) != text::NumberToken::Read)
      fail(": bad corner count " + quoted(token));
    if (!element_problems::validCornerCount(count, nv_))
      fail(element_problems::badCornerCount(count, nv_));
    std::vector<std::uint32_t>& corners = c.corners;
    corners.clear();
    for (std::int64_t k = 0; k < count; ++k) {
      std::int64_t v = 0;
      const text::NumberToken read = tokens.nextInt64(v, token);
      if (read == text::NumberToken::LineEnded)
        fail(" announces " + std::to_string(count) + " corners but lists " + std::to_string(k));
      if (read == text::NumberToken::NotANumber) fail(": bad vertex index " + quoted(token));
      if (!element_problems::validIndex(v, nv_)) fail(element_problems::indexOutOfRange(v, nv_));
      corners.push_back(static_cast<std::uint32_t>(v));
    }
    appendPolygonTriangles(corners, c.triangles, &c.polygons);
    // Any further values on the line (face colours) are ignored.
  }

  std::filesystem::path file_;
  text::FileSource& source_;
  MemoryBudget& budget_;
  std::int64_t nv_ = 0, nf_ = 0;
  MeshData mesh_;
  std::int64_t elements_ = 0;  // elements read
};
}  // namespace

MeshData readOff(const std::filesystem::path& file, MemoryBudget& budget) {
  text::FileSource source(file, kMaxOffBytes, budget.loadObserver());
  return OffParser(source, budget).parse();
}

MeshData readOff(const std::filesystem::path& file) {
  MemoryBudget budget(defaultMemoryLimit());
  return readOff(file, budget);
}

}  // namespace meshtrace
