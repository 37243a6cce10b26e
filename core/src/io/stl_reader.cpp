#include "meshtrace/io/stl_reader.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "io/byte_reader.h"
#include "io/corner_welder.h"
#include "io/element_problems.h"
#include "io/file_source.h"
#include "io/line_pieces.h"
#include "io/mesh_arrays.h"
#include "io/piece_pipeline.h"
#include "io/text.h"
#include "meshtrace/io/input_error.h"
#include "meshtrace/util/quoted.h"

namespace meshtrace {

namespace {
// Meshes beyond this are refused, as OFF's are.
constexpr std::uintmax_t kMaxStlBytes = std::uintmax_t{4} << 30;
constexpr std::uint64_t kBinaryHeaderBytes = 84;  // 80 free bytes, then the facet count
constexpr std::size_t kFacetBytes = 50;           // normal, three corners, attribute count
// Records are read from a buffer of this size.
constexpr std::size_t kBufferBytes = std::size_t{1} << 20;
// The fewest bytes an ASCII facet takes ("facet normal 0 0 0 outer loop",
// three "vertex 0 0 0", "endloop endfacet"), to size the arrays at first.
constexpr std::uint64_t kMinAsciiFacetBytes = 80;

// A facet's welded corners, added to the mesh unless two of them are one
// vertex.
void addFacet(MeshData& mesh, MemoryBudget& budget, const std::filesystem::path& file,
              const std::uint32_t (&corners)[3]) {
  if (corners[0] == corners[1] || corners[0] == corners[2] || corners[1] == corners[2]) return;
  if (mesh.triangles.size() == mesh.triangles.capacity())
    mesh_arrays::growTriangles(mesh, budget, 2 * mesh.triangles.capacity() + 1, file);
  mesh.triangles.push_back({corners[0], corners[1], corners[2]});
}

class BinaryStl {
 public:
  BinaryStl(text::FileSource& source, MemoryBudget& budget, std::uint64_t facets)
      : file_(source.file()), budget_(budget), in_(source, kBufferBytes), facets_(facets) {}

  MeshData read() {
    in_.skip(kBinaryHeaderBytes);
    mesh_arrays::growTriangles(mesh_, budget_, static_cast<std::size_t>(facets_), file_);
    // A closed mesh has about half as many vertices as facets.
    CornerWelder welder(mesh_, budget_, file_, static_cast<std::size_t>(facets_ / 2 + 3));
    for (std::uint64_t f = 0; f < facets_; ++f) {
      const char* at = in_.take(kFacetBytes);
      if (!at)  // the size was checked; the file shrank while read
        throw InputError::inFile(file_, "file ends at facet " + std::to_string(f));
      std::uint32_t corners[3];
      for (int c = 0; c < 3; ++c) {
        Vec3 p;
        for (int k = 0; k < 3; ++k) {
          std::uint32_t bits;
          std::memcpy(&bits, at + 12 * (c + 1) + 4 * k, 4);
          static_assert(std::endian::native == std::endian::little, "STL is little-endian");
          p[k] = std::bit_cast<float>(bits);
          if (!std::isfinite(p[k]))
            throw InputError::inFile(
                file_, "facet " + std::to_string(f) + ": vertex " + std::to_string(c) +
                           element_problems::nonFiniteCoordinate(std::to_string(p[k])));
        }
        corners[c] = welder.weld(p);
      }
      addFacet(mesh_, budget_, file_, corners);
    }
    return std::move(mesh_);
  }

 private:
  std::filesystem::path file_;
  MemoryBudget& budget_;
  text::ByteReader in_;
  std::uint64_t facets_;
  MeshData mesh_;
};

// The words of an ASCII file in order, with the line each is on, read a
// piece at a time.
class Words {
 public:
  // The readers start on "", not on an empty view: their searches pass the
  // text to memchr, which must not be given a null pointer.
  Words(text::FileSource& source, const std::filesystem::path& file)
      : file_(file),
        pieces_(source, text::kPieceBytes),
        lines_(std::string_view("")),
        tokens_(std::string_view("")) {}

  // The next word; false at the end of the file.
  bool next(std::string_view& word) {
    while (!tokens_.next(word)) {
      if (!nextLine()) return false;
    }
    return true;
  }
  // The next word read as a number where it stands
  // (text::TokenReader::nextDouble); `word` is set to it and `isNumber` to
  // whether it is one. False at the end of the file.
  bool nextNumber(double& value, std::string_view& word, bool& isNumber) {
    for (;;) {
      const text::NumberToken read = tokens_.nextDouble(value, word);
      if (read != text::NumberToken::LineEnded) {
        isNumber = read == text::NumberToken::Read;
        return true;
      }
      if (!nextLine()) return false;
    }
  }
  // Drops the rest of the current line (a solid's name).
  void skipLine() { tokens_ = text::TokenReader(std::string_view("")); }
  std::size_t line() const { return lineBefore_ + lines_.lineNumber(); }

 private:
  bool nextLine() {
    std::string_view text;
    while (!lines_.nextNonEmpty(text)) {
      lineBefore_ += lines_.lineNumber();
      if (piece_.nulAfter())
        throw InputError::atLine(file_, lineBefore_ + 1, text::kNulByteMessage);
      if (!pieces_.next(piece_) && !piece_.nulAfter()) return false;
      lines_ = text::LineReader(piece_.text());
    }
    tokens_ = text::TokenReader(text);
    return true;
  }

  std::filesystem::path file_;
  text::LinePieces pieces_;
  text::LinePiece piece_;
  text::LineReader lines_;
  text::TokenReader tokens_;
  std::size_t lineBefore_ = 0;
};

class AsciiStl {
 public:
  AsciiStl(text::FileSource& source, MemoryBudget& budget)
      : file_(source.file()), budget_(budget), words_(source, file_), size_(source.size()) {}

  MeshData read() {
    const std::uint64_t facets = size_ / kMinAsciiFacetBytes;
    mesh_arrays::growTriangles(mesh_, budget_, static_cast<std::size_t>(facets / 4 + 1), file_);
    CornerWelder welder(mesh_, budget_, file_, static_cast<std::size_t>(facets / 8 + 3));
    std::string_view word;
    bool solid = false;
    try {
      solid = words_.next(word) && word == "solid";
    } catch (const InputError&) {  // a NUL byte before the first word
    }
    if (!solid)
      throw InputError::inFile(file_,
                               "neither a binary STL (its size does not match the triangle "
                               "count at byte 80) nor an ASCII one (it must start with solid)");
    std::uint64_t facet = 0;
    for (;;) {  // a solid: its name, its facets, endsolid
      words_.skipLine();
      for (;; ++facet) {
        if (!words_.next(word))
          throw InputError::inFile(
              file_, "file ends after facet " + std::to_string(facet) + ": no endsolid");
        if (word == "endsolid") break;
        if (word != "facet")
          throw InputError::atLine(file_, words_.line(),
                                   "expected facet or endsolid, found " + quoted(word));
        readFacet(facet, welder);
      }
      words_.skipLine();
      if (!words_.next(word)) break;
      if (word != "solid")
        throw InputError::atLine(file_, words_.line(),
                                 "expected solid after endsolid, found " + quoted(word));
    }
    return std::move(mesh_);
  }

 private:
  void readFacet(std::uint64_t facet, CornerWelder& welder) {
    const std::string where = "facet " + std::to_string(facet);
    std::string_view word;
    const auto expect = [&](std::string_view wanted, const std::string& context) {
      if (!words_.next(word)) throw InputError::inFile(file_, "file ends in " + where);
      if (word != wanted)
        throw InputError::atLine(
            file_, words_.line(),
            context + ": expected " + std::string(wanted) + ", found " + quoted(word));
    };
    const auto number = [&]() {
      double value = 0.0;
      bool isNumber = false;
      if (!words_.nextNumber(value, word, isNumber))
        throw InputError::inFile(file_, "file ends in " + where);
      if (!isNumber)
        throw InputError::atLine(file_, words_.line(),
                                 where + ": " + quoted(word) + " is not a number");
      return value;
    };
    expect("normal", where);
    for (int k = 0; k < 3; ++k) number();
    expect("outer", where);
    expect("loop", where);
    std::uint32_t corners[3];
    for (int c = 0; c < 3; ++c) {
      expect("vertex", where);
      Vec3 p;
      for (int k = 0; k < 3; ++k) {
        p[k] = number();
        if (!std::isfinite(p[k]))
          throw InputError::atLine(file_, words_.line(),
                                   where + ": vertex " + std::to_string(c) +
                                       element_problems::nonFiniteCoordinate(word));
      }
      corners[c] = welder.weld(p);
    }
    expect("endloop", where + " (a facet has three vertices)");
    expect("endfacet", where);
    addFacet(mesh_, budget_, file_, corners);
  }

  std::filesystem::path file_;
  MemoryBudget& budget_;
  Words words_;
  std::uint64_t size_;
  MeshData mesh_;
};

// The facet count at byte 80, if the file's size is that of a binary STL
// with it.
bool isBinaryStl(text::FileSource& source, std::uint64_t& facets) {
  if (source.size() < kBinaryHeaderBytes) return false;
  text::ByteReader start(source, kBinaryHeaderBytes);
  const std::string_view header = start.buffered();
  if (header.size() < kBinaryHeaderBytes) return false;
  std::uint32_t count;
  std::memcpy(&count, header.data() + 80, 4);
  facets = count;
  return source.size() == kBinaryHeaderBytes + kFacetBytes * facets;
}
}  // namespace

MeshData readStl(const std::filesystem::path& file, MemoryBudget& budget) {
  std::uint64_t facets = 0;
  bool binary = false;
  {
    // A first look, to choose the reader; each then reads the file from its
    // start, with its progress reported.
    text::FileSource peek(file, kMaxStlBytes);
    if (peek.size() == 0) throw InputError::inFile(file, "empty file");
    binary = isBinaryStl(peek, facets);
  }
  text::FileSource source(file, kMaxStlBytes, budget.loadObserver());
  return binary ? BinaryStl(source, budget, facets).read() : AsciiStl(source, budget).read();
}

}  // namespace meshtrace
