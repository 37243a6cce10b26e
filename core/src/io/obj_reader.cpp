#include "meshtrace/io/obj_reader.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "io/element_problems.h"
#include "io/file_source.h"
#include "io/line_pieces.h"
#include "io/mesh_arrays.h"
#include "io/piece_pipeline.h"
#include "io/text.h"
#include "io/vertex_line.h"
#include "meshtrace/geometry/polygon.h"
#include "meshtrace/io/input_error.h"
#include "meshtrace/io/mesh_reader.h"
#include "meshtrace/util/quoted.h"

namespace meshtrace {

namespace {
// Meshes beyond this are refused rather than loaded into memory.
constexpr std::uintmax_t kMaxObjBytes = std::uintmax_t{4} << 30;
static_assert(kMaxObjBytes <= std::uintmax_t{1} << 32, "line offsets are held in 32 bits");

// The file streams through text::streamPieces. The count finds each
// piece's vertex and face lines (the other statements are skipped there)
// and counts them; the numbering gives each piece the vertices and faces
// above it, so that the parse can resolve a corner's index, relative ones
// included, without the pieces before it.
class ObjParser {
 public:
  ObjParser(text::FileSource& source, MemoryBudget& budget)
      : file_(source.file()), source_(source), budget_(budget) {}

  MeshData parse() {
    text::LinePieces pieces(source_, text::kPieceBytes);
    std::int64_t vertices = 0, faces = 0;
    std::size_t lineBefore = 0;
    text::streamPieces(
        pieces, std::unique_ptr<Chunk>(), count,
        [&](Chunk& c) {
          c.firstVertex = vertices;
          vertices += c.vertexCount;
          c.firstFace = faces;
          faces += c.faceCount;
          c.lineBefore = lineBefore;
          lineBefore += c.lines;
        },
        [&](Chunk& c) { parseChunk(c); },
        [&](Chunk& c, std::atomic<bool>& done) { gather(c, done); });
    if (error_) std::rethrow_exception(error_);
    // Any text file is OBJ to the grammar (unknown statements are skipped):
    // one without a single vertex is not a mesh of any kind.
    if (vertices == 0)
      throw InputError::inFile(file_, "no vertex lines ('v x y z'): not an OBJ mesh");
    finishPolygons(mesh_, budget_, file_);
    return std::move(mesh_);
  }

 private:
  struct Chunk : mesh_arrays::MeshChunk {
    // Its vertex and face lines, comments cut.
    struct Statement {
      std::uint32_t begin, length;  // in text(); a piece never outgrows the file
      std::uint32_t number;         // counted from the chunk's first line, from 1
      bool face;
    };
    std::vector<Statement> statements;
    std::int64_t vertexCount = 0, faceCount = 0;
    std::int64_t firstVertex = 0, firstFace = 0;
    std::vector<Vec3> vertices;
  };

  static void count(Chunk& c) {
    const std::string_view text = c.text();
    text::LineReader lines(text, text::hasLoneCr(text));
    std::string_view line;
    c.statements.clear();
    c.vertexCount = c.faceCount = 0;
    while (lines.nextNonEmpty(line)) {
      std::size_t k = 0;
      while (text::isSpace(line[k])) ++k;  // the line has a token
      const bool oneLetter = k + 1 == line.size() || text::isSpace(line[k + 1]);
      if (!oneLetter || (line[k] != 'v' && line[k] != 'f')) continue;
      const bool face = line[k] == 'f';
      c.statements.push_back({static_cast<std::uint32_t>(line.data() - text.data()),
                              static_cast<std::uint32_t>(line.size()),
                              static_cast<std::uint32_t>(lines.lineNumber()), face});
      ++(face ? c.faceCount : c.vertexCount);
    }
    c.lines = lines.lineNumber();
  }

  void parseChunk(Chunk& c) const {
    const std::string_view text = c.text();
    std::int64_t vertex = c.firstVertex, face = c.firstFace;
    c.vertices.clear();
    c.vertices.reserve(static_cast<std::size_t>(c.vertexCount));
    for (const Chunk::Statement& s : c.statements) {
      const std::string_view line = text.substr(s.begin, s.length);
      try {
        const std::size_t lineNumber = c.lineBefore + s.number;
        if (s.face)
          readFace(line, face++, vertex, lineNumber, c);
        else
          c.vertices.push_back(vertexOf(line, vertex++, lineNumber));
      } catch (const InputError&) {
        c.error = std::current_exception();
        return;
      }
    }
  }

  Vec3 vertexOf(std::string_view line, std::int64_t index, std::size_t lineNumber) const {
    text::TokenReader tokens(line);
    std::string_view keyword;
    tokens.next(keyword);  // "v"
    return text::readVertexCoordinates(tokens, file_, lineNumber, index);
  }

  // `above`: the vertices defined on the lines before, which the corners
  // may name: i for the i-th from the first, -i for the i-th back.
  void readFace(std::string_view line, std::int64_t index, std::int64_t above,
                std::size_t lineNumber, Chunk& c) const {
    const auto fail = [&](const std::string& what) {
      throw InputError::atLine(file_, lineNumber, "face " + std::to_string(index) + what);
    };
    text::TokenReader tokens(line);
    std::string_view token;
    tokens.next(token);  // "f"
    std::vector<std::uint32_t>& corners = c.corners;
    corners.clear();
    for (;;) {
      std::int64_t i = 0;
      // "i/t", "i//n", "i/t/n": the vertex index is before the first '/'.
      const text::NumberToken read = tokens.nextLeadingInt64(i, token);
      if (read == text::NumberToken::LineEnded) break;
      if (read == text::NumberToken::NotANumber) i = 0;
      const std::int64_t v = i > 0 ? i - 1 : above + i;
      if (i == 0 || !element_problems::validIndex(v, above))
        fail(": corner " + quoted(token) + " names none of the " + std::to_string(above) +
             " vertices defined above it");
      corners.push_back(static_cast<std::uint32_t>(v));
    }
    const auto n = static_cast<std::int64_t>(corners.size());
    if (!element_problems::validCornerCount(n, above))
      fail(element_problems::badCornerCount(n, above));
    appendPolygonTriangles(corners, c.triangles, &c.polygons);
  }

  // In file order: the first error ends the reading.
  void gather(Chunk& c, std::atomic<bool>& done) {
    if (!done) {
      if (c.error) {
        error_ = c.error;
      } else {
        try {
          append(c);
        } catch (const MemoryLimitError&) {
          error_ = std::current_exception();
        }
      }
      done = error_ != nullptr;
    }
    c.triangles.clear();
    c.polygons.clear();
    c.error = nullptr;
  }

  void append(const Chunk& c) {
    const std::size_t vertices = mesh_.vertices.size() + c.vertices.size();
    if (vertices > mesh_.vertices.capacity())
      mesh_arrays::growVertices(mesh_, budget_, std::max(2 * mesh_.vertices.capacity(), vertices),
                                file_);
    mesh_.vertices.insert(mesh_.vertices.end(), c.vertices.begin(), c.vertices.end());
    mesh_arrays::appendTriangles(mesh_, budget_, c, static_cast<std::uint32_t>(c.firstFace), file_);
    if (c.piece.nulAfter())
      error_ = std::make_exception_ptr(
          InputError::atLine(file_, c.lineBefore + c.lines + 1, text::kNulByteMessage));
  }

  std::filesystem::path file_;
  text::FileSource& source_;
  MemoryBudget& budget_;
  MeshData mesh_;
  std::exception_ptr error_;
};

}  // namespace

MeshData readObj(const std::filesystem::path& file, MemoryBudget& budget) {
  text::FileSource source(file, kMaxObjBytes, budget.loadObserver());
  return ObjParser(source, budget).parse();
}

}  // namespace meshtrace
