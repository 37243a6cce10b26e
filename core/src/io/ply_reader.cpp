#include "meshtrace/io/ply_reader.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "io/byte_reader.h"
#include "io/element_problems.h"
#include "io/file_source.h"
#include "io/mesh_arrays.h"
#include "io/ply_ascii_reader.h"
#include "io/ply_layout.h"
#include "meshtrace/geometry/polygon.h"
#include "meshtrace/io/input_error.h"
#include "meshtrace/io/mesh_reader.h"
#include "meshtrace/io/ply_header.h"
#include "meshtrace/util/quoted.h"

namespace meshtrace {

namespace {
// Meshes beyond this are refused, as OFF's are.
constexpr std::uintmax_t kMaxPlyBytes = std::uintmax_t{4} << 30;
// Records are read from a buffer of this size, which also holds the whole
// header (at most 64 KiB) when it is first filled.
constexpr std::size_t kBufferBytes = std::size_t{1} << 20;

template <typename T>
T load(const char* at, bool swap) {
  T value;
  std::memcpy(&value, at, sizeof(T));
  if (swap) {
    if constexpr (sizeof(T) == 2) value = static_cast<T>(__builtin_bswap16(value));
    if constexpr (sizeof(T) == 4) value = static_cast<T>(__builtin_bswap32(value));
    if constexpr (sizeof(T) == 8) value = static_cast<T>(__builtin_bswap64(value));
  }
  return value;
}

// A float or double value of `size` bytes.
double loadReal(const char* at, int size, bool swap) {
  if (size == 4) return std::bit_cast<float>(load<std::uint32_t>(at, swap));
  return std::bit_cast<double>(load<std::uint64_t>(at, swap));
}

// An integer value of `size` bytes (1, 2 or 4).
std::int64_t loadInteger(const char* at, int size, bool isSigned, bool swap) {
  switch (size) {
    case 1:
      return isSigned ? std::int64_t{static_cast<std::int8_t>(*at)}
                      : std::int64_t{static_cast<std::uint8_t>(*at)};
    case 2: {
      const auto v = load<std::uint16_t>(at, swap);
      return isSigned ? std::int64_t{static_cast<std::int16_t>(v)} : std::int64_t{v};
    }
    default: {
      const auto v = load<std::uint32_t>(at, swap);
      return isSigned ? std::int64_t{static_cast<std::int32_t>(v)} : std::int64_t{v};
    }
  }
}

// Where a vertex record keeps x, y and z, and of which type.
struct Coordinate {
  std::size_t offset = 0;
  int size = 0;
  bool isFloat = true, isSigned = false;
};

class BinaryPlyReader {
 public:
  BinaryPlyReader(text::FileSource& source, MemoryBudget& budget)
      : file_(source.file()), source_(source), budget_(budget), in_(source, kBufferBytes) {}

  MeshData read() {
    if (source_.size() == 0) fail("empty file");
    const PlyHeader header = readPlyHeader(file_, in_.buffered(), source_.size());
    if (header.format == "ascii" || !readablePlyLayout(header))
      fail("the header changed while the file was read");
    swap_ = (header.format == "binary_big_endian") != (std::endian::native == std::endian::big);
    vertices_ = static_cast<std::int64_t>(header.vertices);
    in_.skip(header.bodyStart);
    for (const PlyElement& e : header.elements) {
      if (e.name == "vertex")
        readVertices(e);
      else if (e.name == "face")
        readFaces(e);
      else
        skipElement(e);
    }
    finishPolygons(mesh_, budget_, file_);
    return std::move(mesh_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError::inFile(file_, what); }
  [[noreturn]] void endsAt(const PlyElement& e, std::uint64_t i) const {
    fail("file ends at " + e.name + " " + std::to_string(i) + " of " + std::to_string(e.count));
  }

  void readVertices(const PlyElement& e) {
    mesh_arrays::sizeVertices(mesh_, budget_, static_cast<std::size_t>(e.count), file_);
    Coordinate xyz[3];
    std::size_t record = 0;
    bool lists = false;  // then records differ in size
    for (const PlyProperty& p : e.properties) {
      for (int k = 0; k < 3; ++k)
        if (p.name.size() == 1 && p.name[0] == 'x' + k)
          xyz[k] = {record, p.size, p.isFloat, p.isSigned};
      record += static_cast<std::size_t>(p.size);
      lists |= p.countSize != 0;
    }
    for (std::uint64_t i = 0; i < e.count; ++i) {
      Vec3& v = mesh_.vertices[i];
      if (lists) {
        // Property by property: the coordinates read, the rest stepped over.
        for (const PlyProperty& p : e.properties) {
          const int k = p.name.size() == 1 ? p.name[0] - 'x' : -1;
          if (k < 0 || k > 2) {
            skipProperty(e, p, i);
            continue;
          }
          const char* at = in_.take(static_cast<std::size_t>(p.size));
          if (!at) endsAt(e, i);
          v[k] = coordinateAt(at, {0, p.size, p.isFloat, p.isSigned});
        }
      } else {
        const char* at = in_.take(record);
        if (!at) endsAt(e, i);
        for (int k = 0; k < 3; ++k) v[k] = coordinateAt(at + xyz[k].offset, xyz[k]);
      }
      for (int k = 0; k < 3; ++k)
        if (!std::isfinite(v[k]))
          fail("vertex " + std::to_string(i) +
               element_problems::nonFiniteCoordinate(shortestText(v[k])));
    }
  }

  // Integer coordinates (any PLY integer type) are exact in double.
  double coordinateAt(const char* at, const Coordinate& c) const {
    return c.isFloat ? loadReal(at, c.size, swap_)
                     : static_cast<double>(loadInteger(at, c.size, c.isSigned, swap_));
  }

  // The faces of face element `e`, numbered on from those of the face
  // elements before it.
  void readFaces(const PlyElement& e) {
    // Exact for a triangle mesh; polygons grow it.
    const std::size_t triangles = mesh_.triangles.size() + static_cast<std::size_t>(e.count);
    if (triangles > mesh_.triangles.capacity())
      mesh_arrays::growTriangles(mesh_, budget_, triangles, file_);
    std::size_t cornerList = 0;  // readablePlyLayout saw that there is one
    while (!isPlyCornerList(e, e.properties[cornerList])) ++cornerList;
    std::vector<std::uint32_t> corners;
    for (std::uint64_t i = 0; i < e.count; ++i) {
      for (std::size_t property = 0; property < e.properties.size(); ++property) {
        const PlyProperty& p = e.properties[property];
        if (property != cornerList) {
          skipProperty(e, p, i);
          continue;
        }
        const std::int64_t count = readCount(e, p, i);
        if (!element_problems::validCornerCount(count, vertices_))
          fail("face " + std::to_string(facesBefore_ + i) +
               element_problems::badCornerCount(count, vertices_));
        corners.clear();
        for (std::int64_t k = 0; k < count; ++k) {
          const char* at = in_.take(static_cast<std::size_t>(p.size));
          if (!at) endsAt(e, i);
          const std::int64_t index = loadInteger(at, p.size, p.isSigned, swap_);
          if (!element_problems::validIndex(index, vertices_))
            fail("face " + std::to_string(facesBefore_ + i) +
                 element_problems::indexOutOfRange(index, vertices_));
          corners.push_back(static_cast<std::uint32_t>(index));
        }
        const std::size_t needed = mesh_.triangles.size() + corners.size() - 2;
        if (needed > mesh_.triangles.capacity())
          mesh_arrays::growTriangles(mesh_, budget_,
                                     std::max(2 * mesh_.triangles.capacity(), needed), file_);
        appendPolygonTriangles(corners, mesh_.triangles, &mesh_.polygons);
      }
    }
    facesBefore_ += e.count;
  }

  std::int64_t readCount(const PlyElement& e, const PlyProperty& p, std::uint64_t i) {
    const char* at = in_.take(static_cast<std::size_t>(p.countSize));
    if (!at) endsAt(e, i);
    return loadInteger(at, p.countSize, p.countSigned, swap_);
  }

  // A property of no use here, stepped over by its size.
  void skipProperty(const PlyElement& e, const PlyProperty& p, std::uint64_t i) {
    std::uint64_t bytes = static_cast<std::uint64_t>(p.size);
    if (p.countSize != 0) {
      const std::int64_t count = readCount(e, p, i);
      if (count < 0)
        fail(e.name + " " + std::to_string(i) + ": " + p.name + " lists " + std::to_string(count) +
             " items");
      bytes *= static_cast<std::uint64_t>(count);
    }
    if (bytes > in_.left() || !in_.skip(bytes)) endsAt(e, i);
  }

  void skipElement(const PlyElement& e) {
    std::uint64_t record = 0;
    bool fixed = true;
    for (const PlyProperty& p : e.properties) {
      record += static_cast<std::uint64_t>(p.size);
      fixed &= p.countSize == 0;
    }
    if (fixed) {  // the counts were checked against the file's size
      if (record > 0 && in_.left() / record < e.count) endsAt(e, in_.left() / record);
      in_.skip(e.count * record);
      return;
    }
    for (std::uint64_t i = 0; i < e.count; ++i)
      for (const PlyProperty& p : e.properties) skipProperty(e, p, i);
  }

  std::filesystem::path file_;
  text::FileSource& source_;
  MemoryBudget& budget_;
  text::ByteReader in_;
  bool swap_ = false;
  std::int64_t vertices_ = 0;
  std::uint64_t facesBefore_ = 0;  // of the face elements read
  MeshData mesh_;
};
}  // namespace

std::optional<MeshData> readPly(const std::filesystem::path& file, MemoryBudget& budget) {
  // A first look at the header, to choose the reader; each reader then
  // reads the file from its start, with its progress reported.
  PlyHeader header;
  {
    text::FileSource peek(file, kMaxPlyBytes);
    if (peek.size() == 0) throw InputError::inFile(file, "empty file");
    text::ByteReader start(peek, kMaxPlyHeaderBytes);
    header = readPlyHeader(file, start.buffered(), peek.size());
  }
  if (!readablePlyLayout(header)) return std::nullopt;
  text::FileSource source(file, kMaxPlyBytes, budget.loadObserver());
  if (header.format == "ascii") return readAsciiPly(source, budget);
  return BinaryPlyReader(source, budget).read();
}

}  // namespace meshtrace
