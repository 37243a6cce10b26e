#include "io/ply_ascii_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "io/element_lines.h"
#include "io/element_problems.h"
#include "io/mesh_arrays.h"
#include "io/ply_layout.h"
#include "meshtrace/geometry/polygon.h"
#include "meshtrace/io/input_error.h"
#include "meshtrace/io/mesh_reader.h"
#include "meshtrace/io/ply_header.h"
#include "meshtrace/util/quoted.h"

namespace meshtrace {

namespace {

// No list in a file of at most 4 GiB can hold more items than this.
constexpr std::int64_t kMaxListItems = std::int64_t{1} << 31;

// What a property's values are to the reader.
enum class Role { Other, X, Y, Z, Corners };

// What an element's records are to the reader.
enum class ElementKind { Other, Vertex, Face };

// An element as its lines are read: where its records start among the
// file's lines, what they are, and what each of its properties is (told
// once from the header, not from the names on every line).
struct ElementLayout {
  const PlyElement* element;
  ElementKind kind;
  std::int64_t firstLine;    // counting the body's non-empty lines from 0
  std::int64_t facesBefore;  // in the face elements before it
  std::vector<Role> roles;

  bool isFace() const { return kind == ElementKind::Face; }
  // The number in the file of the face or other record on body line `line`:
  // faces are numbered on from one face element to the next.
  std::int64_t recordOf(std::int64_t line) const {
    return line - firstLine + (isFace() ? facesBefore : 0);
  }
};

class AsciiPlyReader {
 public:
  AsciiPlyReader(text::FileSource& source, MemoryBudget& budget)
      : file_(source.file()), source_(source), budget_(budget) {}

  MeshData read() {
    text::LinePieces pieces(source_, text::kPieceBytes);
    auto first = std::make_unique<text::ElementChunk>();
    if (!pieces.next(first->piece) && !first->piece.nulAfter()) fail("empty file");
    // The header ends in the file's first 64 KiB, all in the first piece.
    header_ = readPlyHeader(file_, first->piece.text(), source_.size());
    if (header_.format != "ascii" || !readablePlyLayout(header_))
      fail("the header changed while the file was read");
    first->begin = header_.bodyStart;
    vertices_ = static_cast<std::int64_t>(header_.vertices);
    layOut();
    mesh_arrays::sizeVertices(mesh_, budget_, static_cast<std::size_t>(vertices_), file_);
    // Exact for a triangle mesh; polygons grow it.
    mesh_arrays::growTriangles(mesh_, budget_, static_cast<std::size_t>(faces_), file_);
    const std::int64_t read = text::readElementLines(
        pieces, std::move(first), header_.lines, lines_, mesh_, budget_, file_,
        [&](std::string_view line, std::int64_t e, std::size_t lineNumber, text::ElementChunk& c) {
          readRecord(line, e, lineNumber, c);
        },
        [&](std::int64_t e) {
          const ElementLayout& at = layoutOf(e);
          return at.isFace() ? at.recordOf(e) : at.facesBefore;
        });
    if (read < lines_) {
      const ElementLayout& at = layoutOf(read);
      fail("file ends at " + at.element->name + " " + std::to_string(read - at.firstLine) + " of " +
           std::to_string(at.element->count));
    }
    finishPolygons(mesh_, budget_, file_);
    return std::move(mesh_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError::inFile(file_, what); }

  // Where each element's records lie among the body's lines. An element
  // without properties has empty records: no lines.
  void layOut() {
    for (const PlyElement& e : header_.elements) {
      if (e.properties.empty()) continue;
      const ElementKind kind = e.name == "vertex" ? ElementKind::Vertex
                               : e.name == "face"   ? ElementKind::Face
                                                    : ElementKind::Other;
      ElementLayout layout{&e, kind, lines_, faces_, {}};
      for (const PlyProperty& p : e.properties) {
        Role role = Role::Other;
        if (kind == ElementKind::Vertex && p.name.size() == 1 && p.name[0] >= 'x' &&
            p.name[0] <= 'z')
          role = static_cast<Role>(static_cast<int>(Role::X) + (p.name[0] - 'x'));
        if (isPlyCornerList(e, p)) role = Role::Corners;
        layout.roles.push_back(role);
      }
      if (layout.isFace()) faces_ += static_cast<std::int64_t>(e.count);
      layouts_.push_back(std::move(layout));
      // The header's counts fit in the file: their sum does not overflow.
      lines_ += static_cast<std::int64_t>(e.count);
    }
  }

  // The element whose records hold body line `line` (a header may declare
  // thousands of elements).
  const ElementLayout& layoutOf(std::int64_t line) const {
    const auto after = std::upper_bound(
        layouts_.begin(), layouts_.end(), line,
        [](std::int64_t l, const ElementLayout& layout) { return l < layout.firstLine; });
    return *std::prev(after);
  }

  // Record `line - firstLine` of its element: each property's value, or a
  // list's count and items, in the header's order, and nothing after them.
  void readRecord(std::string_view text, std::int64_t line, std::size_t lineNumber,
                  text::ElementChunk& c) {
    const ElementLayout& layout = layoutOf(line);
    const PlyElement& e = *layout.element;
    const std::int64_t index = line - layout.firstLine;
    const std::int64_t record = layout.recordOf(line);
    const auto fail = [&](const std::string& what) {
      throw InputError::atLine(file_, lineNumber, e.name + " " + std::to_string(record) + what);
    };
    text::TokenReader tokens(text);
    std::string_view token;
    Vec3 vertex;
    for (std::size_t k = 0; k < e.properties.size(); ++k) {
      const PlyProperty& p = e.properties[k];
      const Role role = layout.roles[k];
      const auto ended = [&] {
        fail(": the line ends at " + p.name + "; a record is one line of its values");
      };
      std::int64_t items = 1;
      if (p.countSize != 0) {
        const text::NumberToken count = tokens.nextInt64(items, token);
        if (count == text::NumberToken::LineEnded) ended();
        if (count == text::NumberToken::NotANumber || items < 0 || items > kMaxListItems)
          fail(": bad list count " + quoted(token) + " of " + p.name);
      }
      if (role == Role::Corners) {
        if (!element_problems::validCornerCount(items, vertices_))
          fail(element_problems::badCornerCount(items, vertices_));
        c.corners.clear();
      }
      for (std::int64_t item = 0; item < items; ++item) {
        double real = 0.0;
        std::int64_t integer = 0;
        const text::NumberToken value =
            p.isFloat ? tokens.nextDouble(real, token) : tokens.nextInt64(integer, token);
        if (value == text::NumberToken::LineEnded) ended();
        if (value == text::NumberToken::NotANumber)
          fail(": " + p.name + " is " + quoted(token) + ", not " +
               (p.isFloat ? "a number" : "an integer"));
        if (role == Role::Corners) {
          if (!element_problems::validIndex(integer, vertices_))
            fail(element_problems::indexOutOfRange(integer, vertices_));
          c.corners.push_back(static_cast<std::uint32_t>(integer));
        } else if (role != Role::Other) {
          // Integer coordinates are exact in double up to 2^53.
          const double x = p.isFloat ? real : static_cast<double>(integer);
          if (!std::isfinite(x)) fail(element_problems::nonFiniteCoordinate(token));
          vertex[static_cast<int>(role) - static_cast<int>(Role::X)] = x;
        }
      }
    }
    if (tokens.next(token))
      fail(": " + quoted(token) + " after its " + std::to_string(e.properties.size()) +
           (e.properties.size() == 1 ? " property" : " properties"));
    if (layout.kind == ElementKind::Vertex)
      mesh_.vertices[static_cast<std::size_t>(index)] = vertex;
    else if (layout.isFace())
      appendPolygonTriangles(c.corners, c.triangles, &c.polygons);
  }

  std::filesystem::path file_;
  text::FileSource& source_;
  MemoryBudget& budget_;
  PlyHeader header_;
  std::vector<ElementLayout> layouts_;
  std::int64_t lines_ = 0;  // the records of all elements
  std::int64_t vertices_ = 0;
  std::int64_t faces_ = 0;  // in all face elements
  MeshData mesh_;
};

}  // namespace

MeshData readAsciiPly(text::FileSource& source, MemoryBudget& budget) {
  return AsciiPlyReader(source, budget).read();
}

}  // namespace meshtrace
