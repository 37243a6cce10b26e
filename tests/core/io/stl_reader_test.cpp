// The STL reader: corners welded into the vertices of an indexed mesh, in
// the order they first occur; ASCII read in double, with several solids;
// facets without area left out; bad files refused with an InputError
// naming the file, the facet and (ASCII) the line.
#include "meshtrace/io/stl_reader.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "meshtrace/geometry/mesh.h"
#include "support/files.h"
#include "support/input_errors.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

using test::expectMentions;

MeshData readStlBytes(const std::string& bytes) {
  MemoryBudget budget(defaultMemoryLimit());
  return readStl(test::writeFile(test::scratchDir() / "mesh.stl", bytes), budget);
}

std::string errorOf(const std::string& bytes) {
  const auto file = test::writeFile(test::scratchDir() / "mesh.stl", bytes);
  MemoryBudget budget(defaultMemoryLimit());
  return test::inputErrorOf([&] { readStl(file, budget); });
}

using Facet = std::vector<Vec3>;  // three corners

std::string binaryStl(const std::vector<Facet>& facets, const std::string& header = "") {
  std::string out = header;
  out.resize(80, ' ');
  const auto put = [&](std::uint32_t bits) {
    for (int b = 0; b < 4; ++b) out += static_cast<char>(bits >> (8 * b) & 0xff);
  };
  put(static_cast<std::uint32_t>(facets.size()));
  for (const Facet& f : facets) {
    for (int k = 0; k < 3; ++k)
      put(std::bit_cast<std::uint32_t>(std::numeric_limits<float>::quiet_NaN()));
    for (const Vec3& p : f)
      for (int k = 0; k < 3; ++k) put(std::bit_cast<std::uint32_t>(static_cast<float>(p[k])));
    out += std::string(2, '\0');
  }
  return out;
}

std::string asciiFacet(const std::string& a, const std::string& b, const std::string& c) {
  return "  facet normal 0 0 1\n    outer loop\n      vertex " + a + "\n      vertex " + b +
         "\n      vertex " + c + "\n    endloop\n  endfacet\n";
}

// An ASCII file of `facets`, whose coordinates are integers: each written
// as one, -0 as such.
std::string asciiStl(const std::vector<Facet>& facets) {
  std::string text = "solid integers\n";
  for (const Facet& f : facets) {
    std::string corners[3];
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) {
        if (k > 0) corners[c] += ' ';
        corners[c] +=
            std::signbit(f[c][k]) ? std::string("-0") : std::to_string(static_cast<int>(f[c][k]));
      }
    text += asciiFacet(corners[0], corners[1], corners[2]);
  }
  return text + "endsolid integers\n";
}

// Two squares sharing an edge, each of two facets, and a facet whose
// corners weld into two vertices: the six vertices numbered as they first
// occur, -0 welded with +0, the flat facet left out.
const std::vector<Facet> kSquares = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}},
                                     {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}},
                                     {{1, 0, 0}, {2, 0, 0}, {2, 1, 0}},
                                     {{1, 0, -0.0}, {2, 1, 0}, {1, 1, 0}},
                                     {{0, 0, 0}, {2, 0, 0}, {-0.0, 0, 0}}};
const std::vector<Vec3> kWelded = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0},
                                   {0, 1, 0}, {2, 0, 0}, {2, 1, 0}};
const std::vector<TriangleIndices> kTriangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}};

TEST(Stl, BinaryCornersWeldIntoTheVerticesOfAnIndexedMesh) {
  // A header that starts as an ASCII file would: the size decides.
  const MeshData mesh = readStlBytes(binaryStl(kSquares, "solid but binary"));
  EXPECT_EQ(mesh.vertices, kWelded);
  EXPECT_EQ(mesh.triangles, kTriangles);
}

TEST(Stl, AsciiCornersWeldAlikeAndKeepTheirDoubles) {
  const std::string text = asciiStl(kSquares);
  const MeshData mesh = readStlBytes(text);
  EXPECT_EQ(mesh.vertices, kWelded);
  EXPECT_EQ(mesh.triangles, kTriangles);

  // Doubles, not floats; several solids; CRLF line ends; names of any words.
  const MeshData precise =
      readStlBytes("solid first part\r\n" + asciiFacet("0.1 0 0", "1 0.2 0", "0 1 1e-300") +
                   "endsolid first part\r\n\r\nsolid\r\n" +
                   asciiFacet("0.1 0 0", "0 1 1e-300", "-1 -1 -1") + "endsolid\r\n");
  EXPECT_EQ(precise.vertices,
            (std::vector<Vec3>{{0.1, 0, 0}, {1, 0.2, 0}, {0, 1, 1e-300}, {-1, -1, -1}}));
  EXPECT_EQ(precise.triangles, (std::vector<TriangleIndices>{{0, 1, 2}, {0, 2, 3}}));
}

TEST(Stl, ReadsAFileOfManyPiecesAsItsFacetsSay) {
  std::vector<Facet> facets;
  for (int i = 0; i < 300000; ++i)
    facets.push_back({{i, 0, 0}, {i + 1, 0, 0}, {i, 1, 0.5 * (i % 7)}});
  std::string text = "solid strip\n";
  for (const Facet& f : facets) {
    const auto point = [](const Vec3& p) {
      return std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z);
    };
    text += asciiFacet(point(f[0]), point(f[1]), point(f[2]));
  }
  text += "endsolid strip\n";
  ASSERT_GT(text.size(), std::size_t{8} << 20);
  for (const MeshData& mesh : {readStlBytes(text), readStlBytes(binaryStl(facets))}) {
    ASSERT_EQ(mesh.triangles.size(), facets.size());
    EXPECT_EQ(mesh.vertices.size(), 2 * facets.size() + 1);  // (i, 0, 0) shared
    for (std::size_t t = 0; t < facets.size(); t += 997)
      for (int c = 0; c < 3; ++c) EXPECT_EQ(mesh.vertices[mesh.triangles[t][c]], facets[t][c]);
  }
}

TEST(Stl, RefusesABadFileNamingTheFacetAndLine) {
  const std::string good = asciiFacet("0 0 0", "1 0 0", "0 1 0");
  struct Bad {
    std::string bytes;
    std::vector<std::string> mentions;
  };
  const Bad bads[] = {
      {"sold x\n", {"mesh.stl", "neither a binary STL", "nor an ASCII one"}},
      {std::string("\0\0\0solid", 8), {"mesh.stl", "neither a binary STL"}},
      {binaryStl({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}).substr(0, 120), {"neither a binary STL"}},
      {"solid s\n" + good + "  facet normal 0 0 one\n",
       {"mesh.stl:9", "facet 1", "'one' is not a number"}},
      {"solid s\n  facet normal 0 0 1\n outer loop\n vertex 0 0 0\n vertex 1 0 0\n vertex 0 1 0\n"
       " vertex 1 1 0\n endloop\n endfacet\nendsolid s\n",
       {"mesh.stl:7", "facet 0", "three vertices", "expected endloop, found 'vertex'"}},
      {"solid s\n" + good, {"mesh.stl", "file ends after facet 1: no endsolid"}},
      {"solid s\n  facet normal 0 0 1\n outer loop\n vertex 0 0 0\n", {"file ends in facet 0"}},
      {"solid s\n" + good + "facets\n",
       {"mesh.stl:9", "expected facet or endsolid, found 'facets'"}},
      {"solid s\n" + good + "endsolid s\nmore\n", {"mesh.stl:10", "expected solid after endsolid"}},
      {"solid s\n" + asciiFacet("0 0 0", "1 nan 0", "0 1 0"),
       {"mesh.stl:5", "facet 0", "vertex 1", "non-finite", "'nan'"}},
      {"solid s\n" + asciiFacet("0 0 0", "1 0 0", "0 1 -inf"),
       {"mesh.stl:6", "vertex 2", "non-finite"}},
      {"solid s\n" + asciiFacet("0 0 0", "1 0 0", "0 1 1e999"),
       {"mesh.stl:6", "facet 0", "'1e999' is not a number"}},
      {"solid s\n" + good + std::string("  facet normal 0\0 0 1\n", 22), {"mesh.stl:9", "NUL"}},
      {binaryStl({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                  {{0, 0, 0}, {1, std::numeric_limits<double>::infinity(), 0}, {0, 1, 0}}}),
       {"mesh.stl", "facet 1", "vertex 1", "non-finite"}},
  };
  for (const Bad& bad : bads) {
    SCOPED_TRACE(bad.bytes.substr(0, 40));
    const std::string message = errorOf(bad.bytes);
    for (const std::string& part : bad.mentions)
      EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
  }
  EXPECT_EQ(readStlBytes("solid s\n" + good + "endsolid s\n").triangles.size(), 1u);
}

// Facets left out for having no area keep the file's numbering: each
// triangle leads back to its own facet, in either encoding.
TEST(Stl, TrianglesKeepTheirFacetNumbersPastFacetsLeftOut) {
  const Facet good0 = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const Facet good1 = {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const Facet good2 = {{1, 0, 0}, {2, 0, 0}, {1, 1, 0}};
  const Facet flat = {{0, 0, 0}, {1, 0, 0}, {-0.0, 0, 0}};
  const std::vector<Facet> facets = {flat, good0, flat, good1, flat, flat, good2, flat};
  const std::vector<std::uint32_t> kept = {1, 3, 6};  // the file's numbers
  const auto expectKept = [](const std::string& bytes, const std::vector<std::uint32_t>& numbers) {
    const Mesh mesh("mesh.stl", readStlBytes(bytes), Shading::Flat, Material{});
    ASSERT_EQ(mesh.triangles().size(), numbers.size());
    for (std::uint32_t t = 0; t < numbers.size(); ++t) {
      EXPECT_EQ(mesh.faceOf(t).face, numbers[t]) << "triangle " << t;
      EXPECT_EQ(mesh.faceOf(t).corners, 3u);
    }
  };
  expectKept(binaryStl(facets), kept);
  expectKept(asciiStl(facets), kept);

  // Across the batches the corners are welded in: a strip of facets, every
  // 1000th left out.
  std::vector<Facet> strip;
  std::vector<std::uint32_t> stripKept;
  for (std::uint32_t i = 0; i < 13000; ++i) {
    const double x = i;
    if (i % 1000 == 999) {
      strip.push_back({{x, 0, 0}, {x, 0, 0}, {x, 1, 0}});
    } else {
      strip.push_back({{x, 0, 0}, {x + 1, 0, 0}, {x, 1, 0}});
      stripKept.push_back(i);
    }
  }
  expectKept(binaryStl(strip), stripKept);
}

// The words of an ASCII file are found in parallel pieces and their places
// found again only for a message: a bad word far into a large file is
// named at its own line and facet.
TEST(Stl, NamesABadWordFarIntoALargeFileAtItsLine) {
  constexpr int kFacets = 20000, kBad = 15000, kLinesAFacet = 7;
  const auto fileWith = [&](const std::string& badCorner) {
    std::string text = "solid strip\n";
    for (int i = 0; i < kFacets; ++i) {
      const std::string x = std::to_string(i);
      text += asciiFacet(x + " 0 0", i == kBad ? badCorner : x + " 1 0", x + ".5 0 1");
    }
    return text + "endsolid strip\n";
  };
  ASSERT_GT(fileWith("0 0 0").size(), 4 * (std::size_t{1} << 18));  // several pieces
  EXPECT_EQ(readStlBytes(fileWith("0 0 0")).triangles.size(), std::size_t{kFacets});
  // The solid's line, the facets before, then the facet's fourth line.
  const std::string line = "mesh.stl:" + std::to_string(1 + kLinesAFacet * kBad + 4);
  const std::string facet = "facet " + std::to_string(kBad);
  for (const auto& [corner, mentions] :
       std::vector<std::pair<std::string, std::vector<std::string>>>{
           {"1 x 0", {line, facet, "'x' is not a number"}},
           {"1 inf 0", {line, facet, "vertex 1", "non-finite", "'inf'"}},
           {"1 0 0 0", {line, facet, "expected vertex, found '0'"}},
           {std::string("1 \0 0", 5), {line, "NUL"}}}) {
    const std::string message = errorOf(fileWith(corner));
    for (const std::string& part : mentions)
      EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
  }
}

}  // namespace
}  // namespace meshtrace
