#include "meshtrace/io/stl_reader.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "io/byte_reader.h"
#include "io/corner_welder.h"
#include "io/element_problems.h"
#include "io/file_source.h"
#include "io/mesh_arrays.h"
#include "io/stl_ascii_reader.h"
#include "meshtrace/io/input_error.h"

namespace meshtrace {

namespace {
// Meshes beyond this are refused, as OFF's are.
constexpr std::uintmax_t kMaxStlBytes = std::uintmax_t{4} << 30;
constexpr std::uint64_t kBinaryHeaderBytes = 84;  // 80 free bytes, then the facet count
constexpr std::size_t kFacetBytes = 50;           // normal, three corners, attribute count
// Records are read from a buffer of this size.
constexpr std::size_t kBufferBytes = std::size_t{1} << 20;
// Facets are welded in batches of this many.
constexpr std::size_t kBatchFacets = 4096;

class BinaryStl {
 public:
  BinaryStl(text::FileSource& source, MemoryBudget& budget, std::uint64_t facets)
      : file_(source.file()), budget_(budget), in_(source, kBufferBytes), facets_(facets) {}

  MeshData read() {
    in_.skip(kBinaryHeaderBytes);
    mesh_arrays::growTriangles(mesh_, budget_, static_cast<std::size_t>(facets_), file_);
    // A closed mesh has about half as many vertices as facets.
    CornerWelder welder(mesh_, budget_, file_, static_cast<std::size_t>(facets_ / 2 + 3));
    std::vector<Vec3> corners;  // of a batch of facets, welded together
    corners.reserve(3 * kBatchFacets);
    for (std::uint64_t f = 0; f < facets_; ++f) {
      const char* at = in_.take(kFacetBytes);
      if (!at)  // the size was checked; the file shrank while read
        throw InputError::inFile(file_, "file ends at facet " + std::to_string(f));
      for (int c = 0; c < 3; ++c) {
        Vec3& p = corners.emplace_back();
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
      }
      if (corners.size() == 3 * kBatchFacets || f + 1 == facets_) {
        welder.addFacets(corners, f + 1 - corners.size() / 3);
        corners.clear();
      }
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
  return binary ? BinaryStl(source, budget, facets).read() : readAsciiStl(source, budget);
}

}  // namespace meshtrace
